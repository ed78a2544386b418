// The lab's storage: LabStore (the typed API) over PGlite or PostgreSQL. No SQL outside this folder.
export { durableStartParams, type StorageOptions, storageFromEnvironment } from './connect.js';
export { LOCK_FILE } from './data-dir-lock.js';
export { MAX_PATH_LENGTH } from './paths.js';
export { openLabStore } from './store.js';
export * from './types.js';
