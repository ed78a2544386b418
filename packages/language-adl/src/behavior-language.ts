import type { AdlServices } from './adl-module.js';
import type { DiagnosticCatalog } from './diagnostic-catalog/catalog.js';
import type { AdlLspServices } from './lsp/lsp-module.js';

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
    /**
     * LSP hook, called by language servers only (after `register`) with the LSP services of the
     * host language `arc`, whose providers carry registries for the language's node types:
     * - `lsp.Formatter.rules`: `$type` -> formatting rule (helpers `elementBlock`, `statementBlock`, `list`);
     * - `lsp.SemanticTokenProvider.styles`: `$type` -> token of its declarations and of every reference to them;
     * - `lsp.DocumentSymbolProvider.contributions`: `$type` -> outline entry (or `'skip'`);
     * - `shared.lsp.NodeKindProvider.kinds`: `$type` -> outline and completion icon;
     * - `lsp.HoverProvider.contributions`: `$type` -> Markdown;
     * - `lsp.CompletionProvider.contributions`: extra completion per expected grammar feature;
     * - `lsp.CodeActionProvider.register(code, fix)`: quick fixes for the language's diagnostic codes.
     * Scopes registered in `register` already give completion, go-to-definition, references and
     * rename for the language's cross-references; nothing in language-adl changes per language.
     */
    registerLsp?(services: AdlLspServices): void;
}
