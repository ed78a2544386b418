import {
    CompositeCstNodeImpl,
    AstUtils,
    CstNodeBuilder,
    LeafCstNodeImpl,
    LangiumParser,
    createCompletionParser,
    createParser,
    GrammarAST,
    type CompositeCstNode,
    type CstNode,
    type LangiumCoreServices,
    type LeafCstNode,
    type AstNode,
    type AstReflection,
    type LangiumCompletionParser,
    type Lexer,
    type LexerResult,
    type Mutable,
    type ParseResult,
} from 'langium';
import type { Range } from 'vscode-languageserver-types';
import { type ChevrotainErrorHandler, cacheNoViableAltPaths } from './no-viable-alt-paths.js';

type ParserOptions = Parameters<LangiumParser['parse']>[1] & {};

/**
 * The parser of every language of the family: Langium's parser with a cheaper CST builder and
 * AST merge. Parsing the 1,000-component benchmark model spent more time building the CST and
 * collecting its garbage than recognizing the input (issue 18; profile of `parse` with `node --cpu-prof`): every token
 * that starts a rule walked up the new, still empty CST nodes of the rules it starts (an
 * expression operand starts 16) to insert the hidden tokens before it, even when there were none;
 * each insertion and each removal of an empty node went through `Array#splice` of Langium's
 * `Array` subclass, which constructs another instance of that subclass for the removed elements;
 * and the offset and length of a composite node, asked once per rule call, iterated with
 * iterators. The CST and AST built are the same as Langium's: the overrides below only skip work
 * whose result is discarded or compute the same values without the intermediate objects.
 */
export function createAdlParser(services: LangiumCoreServices): LangiumParser {
    const parser = new AdlParser(services);
    createParser(services.Grammar, parser, services.parser.Lexer.definition);
    parser.finalize();
    return parser;
}

/** Langium's completion parser, with the lookahead paths of its syntax errors kept (no-viable-alt-paths.ts). */
export function createAdlCompletionParser(services: LangiumCoreServices): LangiumCompletionParser {
    const parser = createCompletionParser(services);
    cacheNoViableAltPaths((parser as unknown as { wrapper: ChevrotainErrorHandler }).wrapper);
    return parser;
}

/** The members of Langium's parser that the overrides below use (private in its typings). */
interface LangiumParserInternals {
    nodeBuilder: CstNodeBuilder;
    astReflection: AstReflection;
    lexer: Lexer;
    wrapper: { input: LexerResult['tokens']; errors: ParseResult['parserErrors'] } & ChevrotainErrorHandler;
    lexerResult: LexerResult | undefined;
    allRules: Map<string, unknown>;
    mainRule: unknown;
    unorderedGroups: Map<string, boolean[]>;
    doParse(rule: unknown): AstNode;
}

export class AdlParser extends LangiumParser {
    constructor(services: LangiumCoreServices) {
        super(services);
        const self = this as unknown as LangiumParserInternals;
        self.nodeBuilder = new AdlCstNodeBuilder();
        self.astReflection = withDefaultsOnly(self.astReflection);
        cacheNoViableAltPaths(self.wrapper);
    }

    /**
     * Langium's `parse`, with the containers of the AST nodes set by `linkContainers` (below)
     * instead of `linkContentToContainer`, which took a sixth of the parse time.
     */
    override parse<T extends AstNode = AstNode>(input: string, options: ParserOptions = {}): ParseResult<T> {
        const self = this as unknown as LangiumParserInternals;
        self.nodeBuilder.buildRootNode(input);
        const lexerResult = self.lexer.tokenize(input);
        self.lexerResult = lexerResult;
        self.wrapper.input = lexerResult.tokens;
        const ruleMethod = options.rule ? self.allRules.get(options.rule) : self.mainRule;
        if (!ruleMethod) {
            throw new Error(options.rule ? `No rule found with name '${options.rule}'` : 'No main rule available.');
        }
        const result = self.doParse(ruleMethod);
        self.nodeBuilder.addHiddenNodes(lexerResult.hidden);
        self.unorderedGroups.clear();
        self.lexerResult = undefined;
        linkContainers(result);
        return {
            value: result as T,
            lexerErrors: lexerResult.errors,
            lexerReport: lexerResult.report,
            parserErrors: self.wrapper.errors,
        };
    }
}

type TypeMetaData = ReturnType<AstReflection['getTypeMetaData']>;

/**
 * The reflection as the parser's `construct` sees it: each type's metadata with only the
 * properties that have a default value. Langium's `assignMandatoryProperties`, the parser's one
 * use of it, runs once per rule call (16 times for an expression operand) over every property of
 * the node's type to find those; it finds the same ones here.
 */
function withDefaultsOnly(reflection: AstReflection): AstReflection {
    const cache = new Map<string, TypeMetaData>();
    const view = Object.create(reflection) as AstReflection;
    view.getTypeMetaData = (type: string): TypeMetaData => {
        let meta = cache.get(type);
        if (meta === undefined) {
            const full = reflection.getTypeMetaData(type);
            const properties: TypeMetaData['properties'] = {};
            for (const [name, property] of Object.entries(full.properties)) {
                if (property.defaultValue !== undefined) properties[name] = property;
            }
            meta = { ...full, properties };
            cache.set(type, meta);
        }
        return meta;
    };
    return view;
}

function isNode(value: unknown): value is AstNode {
    return typeof value === 'object' && value !== null && typeof (value as { $type?: unknown }).$type === 'string';
}

/**
 * Sets `$container`, `$containerProperty` and `$containerIndex` of every node below `node`, as
 * Langium's `linkContentToContainer(node, { deep: true })` does, without one entry array per
 * property and one closure per list.
 */
function linkContainers(node: AstNode): void {
    const record = node as unknown as Record<string, unknown>;
    for (const name in record) {
        if (name.charCodeAt(0) === 36 /* $ */) continue;
        const value = record[name];
        if (Array.isArray(value)) {
            for (let index = 0; index < value.length; index++) {
                const item: unknown = value[index];
                if (isNode(item)) {
                    const child = item as Mutable<AstNode>;
                    child.$container = node;
                    child.$containerProperty = name;
                    child.$containerIndex = index;
                    linkContainers(child);
                }
            }
        } else if (isNode(value)) {
            const child = value as Mutable<AstNode>;
            child.$container = node;
            child.$containerProperty = name;
            linkContainers(child);
        }
    }
}

/**
 * Merges the AST node of a rule called without assignment (`target`) with the node of the
 * calling rule (`source`), as Langium's `assignWithoutOverride` does, without one entry array
 * per property (`Object.entries`).
 */
function assignWithoutOverride(target: Record<string, unknown>, source: Record<string, unknown>): Record<string, unknown> {
    // AST nodes are plain objects: `for in` visits exactly their own enumerable properties.
    for (const name in source) {
        const existingValue = source[name];
        const newValue = target[name];
        if (newValue === undefined) {
            target[name] = existingValue;
        } else if (Array.isArray(newValue) && Array.isArray(existingValue)) {
            for (const item of newValue) existingValue.push(item);
            target[name] = existingValue;
        }
    }
    // The CST node the target got when its rule ended is replaced by the caller's: drop the
    // references between the two (as Langium does), so the CST holds no stale AST node.
    const targetCstNode = target.$cstNode as { astNode: unknown } | undefined;
    if (targetCstNode) {
        targetCstNode.astNode = undefined;
        target.$cstNode = undefined;
    }
    return target;
}
// `assignWithoutOverride` is private in Langium's typings, so it cannot be overridden in the class body.
Object.defineProperty(AdlParser.prototype, 'assignWithoutOverride', {
    value: assignWithoutOverride,
    writable: true,
    configurable: true,
});

interface AssignmentInfo {
    assignment?: GrammarAST.Assignment;
    crossRef?: 'single' | 'multi';
}

/** Langium's `getAssignment` (the assignment a grammar element belongs to, cached) with one map lookup instead of two. */
function getAssignment(
    this: { assignmentMap: Map<GrammarAST.AbstractElement, AssignmentInfo> },
    feature: GrammarAST.AbstractElement,
): AssignmentInfo {
    let info = this.assignmentMap.get(feature);
    if (info === undefined) {
        const assignment = AstUtils.getContainerOfType(feature, GrammarAST.isAssignment);
        const terminal = assignment?.terminal;
        info = {
            assignment,
            crossRef: terminal && GrammarAST.isCrossReference(terminal) ? (terminal.isMulti ? 'multi' : 'single') : undefined,
        };
        this.assignmentMap.set(feature, info);
    }
    return info;
}
Object.defineProperty(AdlParser.prototype, 'getAssignment', { value: getAssignment, writable: true, configurable: true });

/** Appends `child` to `parent`'s content, as `content.push(child)` does, without the rest array. */
function append(parent: CompositeCstNode, child: CstNode): void {
    (child as { container?: CompositeCstNode }).container = parent;
    const content = parent.content;
    content[content.length] = child;
}

/** Langium's CST builder without the work whose result is discarded (see createAdlParser). */
export class AdlCstNodeBuilder extends CstNodeBuilder {
    override buildCompositeNode(feature: GrammarAST.AbstractElement): CompositeCstNode {
        const compositeNode = new AdlCompositeCstNode();
        compositeNode.grammarSource = feature;
        const current = this.current;
        compositeNode.root = current.root;
        append(current, compositeNode);
        (this as unknown as { nodeStack: CompositeCstNode[] }).nodeStack.push(compositeNode);
        return compositeNode;
    }

    override buildLeafNode(token: LexerResult['tokens'][number], feature?: GrammarAST.AbstractElement): LeafCstNode {
        const leafNode = new AdlLeafCstNode(token, !feature);
        leafNode.grammarSource = feature;
        const current = this.current;
        leafNode.root = current.root;
        append(current, leafNode);
        return leafNode;
    }

    /**
     * Ends the current node as Langium does, then lets it take over the content of a
     * pass-through child (see `isPassThrough`): the expression grammar's operand `x` was 16
     * composite nodes nested one in the other, each kept as long as the document (the AST node
     * points to the outermost); now it is one. Offsets, ranges, texts, AST links and the leaves
     * stay the same; only the composite nodes of rule calls without assignment that cover exactly
     * what their caller covers are gone.
     */
    override construct(item: Parameters<CstNodeBuilder['construct']>[0]): void {
        const node = this.current as CompositeCstNode;
        super.construct(item);
        const content = node.content;
        if (content.length === 1) {
            const child = content[0] as CompositeCstNode;
            if (isPassThrough(child)) {
                const inner = child.content;
                content.length = 0;
                for (let i = 0; i < inner.length; i++) {
                    const grandchild = inner[i]!;
                    (grandchild as { container?: CompositeCstNode }).container = node;
                    content[i] = grandchild;
                }
            }
        }
    }

    /** Adding no hidden tokens changes nothing: skip the search for where they would go. */
    override addHiddenNodes(tokens: Parameters<CstNodeBuilder['addHiddenNodes']>[0]): void {
        if (tokens.length > 0) super.addHiddenNodes(tokens);
    }

    /** Removes the node from its container's content in place (no `splice`, see createAdlParser). */
    override removeNode(node: CstNode): void {
        const content = node.container?.content;
        if (!content) return;
        const index = content.indexOf(node);
        if (index < 0) return;
        for (let i = index + 1; i < content.length; i++) content[i - 1] = content[i]!;
        content.length--;
    }
}

/** Whether each grammar element is a rule call outside any assignment (cached per element). */
const unassignedRuleCalls = new WeakMap<object, boolean>();

/**
 * Whether a child composite node may be dissolved into its parent, its only child: it is the node
 * of a rule call without assignment (nothing but the CST points to it: an assigned call's node
 * may be a reference's `$refNode` or an AST node's `$cstNode`) and it has no AST node of its own
 * (Langium detaches it when the called rule's node merges into the caller's).
 */
function isPassThrough(child: CstNode): boolean {
    if (!(child instanceof CompositeCstNodeImpl)) return false;
    if ((child as unknown as { _astNode?: unknown })._astNode !== undefined) return false;
    const feature = child.grammarSource;
    if (feature === undefined) return false;
    let unassigned = unassignedRuleCalls.get(feature);
    if (unassigned === undefined) {
        unassigned = GrammarAST.isRuleCall(feature) && AstUtils.getContainerOfType(feature, GrammarAST.isAssignment) === undefined;
        unassignedRuleCalls.set(feature, unassigned);
    }
    return unassigned;
}

/**
 * A leaf CST node that keeps its token's line and column numbers and builds its range (three
 * objects, as `CstUtils.tokenToRange` does) when it is first asked for: most ranges never are,
 * and every leaf lives as long as its document.
 */
export class AdlLeafCstNode extends LeafCstNodeImpl {
    private readonly startLine: number;
    private readonly startColumn: number;
    private readonly endLine: number;
    private readonly endColumn: number;

    constructor(token: LexerResult['tokens'][number], hidden: boolean) {
        // The range argument is left out: the getter below computes it.
        super(token.startOffset, token.image.length, undefined as unknown as Range, token.tokenType, hidden);
        this.startLine = token.startLine!;
        this.startColumn = token.startColumn!;
        this.endLine = token.endLine!;
        this.endColumn = token.endColumn!;
    }

    override get range(): Range {
        const self = this as unknown as { _range?: Range };
        // Chevrotain's lines and columns are 1-based, the end column inclusive (CstUtils.tokenToRange).
        return (self._range ??= {
            start: { character: this.startColumn - 1, line: this.startLine - 1 },
            end: { character: this.endColumn, line: this.endLine - 1 },
        });
    }
}

/** A composite CST node whose first and last non-hidden children are found without iterators. */
export class AdlCompositeCstNode extends CompositeCstNodeImpl {}

Object.defineProperty(AdlCompositeCstNode.prototype, 'firstNonHiddenNode', {
    get(this: CompositeCstNode): CstNode | undefined {
        const content = this.content;
        for (let i = 0; i < content.length; i++) {
            if (!content[i]!.hidden) return content[i];
        }
        return content[0];
    },
    configurable: true,
});

Object.defineProperty(AdlCompositeCstNode.prototype, 'lastNonHiddenNode', {
    get(this: CompositeCstNode): CstNode | undefined {
        const content = this.content;
        for (let i = content.length - 1; i >= 0; i--) {
            if (!content[i]!.hidden) return content[i];
        }
        return content[content.length - 1];
    },
    configurable: true,
});
