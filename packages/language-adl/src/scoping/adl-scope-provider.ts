import {
    AstUtils,
    EMPTY_SCOPE,
    WorkspaceCache,
    type AstNode,
    type AstNodeDescription,
    type AstNodeDescriptionProvider,
    type LangiumSharedCoreServices,
    type ReferenceInfo,
    type Scope,
    type ScopeProvider,
} from 'langium';
import type { Block, CDEnum, ComponentType, NameExpression, SwitchGroup } from '../generated/ast.js';
import {
    isAssignmentExpression,
    isBlock,
    isCDEnum,
    isComponentType,
    isSwitchGroup,
    isForStatement,
    isLocalVariableDeclaration,
    isParentComponent,
    isPortAccess,
    isStatement,
    isSubcomponent,
} from '../generated/ast.js';
import type { ExpressionTyper } from '../types/expression-typer.js';
import { switchOfLabelValue } from './switch-labels.js';
import { allPorts, subcomponentType, subcomponentsOf, elementsOf } from '../components/component-model.js';
import { allFeatures } from '../components/features.js';
import { sameBranchFirst } from '../components/variant-context.js';
import { LookupScope } from './lookup-scope.js';
import type { NameResolver } from './name-resolver.js';

/**
 * Resolves every cross-reference of the host language (and the expressions embedded behavior
 * languages reuse) by lookup: see NameResolver for types and components; ports, subcomponents
 * and expression names come from the enclosing component, including inherited ports.
 */
export class AdlScopeProvider implements ScopeProvider {
    /**
     * Scopes contributed by embedded languages for their own references, keyed by
     * `ContainerType.property` (e.g. `Transition.source`): the symbolic integration point.
     */
    readonly contributions = new Map<string, (context: ReferenceInfo) => Scope>();

    /**
     * The names of each component (its own and inherited ports, parameters, fields, ...) and the
     * local variables of each block, by name: resolving each of n names by scanning the component
     * or block made linking quadratic (a model with 5,000 ports took a minute). Cleared on every
     * change in the workspace, since inherited ports come from other documents.
     */
    private readonly componentTables: WorkspaceCache<ComponentType, ReadonlyMap<string, AstNode>>;
    private readonly portTables: WorkspaceCache<ComponentType, ReadonlyMap<string, AstNode>>;
    private readonly blockTables: WorkspaceCache<Block | SwitchGroup, ReadonlyMap<string, ReadonlyArray<{ index: number; node: AstNode }>>>;

    constructor(
        private readonly resolver: NameResolver,
        private readonly descriptions: AstNodeDescriptionProvider,
        shared: LangiumSharedCoreServices,
        /** The typer, for the selector type of a switch whose case labels name enum constants (lazy: it needs the scopes). */
        private readonly typer?: () => ExpressionTyper,
    ) {
        this.componentTables = new WorkspaceCache(shared);
        this.portTables = new WorkspaceCache(shared);
        this.blockTables = new WorkspaceCache(shared);
    }

    getScope(context: ReferenceInfo): Scope {
        const c = context.container;
        const key = `${c.$type}.${context.property}`;
        const contributed = this.contributions.get(key);
        if (contributed) {
            const scope = contributed(context);
            return key === 'PortAccess.subcomponent' ? sameBranchScope(c, scope) : scope;
        }
        switch (key) {
            case 'ReferenceType.ref':
                return new LookupScope(
                    (n) => this.resolver.resolveType(c, n),
                    () => this.resolver.visible(c, 'type'),
                );
            case 'ComponentTypeRef.ref':
                return new LookupScope(
                    (n) => this.resolver.resolveComponent(c, n),
                    () => this.resolver.visible(c, 'component'),
                );
            case 'PortAccess.subcomponent':
                return this.nodes(() => {
                    const comp = AstUtils.getContainerOfType(c, isComponentType);
                    // In `varif (f) { A sub; ... } else { B sub; ... }` a connector means the `sub` of its own branch.
                    return comp ? sameBranchFirst(c, subcomponentsOf(comp)) : [];
                });
            case 'PortAccess.port':
                return this.table(() => {
                    if (!isPortAccess(c)) return EMPTY_TABLE;
                    if (c.subcomponent) {
                        const sub = c.subcomponent.ref;
                        const decl = sub && subcomponentType(sub).decl;
                        return decl ? this.portTable(decl) : EMPTY_TABLE;
                    }
                    const comp = AstUtils.getContainerOfType(c, isComponentType);
                    return comp ? this.portTable(comp) : EMPTY_TABLE;
                });
            case 'NameExpression.ref':
                return this.expressionScope(c as NameExpression);
            case 'CDAssociationEnd.type':
                return new LookupScope(
                    (n) => this.resolver.resolveType(c, n),
                    () => this.resolver.visible(c, 'type'),
                );
            default:
                return EMPTY_SCOPE;
        }
    }

    /** The key of a key argument (`sub(p = 1)`) names a parameter of the instantiated type. */
    private argumentKeyTarget(expr: NameExpression): ComponentType | undefined | null {
        const assign = expr.$container;
        if (!isAssignmentExpression(assign) || assign.left !== expr || assign.op !== '=') return null;
        const owner = assign.$container;
        if (isSubcomponent(owner)) return subcomponentType(owner).decl;
        if (isParentComponent(owner)) return owner.type?.ref?.ref; // no type: partially parsed
        return null;
    }

    private expressionScope(expr: NameExpression): Scope {
        const keyTarget = this.argumentKeyTarget(expr);
        if (keyTarget !== null) {
            // A key names a parameter or (MontiArc's feature binding, `sub(f = true)`) a feature.
            return this.nodes(() => (keyTarget ? [...keyTarget.params, ...allFeatures(keyTarget)] : []));
        }
        const labelEnum = this.caseLabelEnum(expr);
        if (labelEnum) {
            // Java's enum switch (JLS 14.11.1, MontiCore's EnumConstantSwitchLabel): a bare case
            // label names a constant of the selector's enum, whatever else that name means here.
            return this.nodes(() => labelEnum.constants);
        }
        const find = (name: string): AstNodeDescription | undefined => {
            const local = this.localName(expr, name);
            if (local) return this.descriptions.createDescription(local, name);
            return this.resolver.resolveType(expr, name);
        };
        const all = (): AstNodeDescription[] => {
            const out: AstNodeDescription[] = [];
            for (const { name, node } of this.localNames(expr)) out.push(this.descriptions.createDescription(node, name));
            out.push(...this.resolver.visible(expr, 'type'));
            return out;
        };
        return new LookupScope(find, all);
    }

    /** The enum whose constants a bare case label names (`case RED:` in a switch over a `Color`), if `expr` is one. */
    private caseLabelEnum(expr: NameExpression): CDEnum | undefined {
        const sw = switchOfLabelValue(expr);
        if (!sw || !this.typer) return undefined;
        const t = this.typer().typeOf(sw.selector);
        return t.kind === 'object' && isCDEnum(t.decl) ? t.decl : undefined;
    }

    /** The innermost name visible at an expression (as the first of localNames, by table lookups). */
    private localName(expr: AstNode, name: string): AstNode | undefined {
        let previous: AstNode = expr;
        for (let n: AstNode | undefined = expr.$container; n; previous = n, n = n.$container) {
            // A switch group's statements are a block of their own (its locals are visible after them in the group).
            if (isBlock(n) || isSwitchGroup(n)) {
                // $containerIndex: indexOf would scan the block for each name again.
                const upTo = isStatement(previous) ? (previous.$containerIndex ?? n.statements.indexOf(previous)) : n.statements.length;
                const found = nearestBefore(this.blockTable(n).get(name), upTo);
                if (found) return found;
            } else if (isForStatement(n) && n.init) {
                const v = n.init.variables.find((x) => x.name === name);
                if (v) return v;
            } else if (isComponentType(n)) {
                return this.componentTable(n).get(name);
            }
        }
        return undefined;
    }

    /** A component's own and inherited ports by name (the first of a name, as allPorts lists them). */
    private portTable(c: ComponentType): ReadonlyMap<string, AstNode> {
        return this.portTables.get(c, () => {
            const table = new Map<string, AstNode>();
            for (const p of allPorts(c)) if (!table.has(p.name)) table.set(p.name, p.port);
            return table;
        });
    }

    private componentTable(c: ComponentType): ReadonlyMap<string, AstNode> {
        return this.componentTables.get(c, () => {
            const table = new Map<string, AstNode>();
            for (const { name, node } of this.componentNames(c)) if (!table.has(name)) table.set(name, node);
            return table;
        });
    }

    /** A block's local variables by name, each with the index of its declaring statement (ascending). */
    private blockTable(b: Block | SwitchGroup): ReadonlyMap<string, ReadonlyArray<{ index: number; node: AstNode }>> {
        return this.blockTables.get(b, () => {
            const table = new Map<string, Array<{ index: number; node: AstNode }>>();
            b.statements.forEach((s, index) => {
                if (!isLocalVariableDeclaration(s)) return;
                for (const v of s.variables) {
                    const list = table.get(v.name) ?? [];
                    list.push({ index, node: v });
                    table.set(v.name, list);
                }
            });
            return table;
        });
    }

    /** Names visible at an expression, innermost first. */
    private *localNames(expr: AstNode): Generator<{ name: string; node: AstNode }> {
        let previous: AstNode = expr;
        for (let n: AstNode | undefined = expr.$container; n; previous = n, n = n.$container) {
            // A switch group's statements are a block of their own (its locals are visible after them in the group).
            if (isBlock(n) || isSwitchGroup(n)) {
                const upTo = isStatement(previous) ? n.statements.indexOf(previous) : n.statements.length;
                for (let i = upTo - 1; i >= 0; i--) {
                    const s = n.statements[i];
                    if (isLocalVariableDeclaration(s)) {
                        for (const v of s.variables) yield { name: v.name, node: v };
                    }
                }
            } else if (isForStatement(n) && n.init) {
                for (const v of n.init.variables) yield { name: v.name, node: v };
            } else if (isComponentType(n)) {
                yield* this.componentNames(n);
                return;
            }
        }
    }

    private *componentNames(c: ComponentType): Generator<{ name: string; node: AstNode }> {
        for (const p of c.params) yield { name: p.name, node: p };
        for (const e of elementsOf(c)) {
            if (e.$type === 'FieldDeclaration') for (const f of e.fields) yield { name: f.name, node: f };
        }
        for (const p of allPorts(c)) yield { name: p.name, node: p.port };
        for (const f of allFeatures(c)) yield { name: f.name, node: f };
        for (const s of subcomponentsOf(c)) yield { name: s.name, node: s };
        for (const t of c.typeParams) yield { name: t.name, node: t };
    }

    /** A scope over a table of named nodes: lookups by name. */
    private table(get: () => ReadonlyMap<string, AstNode>): Scope {
        const find = (name: string): AstNodeDescription | undefined => {
            const n = get().get(name);
            return n ? this.descriptions.createDescription(n, name) : undefined;
        };
        const all = (): AstNodeDescription[] => [...get()].map(([name, n]) => this.descriptions.createDescription(n, name));
        return new LookupScope(find, all);
    }

    /** A scope over named nodes computed on demand (public for contributed scopes). */
    nodes(get: () => Iterable<AstNode & { name?: string }>): Scope {
        const find = (name: string): AstNodeDescription | undefined => {
            for (const n of get()) if (n.name === name) return this.descriptions.createDescription(n, name);
            return undefined;
        };
        const all = (): AstNodeDescription[] =>
            [...get()].filter((n) => n.name).map((n) => this.descriptions.createDescription(n, n.name!));
        return new LookupScope(find, all);
    }
}

const EMPTY_TABLE: ReadonlyMap<string, AstNode> = new Map();

/** The last declaration before the statement at `upTo` (the one that shadows earlier ones). */
function nearestBefore(declarations: ReadonlyArray<{ index: number; node: AstNode }> | undefined, upTo: number): AstNode | undefined {
    for (let i = (declarations?.length ?? 0) - 1; i >= 0; i--) {
        const d = declarations![i]!;
        if (d.index < upTo) return d.node;
    }
    return undefined;
}

/** A scope preferring, among candidates of one name, the one in the variation branch of `at` (variant-context.ts: sameBranchFirst). */
function sameBranchScope(at: AstNode, scope: Scope): Scope {
    const inBranch = (n: AstNode | undefined): boolean =>
        AstUtils.getContainerOfType(n, (x): x is AstNode => x.$type === 'VarBody') !== undefined;
    const find = (name: string): AstNodeDescription | undefined => {
        const first = scope.getElement(name);
        if (!inBranch(at) && !inBranch(first?.node)) return first; // no variation point involved: as before
        const candidates = scope
            .getAllElements()
            .filter((d) => d.name === name)
            .toArray();
        if (candidates.length <= 1) return candidates[0] ?? scope.getElement(name);
        const nodes = candidates.flatMap((d) => (d.node ? [d.node] : []));
        const best = sameBranchFirst(at, nodes)[0];
        return candidates.find((d) => d.node === best) ?? candidates[0];
    };
    return new LookupScope(find, () => scope.getAllElements().toArray());
}
