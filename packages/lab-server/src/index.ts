// @maa/lab-server: the classroom lab server. This step: its storage (see README.md).
export * from './storage/index.js';
