// The lab's storage: LabStore (the typed API) over PGlite or PostgreSQL. No SQL outside this folder.
export { durableStartParams, type StorageOptions } from './connect.js';
export { MAX_PATH_LENGTH } from './paths.js';
export { openLabStore } from './store.js';
export * from './types.js';
