import {
    Cancellation,
    DefaultDocumentValidator,
    DocumentValidator,
    GrammarAST,
    type AstNode,
    type LangiumCoreServices,
    type LangiumDocument,
    type LinkingError,
    type ParseResult,
    type ValidationAcceptor,
    type ValidationOptions,
} from 'langium';
import type { Diagnostic } from 'vscode-languageserver-types';
import { Codes } from './codes.js';
import { isGuardError } from '../parser/guarded-lexer.js';
import { AdlValidationRegistry, isFailedLinkingError } from './check-failures.js';
import { betweenNodes, pushChildren } from '../workspace/ast-walk.js';

/**
 * Gives every diagnostic of the family a stable code: lexer and parser errors become
 * `syntax/...`, unresolved references the most specific `arc/...`/`expr/...` code for the kind
 * of reference (else `link/unresolved-reference`). Expression names are reported by the
 * expression checks instead, which know qualified names such as `java.lang.String.String()`.
 */
export class AdlDocumentValidator extends DefaultDocumentValidator {
    /**
     * Codes for unresolved references of embedded languages, keyed by `ContainerType.property`;
     * the message is built from the unresolved name.
     */
    readonly linkCodes = new Map<string, { code: string; message: (name: string) => string }>();

    /** Keywords that the composed `Name` rule admits as identifiers (not worth listing in messages). */
    private readonly softKeywords: ReadonlySet<string>;

    constructor(services: LangiumCoreServices) {
        super(services);
        const nameRule = services.Grammar.rules.find((r) => r.name === 'Name');
        const keywords = new Set<string>();
        if (nameRule && GrammarAST.isParserRule(nameRule)) {
            const collect = (e: GrammarAST.AbstractElement): void => {
                if (GrammarAST.isKeyword(e)) keywords.add(e.value);
                else if (GrammarAST.isAlternatives(e)) e.elements.forEach(collect);
            };
            collect(nameRule.definition);
        }
        this.softKeywords = keywords;
    }

    protected override processLexingErrors(parseResult: ParseResult, diagnostics: Diagnostic[], options: ValidationOptions): void {
        const start = diagnostics.length;
        super.processLexingErrors(parseResult, diagnostics, options);
        // Langium turns the lexer errors into diagnostics first and in order, then its report's.
        for (let i = start; i < diagnostics.length; i++) {
            const error = parseResult.lexerErrors[i - start];
            retag(diagnostics[i]!, error && isGuardError(error) ? error.code : Codes.SyntaxToken);
        }
    }

    protected override processParsingErrors(parseResult: ParseResult, diagnostics: Diagnostic[], options: ValidationOptions): void {
        const start = diagnostics.length;
        super.processParsingErrors(withoutFollowUps(parseResult), diagnostics, options);
        for (let i = start; i < diagnostics.length; i++) {
            const d = diagnostics[i]!;
            const atEnd = /but found:? ?[`']{2}/.test(d.message);
            d.message = concise(d.message, atEnd, this.softKeywords);
            retag(d, atEnd ? Codes.SyntaxUnexpectedEnd : Codes.SyntaxUnexpected);
        }
    }

    /** Langium's walk over the nodes (pre-order, children skipped as validateSingleNodeOptions says) without its per-node streams and promises. */
    protected override async validateAstNodes(
        rootNode: AstNode,
        options: ValidationOptions,
        acceptor: ValidationAcceptor,
        cancelToken = Cancellation.CancellationToken.None,
    ): Promise<void> {
        const registry = this.validationRegistry;
        if (this.profiler?.isActive('validating') || !(registry instanceof AdlValidationRegistry)) {
            return super.validateAstNodes(rootNode, options, acceptor, cancelToken);
        }
        const stack: AstNode[] = [rootNode];
        while (stack.length > 0) {
            const wait = betweenNodes(cancelToken);
            if (wait) await wait;
            const node = stack.pop()!;
            const nodeOptions = this.validateSingleNodeOptions(node, options);
            if (nodeOptions.validateNode) {
                for (const check of registry.checksOf(node.$type, options.categories)) {
                    const pending = check(node, acceptor, cancelToken);
                    if (pending) await pending;
                }
            }
            if (nodeOptions.validateChildren) pushChildren(node, stack);
        }
    }

    override async validateDocument(...args: Parameters<DefaultDocumentValidator['validateDocument']>): Promise<Diagnostic[]> {
        const diagnostics = await super.validateDocument(...args);
        // A check that failed on an unusual (e.g. partially parsed) model must still be visible
        // with a code, and must never take the other diagnostics with it.
        for (const d of diagnostics) if (d.code === undefined) d.code = Codes.InternalError;
        return onePerFailedCheck(diagnostics);
    }

    protected override processLinkingErrors(document: LangiumDocument, diagnostics: Diagnostic[], _options: ValidationOptions): void {
        for (const reference of document.references) {
            const error = reference.error;
            if (!error) continue;
            const { container } = error.info;
            const range = reference.$refNode?.range ?? container.$cstNode?.range;
            if (!range) continue;
            if (isFailedLinkingError(error)) {
                diagnostics.push({
                    severity: 1,
                    range,
                    message: error.message,
                    code: Codes.InternalError,
                    source: this.getSource(),
                    data: { check: error.check },
                });
                continue;
            }
            const found = this.unresolvedReference(error);
            if (!found) continue;
            diagnostics.push({
                severity: 1,
                range,
                message: found.message,
                code: found.code,
                source: this.getSource(),
                data: { code: DocumentValidator.LinkingError },
            });
        }
    }

    /**
     * The code and message of an unresolved reference, by where it occurs (the family's own
     * places, then those a behavior language contributed); undefined when another check reports it.
     */
    private unresolvedReference(error: LinkingError): { code: string; message: string } | undefined {
        const { container, property } = error.info;
        const name = error.info.reference.$refText;
        switch (`${container.$type}.${property}`) {
            case 'PortAccess.port': {
                const pa = container as { subcomponent?: { ref?: unknown; error?: unknown } };
                if (pa.subcomponent && !pa.subcomponent.ref) return undefined; // reported on the subcomponent
                const where = pa.subcomponent
                    ? ` in the type of subcomponent '${(pa.subcomponent as { $refText?: string }).$refText}'`
                    : '';
                return { code: Codes.MissingPort, message: `Port '${name}' does not exist${where}.` };
            }
            case 'PortAccess.subcomponent':
                return { code: Codes.MissingSubcomponent, message: `Subcomponent '${name}' does not exist.` };
            case 'ComponentTypeRef.ref':
                return { code: Codes.MissingComponentType, message: `Component type '${name}' cannot be resolved.` };
            case 'ReferenceType.ref':
                return { code: Codes.UnresolvedType, message: `Type '${name}' cannot be resolved.` };
            case 'NameExpression.ref': {
                const assign = container.$container;
                const isArgumentKey =
                    assign?.$type === 'AssignmentExpression' &&
                    (assign as { left?: unknown }).left === container &&
                    ['Subcomponent', 'ParentComponent'].includes(assign.$container?.$type ?? '');
                // Other names are reported by the expression checks, which also resolve qualified names.
                if (!isArgumentKey) return undefined;
                return { code: Codes.UnknownArgumentKey, message: `'${name}' is not a parameter of the instantiated component type.` };
            }
            default: {
                const contributed = this.linkCodes.get(`${container.$type}.${property}`);
                if (contributed) return { code: contributed.code, message: contributed.message(name) };
                return { code: Codes.LinkUnresolved, message: error.message };
            }
        }
    }
}

/**
 * Chevrotain lists every expected token sequence (dozens in a component body); users need the
 * unexpected token and the tokens that could start the text there.
 */
function concise(message: string, atEnd: boolean, softKeywords: ReadonlySet<string>): string {
    const found = /but found:? ?[`']([^`']*)[`']/.exec(message)?.[1];
    const firsts = [...message.matchAll(/^\s*\d+\. \[([^,\]]+)/gm)].map((m) => m[1]!.trim());
    const expected = [...new Set(firsts)].filter((t) => !softKeywords.has(t));
    const what = atEnd ? 'Unexpected end of file' : `Unexpected '${found ?? '?'}'`;
    if (expected.length > 0) {
        const shown = expected.slice(0, 12).map((t) => (t === 'ID' ? 'a name' : `'${t}'`));
        return `${what}; expected ${shown.join(', ')}${expected.length > 12 ? ', ...' : ''}.`;
    }
    if (/Expecting:? end of (file|input)|token of type '?EOF/i.test(message))
        return `${what}; expected the end of the file (one top-level element per file).`;
    const single = /Expecting (?:token of type )?'?([^'\s]+)'?/.exec(message)?.[1];
    return single ? `${what}; expected ${single === 'ID' ? 'a name' : `'${single}'`}.` : message;
}

/** A check that failed on many nodes is one problem: one `internal/check-failed` per check. */
function onePerFailedCheck(diagnostics: Diagnostic[]): Diagnostic[] {
    const seen = new Set<string>();
    return diagnostics.filter((d) => {
        if (d.code !== Codes.InternalError) return true;
        const check = (d.data as { check?: unknown } | undefined)?.check;
        const key = typeof check === 'string' ? check : d.message;
        if (seen.has(key)) return false;
        seen.add(key);
        return true;
    });
}

/**
 * Without the parser errors that the nesting or size guard caused: the parser sees the text
 * around a cut-out region (`x = ;`, `(( ))`) and reports the token after it, or the end of the file.
 */
function withoutFollowUps(parseResult: ParseResult): ParseResult {
    const cuts = parseResult.lexerErrors.filter(isGuardError).flatMap((e) => e.regions);
    if (cuts.length === 0) return parseResult;
    const followUp = (offset: number): boolean =>
        cuts.some((c) => (Number.isNaN(offset) ? c.resumeOffset === Infinity : offset >= c.offset && offset <= c.resumeOffset));
    return { ...parseResult, parserErrors: parseResult.parserErrors.filter((e) => !followUp(e.token.startOffset)) };
}

function retag(d: Diagnostic, code: string): void {
    d.code = code;
}
