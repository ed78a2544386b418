import {
    AstUtils,
    CstUtils,
    GrammarAST,
    GrammarUtils,
    stream,
    type AstNode,
    type AstNodeDescription,
    type LangiumDocument,
    type MaybePromise,
    type ReferenceInfo,
    type Stream,
} from 'langium';
import {
    DefaultCompletionProvider,
    type CompletionAcceptor,
    type CompletionContext,
    type CompletionProviderOptions,
    type CompletionValueItem,
    type NextFeature,
} from 'langium/lsp';
import type { TextEdit } from 'vscode-languageserver-types';
import type { AdlLspServices } from './lsp-module.js';
import { allPorts, enclosingComponent, subcomponentType, subcomponentsOf } from '../components/component-model.js';
import { isArcModel, isCDModel, isExpression } from '../generated/ast.js';
import { ERROR_TYPE, type SymType } from '../types/sym-type.js';
import { detail } from './descriptions.js';
import { importName, membersOf } from './node-info.js';

/**
 * Completes one feature the parser expects at the cursor; returns true when it handled the
 * feature completely (the default completion is then skipped for it).
 */
export type CompletionContribution = (
    context: CompletionContext,
    next: NextFeature,
    acceptor: CompletionAcceptor,
) => MaybePromise<boolean | void>;

/** Reference types whose targets are model types or components (completed by simple name). */
const TYPE_TARGETS = new Set(['CDClass', 'CDEnum', 'ComponentType']);

/**
 * Completion for every language of the family: keywords the grammar allows at the cursor, the
 * names a reference may denote there (through the family's one shared scope, so the component's
 * ports, fields and parameters inside embedded blocks too), types and components by their simple
 * name (adding the import when needed), and the members after `Type.` / `value.`.
 * Behavior languages add `contributions`.
 */
export class AdlCompletionProvider extends DefaultCompletionProvider {
    readonly contributions: CompletionContribution[] = [];
    override readonly completionOptions: CompletionProviderOptions = { triggerCharacters: ['.'] };
    private readonly services: AdlLspServices;
    /** Completion items that need an import, by the description they were made from. */
    private readonly imports = new WeakMap<AstNodeDescription, string>();

    constructor(services: AdlLspServices) {
        super(services);
        this.services = services;
        this.contributions.push((context, next, acceptor) => this.completeSubcomponentPorts(context, next, acceptor));
    }

    protected override async completionFor(context: CompletionContext, next: NextFeature, acceptor: CompletionAcceptor): Promise<void> {
        for (const contribution of this.contributions) {
            if (await contribution(context, next, acceptor)) return;
        }
        if (this.afterDot(context) !== undefined && this.isNameFeature(next)) {
            this.completeMembers(context, acceptor);
            return;
        }
        await super.completionFor(context, next, acceptor);
    }

    /** Soft keywords are identifiers too: never offer them where a name is expected. */
    protected override filterKeyword(context: CompletionContext, keyword: GrammarAST.Keyword): boolean {
        const rule = AstUtils.getContainerOfType(keyword, GrammarAST.isParserRule);
        if (rule && (rule.name === 'Name' || rule.name === 'NameSegment')) return false;
        return super.filterKeyword(context, keyword);
    }

    /**
     * Types and components are offered by simple name where that name resolves to them, else by
     * simple name plus an import (or by qualified name when the simple name means something else).
     */
    protected override getReferenceCandidates(refInfo: ReferenceInfo, context: CompletionContext): Stream<AstNodeDescription> {
        const scope = this.scopeProvider.getScope(refInfo);
        const byNode = new Map<unknown, AstNodeDescription[]>();
        const order: unknown[] = [];
        for (const d of scope.getAllElements()) {
            const key = d.node ?? `${d.documentUri.toString()}#${d.path}`;
            const list = byNode.get(key);
            if (list) list.push(d);
            else {
                byNode.set(key, [d]);
                order.push(key);
            }
        }
        const out: AstNodeDescription[] = [];
        for (const key of order) {
            const group = byNode.get(key)!;
            const best = group.slice().sort((a, b) => a.name.length - b.name.length)[0]!;
            if (!best.name.includes('.') || !TYPE_TARGETS.has(best.type)) {
                out.push(best);
                continue;
            }
            const simple = best.name.substring(best.name.lastIndexOf('.') + 1);
            const resolved = scope.getElement(simple);
            if (resolved && sameTarget(resolved, best)) {
                out.push({ ...best, name: simple });
            } else if (!resolved && refInfo.container.$type !== 'NameExpression' && this.canImport(context.document)) {
                const candidate = { ...best, name: simple };
                this.imports.set(candidate, best.node ? (importName(best.node) ?? best.name) : best.name);
                out.push(candidate);
            } else {
                out.push(best);
            }
        }
        return stream(out);
    }

    protected override createReferenceCompletionItem(
        nodeDescription: AstNodeDescription,
        refInfo: ReferenceInfo,
        context: CompletionContext,
    ): CompletionValueItem {
        const item = super.createReferenceCompletionItem(nodeDescription, refInfo, context);
        const node = nodeDescription.node;
        const toImport = this.imports.get(nodeDescription);
        const isType = TYPE_TARGETS.has(nodeDescription.type);
        return {
            ...item,
            detail: toImport ? `${toImport} (import)` : ((node && detail(node)) ?? nodeDescription.type),
            documentation: this.documentationOf(node),
            // Names of the component (ports, fields, ...) before types, types before keywords.
            sortText: isType && refInfo.container.$type === 'NameExpression' ? '2' : '0',
            additionalTextEdits: toImport ? importEdits(context.document, toImport) : undefined,
        };
    }

    private documentationOf(node: AstNode | undefined): { kind: 'markdown'; value: string } | undefined {
        if (!node) return undefined;
        const text = this.services.lsp.HoverProvider.describeNode(node);
        return text ? { kind: 'markdown', value: text } : undefined;
    }

    private canImport(document: LangiumDocument): boolean {
        const root = document.parseResult.value;
        return isArcModel(root) || isCDModel(root);
    }

    /** The offset of the `.` right before the completed token, if there is one. */
    private afterDot(context: CompletionContext): number | undefined {
        const text = context.textDocument.getText();
        let i = context.tokenOffset - 1;
        while (i >= 0 && /\s/.test(text[i]!)) i--;
        return text[i] === '.' ? i : undefined;
    }

    /** Whether a feature is a plain name (the member of a field access is one). */
    private isNameFeature(next: NextFeature): boolean {
        const f = next.feature;
        if (GrammarAST.isCrossReference(f)) return false;
        if (GrammarAST.isRuleCall(f)) return f.rule.ref?.name === 'ID' || f.rule.ref?.name === 'Name';
        if (GrammarAST.isKeyword(f)) return false;
        const assignment = GrammarAST.isAssignment(f) ? f : AstUtils.getContainerOfType(f, GrammarAST.isAssignment);
        return assignment?.feature === 'member';
    }

    /**
     * `sub.` in a connector: the ports of the subcomponent's type (the parser cannot build the
     * port access yet, so the subcomponent is found by the name before the dot).
     */
    private completeSubcomponentPorts(context: CompletionContext, next: NextFeature, acceptor: CompletionAcceptor): boolean {
        if (!GrammarAST.isCrossReference(next.feature)) return false;
        const assignment = AstUtils.getContainerOfType(next.feature, GrammarAST.isAssignment);
        const rule = assignment && AstUtils.getContainerOfType(assignment, GrammarAST.isParserRule);
        if (assignment?.feature !== 'port' || rule?.name !== 'PortAccess') return false;
        const dot = this.afterDot(context);
        if (dot === undefined) return false;
        const name = /([_a-zA-Z$][\w$]*)\s*$/.exec(context.textDocument.getText().substring(0, dot))?.[1];
        const component = enclosingComponent(context.node ?? context.document.parseResult.value);
        const sub = name && component ? subcomponentsOf(component).find((s) => s.name === name) : undefined;
        if (!sub) return false;
        const { decl, subst } = subcomponentType(sub);
        for (const p of decl ? allPorts(decl, subst) : []) {
            acceptor(context, {
                label: p.name,
                kind: this.nodeKindProvider.getCompletionItemKind(p.port),
                detail: detail(p.port),
                documentation: this.documentationOf(p.port),
                sortText: '0',
            });
        }
        return true;
    }

    /** Members after `.`: enum constants after an enum type, attributes after a value or class. */
    private completeMembers(context: CompletionContext, acceptor: CompletionAcceptor): void {
        const dot = this.afterDot(context)!;
        const type = this.receiverType(context, dot);
        const kinds = this.nodeKindProvider;
        for (const m of membersOf(type, this.services.maa.TypeRelations)) {
            acceptor(context, {
                label: m.name,
                kind: kinds.getCompletionItemKind(m.node),
                detail: detail(m.node),
                documentation: this.documentationOf(m.node),
                sortText: '0',
            });
        }
    }

    private receiverType(context: CompletionContext, dot: number): SymType {
        const typer = this.services.maa.ExpressionTyper;
        const cst = context.document.parseResult.value.$cstNode;
        let leaf = cst && CstUtils.findLeafNodeBeforeOffset(cst, dot);
        // The leaf found may be the `.` itself (the parser kept it): the receiver ends before it.
        if (cst && leaf && leaf.offset >= dot && dot > 0) leaf = CstUtils.findLeafNodeBeforeOffset(cst, dot - 1);
        if (leaf && leaf.end <= dot && !leaf.hidden) {
            let expr: AstNode | undefined = leaf.astNode;
            if (expr && isExpression(expr)) {
                while (
                    expr.$container &&
                    isExpression(expr.$container) &&
                    expr.$container.$cstNode &&
                    expr.$container.$cstNode.end === leaf.end
                ) {
                    expr = expr.$container;
                }
                const t = typer.typeOf(expr as Parameters<typeof typer.typeOf>[0], []);
                if (t.kind !== 'error') return t;
            }
        }
        // The parser may have dropped the receiver of an unfinished access: resolve its text.
        const text = context.textDocument.getText().substring(0, dot);
        const qn = /([_a-zA-Z$][\w$]*(?:\s*\.\s*[_a-zA-Z$][\w$]*)*)\s*$/.exec(text)?.[1]?.replace(/\s+/g, '');
        const anchor = leaf?.astNode ?? context.node ?? context.document.parseResult.value;
        const type = qn ? this.services.maa.NameResolver.resolveType(anchor, qn) : undefined;
        if (type?.node) return typer.typeOfNamed(type.node);
        return ERROR_TYPE;
    }
}

function sameTarget(a: AstNodeDescription, b: AstNodeDescription): boolean {
    if (a.node && b.node) return a.node === b.node;
    return a.documentUri.toString() === b.documentUri.toString() && a.path === b.path;
}

/** The edit that adds `import qn;` to a model file (after the last import, or after the package). */
export function importEdits(document: LangiumDocument, qualifiedName: string): TextEdit[] {
    const root = document.parseResult.value;
    if (!isArcModel(root) && !isCDModel(root)) return [];
    if (root.imports.some((i) => i.importedNamespace === qualifiedName)) return [];
    const last = root.imports[root.imports.length - 1]?.$cstNode;
    if (last) return [{ range: { start: last.range.end, end: last.range.end }, newText: `\nimport ${qualifiedName};` }];
    const packageEnd = root.package ? GrammarUtils.findNodeForKeyword(root.$cstNode, ';') : undefined;
    if (packageEnd) return [{ range: { start: packageEnd.range.end, end: packageEnd.range.end }, newText: `\n\nimport ${qualifiedName};` }];
    const start = { line: 0, character: 0 };
    return [{ range: { start, end: start }, newText: `import ${qualifiedName};\n\n` }];
}
