import type { AdlServices } from './adl-module.js';
import type { DiagnosticCatalog } from './docs/diagnostic-catalog.js';

/**
 * An embedded behavior language, as registered in a language family's configuration.
 *
 * Syntactic integration happens at build time (the package's `maa.language.behavior` entry in
 * package.json names the grammar rule that fills the host's `Behavior` slot); this object is the
 * run-time part: it installs the language's scopes (`AdlScopeProvider.contributions`), codes for
 * its unresolved references (`AdlDocumentValidator.linkCodes`) and its checks into the services
 * of the host language `arc`.
 */
export interface BehaviorLanguage {
    /** The language's name, e.g. `automaton`. */
    readonly name: string;
    /** The keyword that opens its block in a component, e.g. `automaton`. */
    readonly keyword: string;
    /** The `$type` of the AST node its block parses to, e.g. `Automaton`. */
    readonly astType: string;
    /** The language's diagnostics with tested examples (rendered into docs/diagnostics.md). */
    readonly diagnostics?: DiagnosticCatalog;
    register(services: AdlServices): void;
}
