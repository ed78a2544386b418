export { createMaaServices, createMaaLspServices, behaviorLanguages, MAA_SERVICE_REQUIREMENTS } from './family.js';
export { checkModelRoots } from './check.js';
export { CheckInputError, type CheckDiagnostic, type CheckOptions, type RootSpec, type Severity } from '@maa/language-adl';
export { familyDiagnostics, renderDiagnosticsMarkdown } from './diagnostic-catalog/render-diagnostics.js';
export * from './diagram/index.js';
export { LANGUAGE_FACTS, type LanguageFact, type LanguageFacts, type LanguageScopes } from './generated/language-facts.js';
export { loadDiagramWorkspace, type DiagramWorkspace } from './diagram-workspace.js';
