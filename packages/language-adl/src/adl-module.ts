import {
    DefaultWorkspaceManager,
    URI,
    type AstNode,
    type LangiumCoreServices,
    type LangiumDocument,
    type LangiumSharedCoreServices,
    type Module,
    type PartialLangiumCoreServices,
    type PartialLangiumSharedCoreServices,
} from 'langium';
import type { WorkspaceFolder } from 'vscode-languageserver-types';
import { ModelRoots } from './model-roots.js';
import { createAdlCompletionParser, createAdlParser } from './parser/adl-parser.js';
import { GuardedLexer } from './parser/guarded-lexer.js';
import { AdlScopeComputation } from './scoping/adl-scope-computation.js';
import { AdlScopeProvider } from './scoping/adl-scope-provider.js';
import { NameResolver } from './scoping/name-resolver.js';
import { RootIndex } from './scoping/root-index.js';
import { BUILTIN_DOCUMENTS } from './types/builtin-library.js';
import { ExpressionTyper } from './types/expression-typer.js';
import { TypeRelations } from './types/type-relations.js';
import { AdlLinker, AdlValidationRegistry } from './validation/check-failures.js';
import { AdlDocumentValidator } from './validation/document-validator.js';
import { AdlReferenceDescriptionProvider } from './workspace/reference-descriptions.js';
import { ReservedNames } from './validation/reserved-names.js';

/** Services the host language adds to every language of a family (arc, cd, behavior languages). */
export interface AdlAddedServices {
    maa: {
        NameResolver: NameResolver;
        TypeRelations: TypeRelations;
        ExpressionTyper: ExpressionTyper;
    };
}

export interface AdlAddedSharedServices {
    maa: {
        ModelRoots: ModelRoots;
        RootIndex: RootIndex;
        ReservedNames: ReservedNames;
    };
}

export type AdlSharedServices = LangiumSharedCoreServices & AdlAddedSharedServices;
export type AdlServices = LangiumCoreServices & AdlAddedServices & { shared: AdlSharedServices };

/** Loads the built-in `java.lang`/`java.util` library next to the workspace's model files. */
export class AdlWorkspaceManager extends DefaultWorkspaceManager {
    protected override async loadAdditionalDocuments(
        _folders: WorkspaceFolder[],
        collector: (document: LangiumDocument<AstNode>) => void,
    ): Promise<void> {
        for (const { uri, text } of BUILTIN_DOCUMENTS) {
            const u = URI.parse(uri);
            if (!this.langiumDocuments.hasDocument(u)) collector(this.langiumDocuments.createDocument(u, text));
        }
    }
}

/** Creates (or returns the already loaded) documents of the built-in library. */
export function builtinDocuments(shared: LangiumSharedCoreServices): LangiumDocument[] {
    const docs = shared.workspace.LangiumDocuments;
    return BUILTIN_DOCUMENTS.map(({ uri, text }) => {
        const u = URI.parse(uri);
        return docs.getDocument(u) ?? docs.createDocument(u, text);
    });
}

export const AdlSharedModule: Module<AdlSharedServices, PartialLangiumSharedCoreServices & AdlAddedSharedServices> = {
    workspace: {
        WorkspaceManager: (s) => new AdlWorkspaceManager(s),
    },
    maa: {
        ModelRoots: () => new ModelRoots(),
        RootIndex: (s) => new RootIndex(s, s.workspace.IndexManager, s.maa.ModelRoots),
        ReservedNames: (s) => new ReservedNames(s.maa.ModelRoots),
    },
};

/** The host language's services; every language of the family is injected with them. */
export const AdlModule: Module<AdlServices, PartialLangiumCoreServices & AdlAddedServices> = {
    parser: {
        Lexer: (s) => new GuardedLexer(s),
        LangiumParser: (s) => createAdlParser(s),
        CompletionParser: (s) => createAdlCompletionParser(s),
    },
    references: {
        Linker: (s) => new AdlLinker(s),
        ScopeComputation: (s) => new AdlScopeComputation(s),
        ScopeProvider: (s) =>
            new AdlScopeProvider(s.maa.NameResolver, s.workspace.AstNodeDescriptionProvider, s.shared, () => s.maa.ExpressionTyper),
    },
    workspace: {
        ReferenceDescriptionProvider: (s) => new AdlReferenceDescriptionProvider(s),
    },
    validation: {
        DocumentValidator: (s) => new AdlDocumentValidator(s),
        ValidationRegistry: (s) => new AdlValidationRegistry(s),
    },
    maa: {
        NameResolver: (s) => new NameResolver(s.shared.maa.RootIndex, s.shared.maa.ModelRoots, s.workspace.AstNodeDescriptionProvider),
        TypeRelations: (s) => new TypeRelations(s.shared.maa.RootIndex),
        ExpressionTyper: (s) => new ExpressionTyper(s.maa.TypeRelations, s.maa.NameResolver),
    },
};
