import { contract } from '../contract.js';
import { SimulatorFinished, SimulatorProgress } from './run-lines.js';
import { ProgramStepEvent, SetBreakpoints, SimulatorStatus, TransitionEvent } from './schema.js';

export * from './schema.js';
export * from './run-lines.js';

/** Checks a `/sim/get_status` answer. */
export const simulatorStatusContract = contract('/sim/get_status answer', SimulatorStatus);
/** Checks a `maa-sim run --progress-json` line. */
export const simulatorProgressContract = contract('maa-sim progress line', SimulatorProgress);
/** Checks the `maa-sim run --status-json` finished line. */
export const simulatorFinishedContract = contract('maa-sim finished line', SimulatorFinished);
/** Checks the `data` of a `/maa/transitions` message. */
export const transitionEventContract = contract('/maa/transitions message', TransitionEvent);
/** Checks the `data` of a `/maa/program_steps` message. */
export const programStepEventContract = contract('/maa/program_steps message', ProgramStepEvent);
/** Checks a `/sim/set_breakpoints` request. */
export const setBreakpointsContract = contract('/sim/set_breakpoints request', SetBreakpoints);
