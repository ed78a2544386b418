import type { Module } from 'langium';
import {
    createDefaultModule,
    createDefaultSharedModule,
    type DefaultSharedModuleContext,
    type LangiumLSPServices,
    type LangiumSharedLSPServices,
    type PartialLangiumLSPServices,
    type PartialLangiumSharedLSPServices,
} from 'langium/lsp';
import type { AdlServices, AdlSharedServices } from '../adl-module.js';
import type { BehaviorLanguage } from '../behavior-language.js';
import { createHostServices, type FamilyLanguage, type GeneratedModules } from '../services.js';
import { AdlCodeActionProvider } from './code-actions.js';
import { AdlCompletionProvider } from './completion.js';
import { AdlDefinitionProvider } from './definition.js';
import { AdlFoldingRangeProvider } from './folding.js';
import { AdlFormatter } from './formatter.js';
import { AdlDocumentHighlightProvider } from './highlight.js';
import { guardLspModule } from './guard.js';
import { registerHostQuickFixes } from './host-fixes.js';
import { AdlHoverProvider } from './hover.js';
import { AdlNodeKindProvider } from './node-kinds.js';
import { AdlReferences } from './references.js';
import { AdlRenameProvider } from './rename.js';
import { AdlSemanticTokenProvider } from './semantic-tokens.js';
import { AdlDocumentSymbolProvider } from './symbols.js';
import { AdlDocumentUpdateHandler, AdlLspDocumentBuilder, AdlLspLangiumDocuments, AdlLspWorkspaceManager } from './workspace.js';

/**
 * The LSP services of every language of the family. Each provider that a behavior language may
 * extend carries a registry (keyed by AST `$type`, or by diagnostic code for quick fixes):
 *
 * | service | registry |
 * |---|---|
 * | `lsp.Formatter` | `rules` ($type -> formatting rule) |
 * | `lsp.SemanticTokenProvider` | `styles` ($type -> token of declarations and references), `highlighters` |
 * | `lsp.DocumentSymbolProvider` | `contributions` ($type -> outline entry) |
 * | `lsp.CompletionProvider` | `contributions` (per expected grammar feature) |
 * | `lsp.HoverProvider` | `contributions` ($type -> Markdown) |
 * | `lsp.CodeActionProvider` | `register(code, fix)` |
 * | `lsp.DefinitionProvider` | `targets` (declarations outside model documents) |
 * | `references.References` | `nameResolvers`, `referenceFinders` (names that are not cross-references) |
 * | `shared.lsp.NodeKindProvider` | `kinds` ($type -> symbol and completion kind) |
 */
export interface AdlAddedLspServices {
    lsp: {
        CompletionProvider: AdlCompletionProvider;
        HoverProvider: AdlHoverProvider;
        DocumentSymbolProvider: AdlDocumentSymbolProvider;
        FoldingRangeProvider: AdlFoldingRangeProvider;
        Formatter: AdlFormatter;
        SemanticTokenProvider: AdlSemanticTokenProvider;
        RenameProvider: AdlRenameProvider;
        CodeActionProvider: AdlCodeActionProvider;
        DefinitionProvider: AdlDefinitionProvider;
        DocumentHighlightProvider: AdlDocumentHighlightProvider;
    };
    references: {
        References: AdlReferences;
    };
}

export interface AdlAddedSharedLspServices {
    lsp: {
        NodeKindProvider: AdlNodeKindProvider;
        DocumentUpdateHandler: AdlDocumentUpdateHandler;
    };
    workspace: {
        WorkspaceManager: AdlLspWorkspaceManager;
        DocumentBuilder: AdlLspDocumentBuilder;
        LangiumDocuments: AdlLspLangiumDocuments;
    };
}

export type AdlLspSharedServices = AdlSharedServices & LangiumSharedLSPServices & AdlAddedSharedLspServices;
export type AdlLspServices = AdlServices & LangiumLSPServices & AdlAddedLspServices & { shared: AdlLspSharedServices };

/** The family's shared LSP services: model roots from the workspace, node kinds. */
export const AdlLspSharedModule: Module<AdlLspSharedServices, PartialLangiumSharedLSPServices & AdlAddedSharedLspServices> = {
    lsp: {
        NodeKindProvider: () => new AdlNodeKindProvider(),
        DocumentUpdateHandler: (s) => new AdlDocumentUpdateHandler(s),
    },
    workspace: {
        WorkspaceManager: (s) => new AdlLspWorkspaceManager(s),
        DocumentBuilder: (s) => new AdlLspDocumentBuilder(s),
        LangiumDocuments: (s) => new AdlLspLangiumDocuments(s),
    },
};

/** The LSP services of one language of the family (host languages and behavior-language files). */
export const AdlLspModule: Module<AdlLspServices, PartialLangiumLSPServices & AdlAddedLspServices> = {
    lsp: {
        CompletionProvider: (s) => new AdlCompletionProvider(s),
        HoverProvider: (s) => new AdlHoverProvider(s),
        DocumentSymbolProvider: (s) => new AdlDocumentSymbolProvider(s),
        FoldingRangeProvider: (s) => new AdlFoldingRangeProvider(s),
        Formatter: () => new AdlFormatter(),
        SemanticTokenProvider: (s) => new AdlSemanticTokenProvider(s),
        RenameProvider: (s) => new AdlRenameProvider(s),
        DefinitionProvider: (s) => new AdlDefinitionProvider(s),
        DocumentHighlightProvider: (s) => new AdlDocumentHighlightProvider(s),
        CodeActionProvider: (s) => {
            const actions = new AdlCodeActionProvider(s);
            registerHostQuickFixes(actions);
            return actions;
        },
    },
    references: {
        References: (s) => new AdlReferences(s),
    },
};

/** The services of a language family with LSP support (see createHostLspServices). */
export interface HostLspServices {
    shared: AdlLspSharedServices;
    Arc: AdlLspServices;
    Cd: AdlLspServices;
    languages: ReadonlyMap<string, AdlLspServices>;
}

/**
 * Creates the services of a language family for a language server: Langium's LSP defaults, the
 * host's modules, AdlLspModule, then every behavior language's and further language's
 * `register` and `registerLsp` hooks. Every LSP feature is guarded (guard.ts): an exception in
 * it is logged once and answered with a RequestFailed error, never an internal error.
 */
export function createHostLspServices(
    context: DefaultSharedModuleContext,
    generated: GeneratedModules,
    behaviors: readonly BehaviorLanguage[],
    languages: readonly FamilyLanguage[] = [],
): HostLspServices {
    const host = createHostServices(context, generated, behaviors, languages, {
        shared: (ctx) => guardLspModule(createDefaultSharedModule(ctx)) as unknown as Module<AdlSharedServices, object>,
        language: (ctx) =>
            guardLspModule(createDefaultModule(ctx as Parameters<typeof createDefaultModule>[0])) as unknown as Module<AdlServices, object>,
        sharedModules: [AdlLspSharedModule as unknown as Module<AdlSharedServices, object>],
        languageModules: [guardLspModule(AdlLspModule) as unknown as Module<AdlServices, object>],
    });
    const services = host as unknown as HostLspServices;
    for (const b of behaviors) b.registerLsp?.(services.Arc);
    for (const l of languages) {
        const s = services.languages.get(l.languageId);
        if (s) l.registerLsp?.(s);
    }
    return services;
}
