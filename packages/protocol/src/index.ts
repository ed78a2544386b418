/**
 * @maa/protocol: the wire contracts between the workbench's parts, one folder per contract
 * (README.md). Each exports TypeBox schemas (JSON Schema objects), their static types and a
 * {@link Contract} that validates at run time.
 */
export type { Static, TSchema } from '@sinclair/typebox';
export * from './contract.js';
export * from './position.js';
export * from './trace/index.js';
export * from './deployment/index.js';
export * from './http/index.js';
export * from './topics/index.js';
export * from './lockstep/index.js';
export * from './simulator/index.js';
export * from './exercise/index.js';
export * from './grading/index.js';
