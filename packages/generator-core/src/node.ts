// @maa/generator-core/node: generation itself (Node only): the orchestrator, the shared
// Nunjucks environment and the transactional writer.
export * from './index.js';
export * from './orchestrator/orchestrator.js';
export * from './orchestrator/gen-codes.js';
export * from './output/writer.js';
export { killWhenPaused } from './output/pause.js';
export * from './templates/environment.js';
