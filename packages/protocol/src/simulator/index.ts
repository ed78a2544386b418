import { contract } from '../contract.js';
import { SimulatorStatus } from './schema.js';

export * from './schema.js';

/** Checks a `/sim/get_status` answer. */
export const simulatorStatusContract = contract('/sim/get_status answer', SimulatorStatus);
