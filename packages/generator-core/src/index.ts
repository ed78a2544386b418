// @maa/generator-core: the parts of generator composition that run everywhere (also in a
// browser language server): generator types, manifests, the registry, the application
// configuration language and its checks, the architecture view, the standard rules, naming
// helpers. The orchestrator, the Nunjucks environment and the writer need Node:
// `@maa/generator-core/node`.
export * from './app/arcapp-language.js';
export * from './app/arcapp-module.js';
export * from './app/app-analysis.js';
export * from './app/app-checks.js';
export * from './app/app-diagnostics.js';
export * from './app/codes.js';
export * from './app/registry-provider.js';
export * from './generators/types.js';
export * from './manifest/manifest.js';
export * from './manifest/schema.js';
export * from './model/architecture.js';
export * from './model/modes.js';
export * from './output/file-builder.js';
export * from './output/protected-regions.js';
export * from './registry/discovery.js';
export * from './registry/registry.js';
export * from './registry/registry-service.js';
export * from './rules/standard-rules.js';
export * from './templates/naming.js';
export * as appAst from './generated/ast.js';
