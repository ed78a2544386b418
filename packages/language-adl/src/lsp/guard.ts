import { isOperationCancelled } from 'langium';
import { LSPErrorCodes, ResponseError } from 'vscode-languageserver-protocol';

/**
 * The methods through which Langium's request handlers (`startLanguageServer`) enter each LSP
 * service, per service name in the `lsp` group of a language's or the shared services.
 */
const ENTRY_METHODS: Readonly<Record<string, readonly string[]>> = {
    CompletionProvider: ['getCompletion'],
    HoverProvider: ['getHoverContent'],
    DefinitionProvider: ['getDefinition'],
    DeclarationProvider: ['getDeclaration'],
    TypeProvider: ['getTypeDefinition'],
    ImplementationProvider: ['getImplementation'],
    ReferencesProvider: ['findReferences'],
    DocumentHighlightProvider: ['getDocumentHighlight'],
    DocumentSymbolProvider: ['getSymbols'],
    FoldingRangeProvider: ['getFoldingRanges'],
    Formatter: ['formatDocument', 'formatDocumentRange', 'formatDocumentOnType'],
    CodeActionProvider: ['getCodeActions'],
    RenameProvider: ['rename', 'prepareRename'],
    SemanticTokenProvider: ['semanticHighlight', 'semanticHighlightRange', 'semanticHighlightDelta'],
    SignatureHelp: ['provideSignatureHelp'],
    CodeLensProvider: ['provideCodeLens'],
    DocumentLinkProvider: ['getDocumentLinks'],
    InlayHintProvider: ['getInlayHints'],
    CallHierarchyProvider: ['prepareCallHierarchy', 'incomingCalls', 'outgoingCalls'],
    TypeHierarchyProvider: ['prepareTypeHierarchy', 'supertypes', 'subtypes'],
    WorkspaceSymbolProvider: ['getSymbols', 'resolveSymbol'],
    ExecuteCommandHandler: ['executeCommand'],
};

/** At most this many distinct failures are logged (a model that breaks a feature on every keystroke logs once). */
const MAX_LOGGED = 200;
const logged = new Set<string>();

/**
 * Turns an exception of an LSP feature into a refusal: cancellations and LSP errors pass
 * unchanged; anything else is logged once (per feature and message) and becomes a
 * RequestFailed error naming the feature, so the client gets an answer instead of JSON-RPC's
 * internal error (-32603) with a stack trace.
 */
export function refusal(feature: string, error: unknown, log: (message: string) => void = (m) => console.error(m)): unknown {
    if (isOperationCancelled(error) || error instanceof ResponseError) return error;
    const message = error instanceof Error ? error.message : String(error);
    const key = `${feature}: ${message}`;
    if (!logged.has(key) && logged.size < MAX_LOGGED) {
        logged.add(key);
        log(
            `${feature} failed (further failures with this message are not logged): ${error instanceof Error && error.stack ? error.stack : message}`,
        );
    }
    return new ResponseError(LSPErrorCodes.RequestFailed, `${feature} failed: ${message}`);
}

/** Calls a feature's method; a throw or a rejection becomes the refusal (see `refusal`). */
function callGuarded(feature: string, call: () => unknown, log: (message: string) => void): unknown {
    let result: unknown;
    try {
        result = call();
    } catch (e) {
        throw refusal(feature, e, log);
    }
    if (result instanceof Promise)
        return result.catch((e: unknown) => {
            throw refusal(feature, e, log);
        });
    return result;
}

/** Logs a message to the client's log (window/logMessage) when the services have a connection, else to the console. */
export function serverLog(services: unknown): (message: string) => void {
    type WithConnection = { lsp?: { Connection?: { console: { error(m: string): void } } } };
    const s = services as WithConnection & { shared?: WithConnection };
    const connection = s.shared?.lsp?.Connection ?? s.lsp?.Connection;
    return connection ? (m) => connection.console.error(m) : (m) => console.error(m);
}

/**
 * The service with its entry methods guarded. A proxy, so the service keeps its class
 * (`instanceof`), its registries (`contributions`, `targets`, ...) and its other methods, which
 * providers call on each other unguarded; the entry method runs on the service itself.
 */
export function guardService<T extends object>(name: string, service: T, log?: (message: string) => void): T {
    const methods = ENTRY_METHODS[name];
    if (!methods) return service;
    return new Proxy(service, {
        get(target, key, receiver) {
            const value: unknown = Reflect.get(target, key, receiver);
            if (typeof key !== 'string' || typeof value !== 'function' || !methods.includes(key)) return value;
            const method = value as (...args: unknown[]) => unknown;
            return (...args: unknown[]) =>
                callGuarded(`${name}.${key}`, () => method.apply(target, args), log ?? ((m) => console.error(m)));
        },
    });
}

/** A Langium module: groups of service factories (`lsp: { HoverProvider: (s) => ... }`). */
type ModuleGroups = Record<string, unknown>;

/**
 * A module whose LSP services (the `lsp` group) are guarded as they are created: Langium's
 * default modules and the family's own, so every language's request handling answers or
 * refuses (see guardService). Other groups are unchanged.
 */
export function guardLspModule<M extends object>(module: M): M {
    const lsp = (module as ModuleGroups)['lsp'];
    if (typeof lsp !== 'object' || lsp === null) return module;
    const guarded: Record<string, unknown> = {};
    for (const [name, factory] of Object.entries(lsp)) {
        guarded[name] =
            typeof factory === 'function' && name in ENTRY_METHODS
                ? (services: unknown) => {
                      const service: unknown = (factory as (s: unknown) => unknown)(services);
                      return typeof service === 'object' && service !== null ? guardService(name, service, serverLog(services)) : service;
                  }
                : factory;
    }
    return { ...module, lsp: guarded } as M;
}
