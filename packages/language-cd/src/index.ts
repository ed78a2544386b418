// @maa/language-cd: the class-diagram language on its own (the AST types and the grammar of the
// `ClassDiagram` project that maa-compose-grammar composes from src/grammar). The family's
// composed services, which also check class diagrams, are in @maa/language-adl.
export * from './generated/ast.js';
export { CdGrammar } from './generated/grammar.js';
