// @maa/language-adl for browsers (the `browser` export condition of the package): everything of
// the package index except the checker of model roots on disk (node:fs), whose types stay
// available. Bundlers that resolve the `browser` condition (esbuild, Vite) pick this file, so a
// language server in a Web Worker pulls in no Node built-ins.
export * from './adl-module.js';
export * from './behavior-language.js';
export * from './model-roots.js';
export * from './workspace/model-root.js';
export * from './services.js';
export * from './components/component-model.js';
export * from './components/features.js';
export * from './components/variability.js';
export * from './components/variant-context.js';
export * from './components/autoconnect.js';
export * from './components/connector-chains.js';
export * from './scoping/adl-scope-provider.js';
export * from './scoping/lookup-scope.js';
export * from './scoping/name-resolver.js';
export * from './types/sym-type.js';
export * from './types/type-resolver.js';
export * from './types/type-relations.js';
export * from './types/expression-typer.js';
export * from './types/constant-evaluator.js';
export * from './types/builtin-library.js';
export * from './validation/codes.js';
export * from './validation/document-validator.js';
export * from './validation/reserved-names.js';
export * from './validation/checks/expression-checks.js';
export * as ast from './generated/ast.js';
export * from './diagnostic-catalog/catalog.js';
export * from './diagnostic-catalog/adl-diagnostics.js';
export * from './lsp/index.js';
export type { CheckDiagnostic, CheckOptions, RootSpec, Severity } from './workspace/root-checker.js';
