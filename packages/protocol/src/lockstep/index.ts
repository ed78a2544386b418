import { contract } from '../contract.js';
import { Lockstep, StepOutputs } from './schema.js';

export * from './schema.js';

export { LOCKSTEP_FILE_NAME } from '../formats.js';

/** Checks a parsed `lockstep.json`. */
export const lockstepContract = contract('lockstep.json', Lockstep);
/** Checks what a lock-step controller's `step` returned. */
export const stepOutputsContract = contract('lock-step step result', StepOutputs);
