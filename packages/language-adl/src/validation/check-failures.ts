import {
    Cancellation,
    DefaultLinker,
    ValidationRegistry,
    isOperationCancelled,
    type AstNode,
    type AstNodeDescription,
    type LangiumDocument,
    type LinkingError,
    type MaybePromise,
    type ReferenceInfo,
    type ValidationAcceptor,
    type ValidationCategory,
    type ValidationCheck,
} from 'langium';
import { Codes } from './codes.js';
import { forEachReferenceBelow } from '../workspace/ast-walk.js';

/**
 * A check or a name lookup that threw is a bug, but one that must not take the document's other
 * diagnostics with it, nor flood the log on every keystroke: it becomes one
 * `internal/check-failed` diagnostic that names the check, and it is logged once per check and
 * message for the life of the process.
 */

/** Where a failure happened: the innermost method of the family's checks, typer or scoping. */
export function failedCheck(err: unknown, fallback: string): string {
    const stack = err instanceof Error && typeof err.stack === 'string' ? err.stack : '';
    // V8 frames read "    at ClassName.method (file:line:col)"; other engines yield the fallback.
    for (const m of stack.matchAll(/^\s*at (?:async )?([A-Z]\w*(?:Checks|Typer|Resolver|Relations|Provider|Validator|Model))\.(\w+) /gm)) {
        return `${m[1]}.${m[2]}`;
    }
    return fallback;
}

const logged = new Set<string>();
const MAX_LOGGED = 1000;

/** Logs a failure the first time its check and message occur (bounded, so the set cannot grow forever). */
export function logFailureOnce(check: string, err: unknown): void {
    const key = `${check}\u0000${errorMessage(err)}`;
    if (logged.has(key) || logged.size >= MAX_LOGGED) return;
    logged.add(key);
    console.error(`Internal error in ${check} (reported once; a diagnostic internal/check-failed marks the model):`, err);
}

export function errorMessage(err: unknown): string {
    return err instanceof Error ? err.message : String(err);
}

export function checkFailedMessage(check: string, err: unknown): string {
    return `Internal error: the check ${check} failed on this model (${errorMessage(err)}). The other checks ran; please report this with the model.`;
}

/** The registry of every language of the family: failing checks become `internal/check-failed`. */
export class AdlValidationRegistry extends ValidationRegistry {
    /** The checks per node type and categories, as getChecks yields them (asked once per AST node). */
    private readonly checksByType = new Map<string, readonly ValidationCheck[]>();

    protected override addEntry(type: string, entry: Parameters<ValidationRegistry['addEntry']>[1]): void {
        super.addEntry(type, entry);
        this.checksByType.clear();
    }

    /** `getChecks(type, categories)` as an array, computed once per type and categories. */
    checksOf(type: string, categories?: readonly ValidationCategory[]): readonly ValidationCheck[] {
        const key = categories ? `${type}\u0000${categories.join(',')}` : type;
        let checks = this.checksByType.get(key);
        if (!checks) {
            checks = this.getChecks(type, categories ? [...categories] : undefined).toArray();
            this.checksByType.set(key, checks);
        }
        return checks;
    }

    /**
     * Most checks are synchronous: wrapped so that they return no promise (Langium's wrapper makes
     * two per check and node); an asynchronous check's promise is returned, its failure handled.
     */
    protected override wrapValidationException(check: ValidationCheck, thisObj: unknown): ValidationCheck {
        return (node, accept, cancelToken) => {
            let result: MaybePromise<void>;
            try {
                result = check.call(thisObj, node, accept, cancelToken);
            } catch (err) {
                reportCheckFailure(err, accept, node);
                return undefined;
            }
            return result instanceof Promise ? result.catch((err: unknown) => reportCheckFailure(err, accept, node)) : undefined;
        };
    }

    protected override async handleException(
        functionality: () => MaybePromise<void>,
        _context: string,
        accept: ValidationAcceptor,
        node: AstNode,
    ): Promise<void> {
        try {
            await functionality();
        } catch (err) {
            reportCheckFailure(err, accept, node);
        }
    }
}

/** A check that threw: one `internal/check-failed` diagnostic on its node (a cancellation goes on). */
function reportCheckFailure(err: unknown, accept: ValidationAcceptor, node: AstNode): void {
    if (isOperationCancelled(err)) throw err;
    const check = failedCheck(err, `the check of ${node.$type}`);
    logFailureOnce(check, err);
    accept('error', checkFailedMessage(check, err), { node, code: Codes.InternalError, data: { check } });
}

/** A linking error that stands for an exception in a name lookup (see AdlLinker). */
export interface FailedLinkingError extends LinkingError {
    readonly check: string;
}

export function isFailedLinkingError(e: LinkingError): e is FailedLinkingError {
    return typeof (e as Partial<FailedLinkingError>).check === 'string';
}

/** The linker of the family: a lookup that throws becomes one `internal/check-failed` diagnostic. */
export class AdlLinker extends DefaultLinker {
    /** Langium's linking walk (every reference, pre-order) without its per-node streams and promises. */
    override async link(document: LangiumDocument, cancelToken = Cancellation.CancellationToken.None): Promise<void> {
        if (this.profiler?.isActive('linking')) return super.link(document, cancelToken);
        await forEachReferenceBelow(document.parseResult.value, cancelToken, (ref) => this.doLink(ref, document));
    }

    override getCandidate(refInfo: ReferenceInfo): AstNodeDescription | LinkingError {
        try {
            return super.getCandidate(refInfo);
        } catch (err) {
            if (isOperationCancelled(err)) throw err;
            const check = failedCheck(err, `the name lookup of ${refInfo.container.$type}.${refInfo.property}`);
            logFailureOnce(check, err);
            const failure: FailedLinkingError = { info: refInfo, check, message: checkFailedMessage(check, err) };
            return failure;
        }
    }
}
