// @maa/language-cd: the class-diagram language: the AST types and the grammar of the
// `ClassDiagram` project that maa-compose-grammar composes from src/grammar, and the logic of class
// diagrams that does not depend on the rest of the family: their diagnostic codes, checks
// (validation/) and declared types (scoping/). The family's composed services, which install these
// checks into the services of `.cd` files, are in @maa/language-adl.
export * from './generated/ast.js';
export { CdGrammar } from './generated/grammar.js';
export * from './codes.js';
export * from './scoping/cd-declarations.js';
export * from './validation/cd-checks.js';
