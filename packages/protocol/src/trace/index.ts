import { contract } from '../contract.js';
import { TraceFile } from './schema.js';

export * from './schema.js';

/** The name of the trace file in a generated platform folder. */
export { TRACE_FILE_NAME } from '../formats.js';

/** Checks a parsed `.maa-trace.json`. */
export const traceFileContract = contract('trace file', TraceFile);
