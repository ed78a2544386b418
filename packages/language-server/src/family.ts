import { DocumentState, type DefaultSharedCoreModuleContext } from 'langium';
import type { DefaultSharedModuleContext, ServiceRequirements } from 'langium/lsp';
import { createHostLspServices, createHostServices, type HostLanguageServices, type HostLspServices } from '@maa/language-adl';
import { BEHAVIOR_LANGUAGES, FAMILY_LANGUAGES } from './generated/behavior-languages.js';
import { ArcGeneratedModule, CdGeneratedModule, MaaGeneratedSharedModule } from './generated/module.js';

/**
 * The language family of this workbench: the host language (`.arc`), class diagrams (`.cd`)
 * and every behavior language listed in this package's `maa.family` (package.json), composed
 * into one grammar (one AST reflection) and one set of services with one shared scope.
 */
export function createMaaServices(context: DefaultSharedCoreModuleContext): HostLanguageServices {
    return createHostServices(
        context,
        { shared: MaaGeneratedSharedModule, arc: ArcGeneratedModule, cd: CdGeneratedModule },
        BEHAVIOR_LANGUAGES,
        FAMILY_LANGUAGES,
    );
}

/**
 * The same family with the language-server services (Langium's LSP defaults and the host's
 * AdlLspModule, plus every registered language's `registerLsp` contributions): for the node and
 * browser entry points and for tests of LSP features. Model roots come from the workspace folders.
 */
export function createMaaLspServices(context: DefaultSharedModuleContext): HostLspServices {
    return createHostLspServices(
        context,
        { shared: MaaGeneratedSharedModule, arc: ArcGeneratedModule, cd: CdGeneratedModule },
        BEHAVIOR_LANGUAGES,
        FAMILY_LANGUAGES,
    );
}

/**
 * The document state LSP requests of the family's language server wait for, where Langium's
 * default is too early (pass to `startLanguageServer`).
 *
 * The outline (`textDocument/documentSymbol`, which editors request after every change for the
 * outline, breadcrumbs and sticky scroll) waits for the linked document, like hover and
 * completion, instead of Langium's default `Parsed`: its details name each subcomponent's type,
 * which resolves cross-references. Run on a document that a change has just reset (parsed, not
 * yet indexed and scoped), that resolution made Langium warn "Attempted reference resolution
 * before document reached ComputedScopes state" on keystrokes, and it filled the family's name
 * index (cached until the next change) from the index as it was before the change, so documents
 * linked later in the same build (an .arcapp naming the edited component) were linked to the
 * component of the previous text.
 */
export const MAA_SERVICE_REQUIREMENTS: Partial<ServiceRequirements> = {
    DocumentSymbolProvider: DocumentState.Linked,
};

export function behaviorLanguages(): readonly string[] {
    return BEHAVIOR_LANGUAGES.map((b) => b.name);
}
