import { GrammarUtils, type AstNode, type CstNode, type LangiumDocument } from 'langium';
import {
    AbstractFormatter,
    Formatting,
    type FormattingAction,
    type FormattingContext,
    type FormattingRegion,
    type NodeFormatter,
} from 'langium/lsp';
import type {
    DocumentFormattingParams,
    DocumentOnTypeFormattingParams,
    DocumentRangeFormattingParams,
    FormattingOptions,
} from 'vscode-languageserver-protocol';
import type { TextEdit } from 'vscode-languageserver-types';
import { isExpression } from '../generated/ast.js';
import { previousLeaf } from './node-info.js';

/** Formats one node (its own keywords and the gaps between its parts). */
export type FormattingRule = (node: AstNode, formatter: AdlFormatter) => void;

/** A formatting that puts a node after a line break into the column of another node. */
interface AlignAction extends FormattingAction {
    readonly align: CstNode;
}

function isAlign(f: FormattingAction): f is AlignAction {
    return 'align' in f;
}

/** A formatting that sets the number of line breaks before a node, comments included. */
interface LineAction extends FormattingAction {
    readonly exactLines: number;
}

function isLines(f: FormattingAction): f is LineAction {
    return 'exactLines' in f;
}

/** New line and one indentation level more; keeps (at most) one blank line the user left. */
const INDENT_KEEP_BLANK: FormattingAction = Formatting.fit(Formatting.indent(), { options: {}, moves: [{ tabs: 1, lines: 2 }] });

/**
 * The formatter of the family, in MontiArc's style: two-space indentation, one element per line
 * inside components, automata, states and class diagrams, single spaces around binary
 * operators, `->`, `=` and after keywords and commas, no space before `;`, `,`, `.` and argument
 * lists. Choices that are the modeler's are kept: statement blocks written on one line
 * (`/ { o = 1; }`), comma lists continued on the next line (aligned under their first element),
 * and one blank line between elements.
 *
 * Rules are registered per AST `$type` in `rules`; a behavior language adds rules for its node
 * types and uses the helpers (`elementBlock`, `statementBlock`, `list`, `keywordSpacing`).
 */
export class AdlFormatter extends AbstractFormatter {
    readonly rules = new Map<string, FormattingRule>();
    /** Spaces per indentation level (MontiArc style); the client's tab size is not used. */
    indentSize = 2;

    constructor() {
        super();
        registerHostRules(this);
    }

    // ---- API for rules ----

    /** The node formatter of Langium's formatting API for a node. */
    on<T extends AstNode>(node: T): NodeFormatter<T> {
        return this.getNodeFormatter(node);
    }

    /**
     * A body of elements between `open` and `close`: one element per line, indented, `close` on
     * its own line; an empty body becomes `{ }`. The opening keyword gets one space before it.
     */
    elementBlock(node: AstNode, open = '{', close = '}'): void {
        const f = this.on(node);
        const o = f.keyword(open);
        const c = f.keyword(close);
        if (o.nodes.length === 0 || c.nodes.length === 0) return;
        const interior = f.interior(o, c);
        if (interior.nodes.length === 0) {
            c.prepend(Formatting.oneSpace());
            return;
        }
        interior.prepend(INDENT_KEEP_BLANK);
        c.prepend(Formatting.newLine());
    }

    /**
     * A block of statements: formatted like an element block, except that a block written on
     * one line stays on one line (`{ toaster = ToasterCmd.START; }`).
     */
    statementBlock(node: AstNode, items: readonly AstNode[], open = '{', close = '}'): void {
        const f = this.on(node);
        const o = f.keyword(open);
        const c = f.keyword(close);
        const oc = o.nodes[0];
        const cc = c.nodes[0];
        if (!oc || !cc) return;
        const hasComment = f.interior(o, c).nodes.some((n) => n.hidden);
        if (oc.range.start.line === cc.range.start.line && !hasComment) {
            if (items.length === 0) {
                c.prepend(Formatting.oneSpace());
                return;
            }
            items.forEach((item, i) => {
                if (i > 0) f.node(item).prepend(Formatting.oneSpace());
            });
            o.append(Formatting.oneSpace());
            c.prepend(Formatting.oneSpace());
            return;
        }
        this.elementBlock(node, open, close);
    }

    /**
     * A comma-separated list (`port in int a, out int b`, `f(a, b)`): no space before a comma,
     * one after; an element the user put on a new line is aligned under the first element.
     */
    list(node: AstNode, items: readonly AstNode[]): void {
        const f = this.on(node);
        const first = items[0]?.$cstNode;
        for (const comma of f.keywords(',').nodes) this.collector(comma, 'prepend', Formatting.noSpace());
        if (!first) return;
        items.forEach((item, i) => {
            if (i === 0 || !item.$cstNode) return;
            const action: AlignAction = { options: {}, moves: [{ characters: 1 }], align: first };
            f.node(item).prepend(action);
        });
    }

    /** One space after each of the node's own keywords in `after`, one before each in `before`. */
    keywordSpacing(node: AstNode, spacing: { after?: string[]; before?: string[]; around?: string[]; tight?: string[] }): void {
        const f = this.on(node);
        for (const k of spacing.after ?? []) f.keywords(k).append(Formatting.oneSpace());
        for (const k of spacing.before ?? []) f.keywords(k).prepend(Formatting.oneSpace());
        for (const k of spacing.around ?? []) f.keywords(k).surround(Formatting.oneSpace());
        for (const k of spacing.tight ?? []) f.keywords(k).surround(Formatting.noSpace());
    }

    /**
     * Exactly one blank line before a node, or before the comments directly above it (which
     * stay attached to the node).
     */
    blankLineBefore(node: AstNode): void {
        const cst = node.$cstNode;
        if (!cst) return;
        let first: CstNode = cst;
        for (let prev = previousLeaf(first); prev?.hidden && first.range.start.line - prev.range.end.line <= 1; prev = previousLeaf(prev)) {
            const before = previousLeaf(prev);
            if (before && before.range.end.line === prev.range.start.line) break; // trails the element before
            first = prev;
        }
        const blank: LineAction = { options: {}, moves: [{ lines: 2 }], exactLines: 2 };
        this.collector(first, 'prepend', blank);
        if (first !== cst) this.collector(cst, 'prepend', Formatting.newLine());
    }

    /** The region of a property of any node (rules get nodes typed as `AstNode`). */
    property(node: AstNode, name: string): FormattingRegion {
        return this.on(node).cst(GrammarUtils.findNodesForProperty(node.$cstNode, name));
    }

    /** No space before the node's own `;`. */
    semicolons(node: AstNode): void {
        this.on(node).keywords(';').prepend(Formatting.noSpace());
    }

    // ---- Langium's formatter ----

    protected format(node: AstNode): void {
        const rule = this.rules.get(node.$type);
        if (rule) rule(node, this);
        if (isExpression(node)) parentheses(node, this);
    }

    override formatDocument(document: LangiumDocument, params: DocumentFormattingParams): TextEdit[] {
        return super.formatDocument(document, { ...params, options: this.style(params.options) }) as TextEdit[];
    }

    override formatDocumentRange(document: LangiumDocument, params: DocumentRangeFormattingParams): TextEdit[] {
        return super.formatDocumentRange(document, { ...params, options: this.style(params.options) }) as TextEdit[];
    }

    override formatDocumentOnType(document: LangiumDocument, params: DocumentOnTypeFormattingParams): TextEdit[] {
        return super.formatDocumentOnType(document, { ...params, options: this.style(params.options) }) as TextEdit[];
    }

    private style(options: FormattingOptions): FormattingOptions {
        return { ...options, insertSpaces: true, tabSize: this.indentSize };
    }

    protected override createTextEdit(
        a: CstNode | undefined,
        b: CstNode,
        formatting: FormattingAction,
        context: FormattingContext,
    ): TextEdit[] {
        if (isLines(formatting) && a && a.range.end.line < b.range.start.line) {
            // Langium only re-indents comments; this also sets the line breaks before them.
            const indent = ' '.repeat(context.indentation * (context.options.insertSpaces ? context.options.tabSize : 1));
            return [{ range: { start: a.range.end, end: b.range.start }, newText: `${'\n'.repeat(formatting.exactLines)}${indent}` }];
        }
        if (isAlign(formatting) && a && !b.hidden && a.range.end.line !== b.range.start.line) {
            const column = this.alignedColumn(formatting.align, context);
            if (column !== undefined) return [{ range: { start: a.range.end, end: b.range.start }, newText: `\n${' '.repeat(column)}` }];
        }
        return super.createTextEdit(a, b, formatting, context);
    }

    /**
     * Comments are re-indented with the code around them, except inside nodes no rule formats
     * (e.g. the block of a behavior language without formatting rules): those stay as written.
     */
    protected override createHiddenTextEdits(
        previous: CstNode | undefined,
        hidden: CstNode,
        formatting: FormattingAction | undefined,
        context: FormattingContext,
    ): TextEdit[] {
        if (!formatting && !this.rules.has(hidden.astNode.$type)) return [];
        return super.createHiddenTextEdits(previous, hidden, formatting, context);
    }

    /**
     * The column the first element of a list will have after formatting: the indentation of
     * its line plus the (normalized) text before it on that line.
     */
    private alignedColumn(first: CstNode, context: FormattingContext): number | undefined {
        const doc = context.document;
        const line = first.range.start.line;
        const lineText = doc.getText({ start: { line, character: 0 }, end: first.range.start });
        const indent = context.indentation * (context.options.insertSpaces ? context.options.tabSize : 1);
        const before = lineText.trim();
        if (before === '') return indent + this.indentSize;
        return indent + before.replace(/\s+/g, ' ').length + 1;
    }
}

/** `( expression )`: no space inside the parentheses. */
function parentheses(node: AstNode, f: AdlFormatter): void {
    const own = f.on(node);
    const open = own.keyword('(');
    const close = own.keyword(')');
    const cst = node.$cstNode;
    if (!cst) return;
    // Only parentheses that enclose the node itself (calls have their own rule).
    if (open.nodes[0] && open.nodes[0].offset === cst.offset) open.append(Formatting.noSpace());
    if (close.nodes.length && close.nodes[close.nodes.length - 1]!.end === cst.end && open.nodes[0]?.offset === cst.offset) {
        own.cst([close.nodes[close.nodes.length - 1]!]).prepend(Formatting.noSpace());
    }
}

type Props = Record<string, unknown>;

function nodes(node: AstNode, property: string): AstNode[] {
    const v = (node as unknown as Props)[property];
    return Array.isArray(v) ? v.filter((x): x is AstNode => typeof x === 'object' && x !== null && '$type' in x) : [];
}

function child(node: AstNode, property: string): AstNode | undefined {
    const v = (node as unknown as Props)[property];
    return typeof v === 'object' && v !== null && '$type' in v ? (v as AstNode) : undefined;
}

/**
 * Top-level elements of a model file: the package, a blank line, the imports (one per line), a
 * blank line, the one element. Comments directly above an element stay attached to it.
 */
function modelFile(node: AstNode, f: AdlFormatter, main: string): void {
    const on = f.on(node);
    on.keywords('package').append(Formatting.oneSpace());
    f.semicolons(node);
    const imports = nodes(node, 'imports');
    const hasPackage = Boolean((node as unknown as Props).package);
    imports.forEach((imp, i) => {
        if (i === 0 && hasPackage) f.blankLineBefore(imp);
        else on.node(imp).prepend(Formatting.newLine());
    });
    const element = child(node, main);
    if (element && (imports.length > 0 || hasPackage)) f.blankLineBefore(element);
}

/** Generics and parameter lists: `<A, B>`, `(int a, int b)` without inner spaces. */
function brackets(node: AstNode, f: AdlFormatter, open: string, close: string, items: readonly AstNode[]): void {
    const on = f.on(node);
    on.keywords(open).prepend(Formatting.noSpace());
    on.keywords(open).append(Formatting.noSpace());
    on.keywords(close).prepend(Formatting.noSpace());
    f.list(node, items);
}

function registerHostRules(f: AdlFormatter): void {
    const r = f.rules;
    // ---- files ----
    r.set('ArcModel', (n, fm) => modelFile(n, fm, 'component'));
    r.set('CDModel', (n, fm) => modelFile(n, fm, 'diagram'));
    for (const t of ['ArcImport', 'CDImport']) {
        r.set(t, (n, fm) => {
            fm.keywordSpacing(n, { after: ['import'] });
            fm.semicolons(n);
        });
    }
    r.set('Stereotype', (n, fm) => {
        const on = fm.on(n);
        on.keywords('<<').append(Formatting.noSpace());
        on.keywords('>').prepend(Formatting.noSpace());
        fm.list(n, nodes(n, 'values'));
        // A stereotype is followed by what it annotates.
        on.keywords('>').slice(-1).append(Formatting.oneSpace());
    });
    r.set('StereoValue', (n, fm) => fm.keywordSpacing(n, { tight: ['='] }));

    // ---- components ----
    r.set('ComponentType', (n, fm) => {
        const on = fm.on(n);
        on.keywords('component').append(Formatting.oneSpace());
        const typeParams = nodes(n, 'typeParams');
        if (typeParams.length) {
            on.keyword('<').prepend(Formatting.noSpace()).append(Formatting.noSpace());
            on.keyword('>').prepend(Formatting.noSpace());
        }
        const open = on.keyword('(');
        if (open.nodes.length) {
            open.prepend(Formatting.noSpace()).append(Formatting.noSpace());
            on.keyword(')').prepend(Formatting.noSpace());
        }
        fm.list(n, typeParams);
        fm.list(n, nodes(n, 'params'));
        const instances = nodes(n, 'instances');
        instances.forEach((inst, i) => {
            if (i === 0) on.node(inst).prepend(Formatting.oneSpace());
        });
        fm.list(n, instances);
        on.keywords('extends').surround(Formatting.oneSpace());
        fm.list(n, nodes(n, 'parents'));
        const body = child(n, 'body');
        if (body) on.node(body).prepend(Formatting.oneSpace());
    });
    r.set('ComponentBody', (n, fm) => fm.elementBlock(n));
    r.set('Parameter', (n, fm) => {
        fm.property(n, 'name').prepend(Formatting.oneSpace());
        fm.keywordSpacing(n, { around: ['='] });
    });
    r.set('ParentComponent', (n, fm) => brackets(n, fm, '(', ')', nodes(n, 'args')));
    r.set('ComponentTypeRef', (n, fm) => brackets(n, fm, '<', '>', nodes(n, 'typeArgs')));
    r.set('PortDeclaration', (n, fm) => {
        fm.keywordSpacing(n, { after: ['port'] });
        fm.semicolons(n);
        fm.list(n, nodes(n, 'ports'));
    });
    r.set('Port', (n, fm) => {
        if ((n as unknown as Props).direction) {
            fm.property(n, 'direction').append(Formatting.oneSpace());
            fm.property(n, 'name').prepend(Formatting.oneSpace());
        }
    });
    r.set('FieldDeclaration', (n, fm) => {
        const fields = nodes(n, 'fields');
        if (fields[0]) fm.on(n).node(fields[0]).prepend(Formatting.oneSpace());
        fm.list(n, fields);
        fm.semicolons(n);
    });
    r.set('Field', (n, fm) => fm.keywordSpacing(n, { around: ['='] }));
    // Variable architectures: `feature a, b;`, `constraint(e);`, `varif (e) { ... } else { ... }`.
    r.set('FeatureDeclaration', (n, fm) => {
        const features = nodes(n, 'features');
        if (features[0]) fm.on(n).node(features[0]).prepend(Formatting.oneSpace());
        fm.list(n, features);
        fm.semicolons(n);
    });
    r.set('ConstraintDeclaration', (n, fm) => {
        const on = fm.on(n);
        on.keyword('(').prepend(Formatting.noSpace()).append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace());
        fm.semicolons(n);
    });
    r.set('VarIf', (n, fm) => {
        const on = fm.on(n);
        on.keyword('varif').append(Formatting.oneSpace());
        on.keyword('(').append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace()).append(Formatting.oneSpace());
        on.keywords('else').surround(Formatting.oneSpace());
    });
    r.set('VarBody', (n, fm) => fm.elementBlock(n));
    r.set('ComponentInstantiation', (n, fm) => {
        const instances = nodes(n, 'instances');
        if (instances[0]) fm.on(n).node(instances[0]).prepend(Formatting.oneSpace());
        fm.list(n, instances);
        fm.semicolons(n);
    });
    r.set('Subcomponent', (n, fm) => brackets(n, fm, '(', ')', nodes(n, 'args')));
    r.set('Connector', (n, fm) => {
        fm.keywordSpacing(n, { around: ['->'] });
        fm.list(n, nodes(n, 'targets'));
        fm.semicolons(n);
    });
    r.set('PortAccess', (n, fm) => fm.keywordSpacing(n, { tight: ['.'] }));
    r.set('BehaviorDeclaration', () => undefined);
    for (const t of ['ComputeBlock', 'InitBlock']) r.set(t, (n, fm) => fm.keywordSpacing(n, { after: ['compute', 'init'] }));

    // ---- statements ----
    r.set('Block', (n, fm) => fm.statementBlock(n, nodes(n, 'statements')));
    r.set('LocalVariableDeclaration', (n, fm) => {
        const vars = nodes(n, 'variables');
        if (vars[0]) fm.on(n).node(vars[0]).prepend(Formatting.oneSpace());
        fm.list(n, vars);
        fm.semicolons(n);
    });
    r.set('LocalVariable', (n, fm) => fm.keywordSpacing(n, { around: ['='] }));
    r.set('ExpressionStatement', (n, fm) => fm.semicolons(n));
    r.set('IfStatement', (n, fm) => {
        const on = fm.on(n);
        on.keyword('if').append(Formatting.oneSpace());
        on.keyword('(').append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace()).append(Formatting.oneSpace());
        on.keywords('else').surround(Formatting.oneSpace());
    });
    r.set('WhileStatement', (n, fm) => {
        const on = fm.on(n);
        on.keyword('while').append(Formatting.oneSpace());
        on.keyword('(').append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace()).append(Formatting.oneSpace());
    });
    r.set('ForStatement', (n, fm) => {
        const on = fm.on(n);
        on.keyword('for').append(Formatting.oneSpace());
        on.keyword('(').append(Formatting.noSpace());
        on.keywords(';').prepend(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace()).append(Formatting.oneSpace());
        fm.list(n, nodes(n, 'updates'));
    });
    r.set('DoWhileStatement', (n, fm) => {
        const on = fm.on(n);
        on.keyword('do').append(Formatting.oneSpace());
        on.keyword('while').surround(Formatting.oneSpace());
        on.keyword('(').append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace());
        fm.semicolons(n);
    });
    r.set('SwitchStatement', (n, fm) => {
        const on = fm.on(n);
        on.keyword('switch').append(Formatting.oneSpace());
        on.keyword('(').append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace()).append(Formatting.oneSpace());
        fm.elementBlock(n);
    });
    // `case 1:` groups: one label per line, the statements indented below; `case 1 -> s;` rules on one line.
    r.set('SwitchGroup', (n, fm) => {
        const on = fm.on(n);
        const labels = nodes(n, 'labels');
        for (const l of labels.slice(1)) on.node(l).prepend(Formatting.newLine());
        const arrow = labels.some((l) => (l as AstNode & { arrow?: boolean }).arrow);
        for (const st of nodes(n, 'statements')) on.node(st).prepend(arrow ? Formatting.oneSpace() : Formatting.indent());
    });
    r.set('SwitchLabel', (n, fm) => {
        const on = fm.on(n);
        on.keyword('case').append(Formatting.oneSpace());
        on.keywords(':').prepend(Formatting.noSpace());
        on.keywords('->').prepend(Formatting.oneSpace());
        fm.list(n, nodes(n, 'values'));
    });
    // Switch expressions: like the statement, one arm per line (`case 1 -> value;`, `case 2 -> { ... }`).
    r.set('SwitchExpression', (n, fm) => {
        const on = fm.on(n);
        on.keyword('switch').append(Formatting.oneSpace());
        on.keyword('(').append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace()).append(Formatting.oneSpace());
        fm.elementBlock(n);
    });
    r.set('SwitchArm', (n, fm) => {
        const on = fm.on(n);
        const part = child(n, 'value') ?? child(n, 'body');
        if (part) on.node(part).prepend(Formatting.oneSpace());
        fm.semicolons(n);
    });
    r.set('YieldStatement', (n, fm) => {
        fm.on(n).keyword('yield').append(Formatting.oneSpace());
        fm.semicolons(n);
    });
    for (const t of ['BreakStatement', 'ContinueStatement']) r.set(t, (n, fm) => fm.semicolons(n));

    // ---- expressions ----
    r.set('BinaryExpression', (n, fm) => fm.property(n, 'op').surround(Formatting.oneSpace()));
    r.set('AssignmentExpression', (n, fm) => fm.property(n, 'op').surround(Formatting.oneSpace()));
    r.set('ConditionalExpression', (n, fm) => fm.keywordSpacing(n, { around: ['?', ':'] }));
    r.set('PrefixExpression', (n, fm) => fm.property(n, 'op').append(Formatting.noSpace()));
    r.set('PostfixExpression', (n, fm) => fm.property(n, 'op').prepend(Formatting.noSpace()));
    r.set('FieldAccessExpression', (n, fm) => fm.keywordSpacing(n, { tight: ['.'] }));
    r.set('CallExpression', (n, fm) => {
        const on = fm.on(n);
        const open = on.keywords('(').slice(-1);
        open.prepend(Formatting.noSpace()).append(Formatting.noSpace());
        on.keywords(')').slice(-1).prepend(Formatting.noSpace());
        fm.list(n, nodes(n, 'args'));
    });
    r.set('ArrayAccessExpression', (n, fm) => {
        const on = fm.on(n);
        on.keywords('[').slice(-1).prepend(Formatting.noSpace()).append(Formatting.noSpace());
        on.keywords(']').slice(-1).prepend(Formatting.noSpace());
    });

    // ---- types ----
    r.set('ReferenceType', (n, fm) => brackets(n, fm, '<', '>', nodes(n, 'typeArgs')));
    r.set('ArrayType', (n, fm) => {
        const on = fm.on(n);
        on.keywords('[').prepend(Formatting.noSpace()).append(Formatting.noSpace());
    });
    r.set('TypeParameter', (n, fm) => fm.keywordSpacing(n, { around: ['extends', '&'] }));
    r.set('WildcardType', (n, fm) => fm.keywordSpacing(n, { around: ['extends', 'super'] }));

    // ---- class diagrams ----
    r.set('ClassDiagram', (n, fm) => {
        fm.keywordSpacing(n, { after: ['classdiagram'], before: ['{'] });
        fm.elementBlock(n);
    });
    r.set('CDClass', (n, fm) => {
        const on = fm.on(n);
        fm.property(n, 'kind').append(Formatting.oneSpace());
        const typeParams = nodes(n, 'typeParams');
        if (typeParams.length) {
            on.keyword('<').prepend(Formatting.noSpace()).append(Formatting.noSpace());
            on.keyword('>').prepend(Formatting.noSpace());
            fm.list(n, typeParams);
        }
        on.keywords('extends', 'implements').surround(Formatting.oneSpace());
        fm.list(n, [...nodes(n, 'superTypes'), ...nodes(n, 'interfaces')]);
        on.keywords('{').prepend(Formatting.oneSpace());
        fm.semicolons(n);
        fm.elementBlock(n);
    });
    r.set('CDEnum', (n, fm) => {
        const on = fm.on(n);
        on.keyword('enum').append(Formatting.oneSpace());
        on.keyword('{').prepend(Formatting.oneSpace());
        on.keywords(';').prepend(Formatting.noSpace());
        fm.statementBlock(n, [...nodes(n, 'constants'), ...nodes(n, 'members')]);
        fm.list(n, nodes(n, 'constants'));
    });
    r.set('CDAttribute', (n, fm) => {
        fm.property(n, 'name').prepend(Formatting.oneSpace());
        fm.semicolons(n);
    });
    r.set('CDMethod', (n, fm) => {
        const on = fm.on(n);
        fm.property(n, 'name').prepend(Formatting.oneSpace());
        on.keyword('(').prepend(Formatting.noSpace()).append(Formatting.noSpace());
        on.keyword(')').prepend(Formatting.noSpace());
        fm.list(n, nodes(n, 'params'));
        fm.semicolons(n);
    });
    r.set('CDMethodParameter', (n, fm) => fm.property(n, 'name').prepend(Formatting.oneSpace()));
    r.set('CDAssociation', (n, fm) => {
        fm.property(n, 'kind').append(Formatting.oneSpace());
        fm.property(n, 'direction').surround(Formatting.oneSpace());
        fm.semicolons(n);
    });
}
