import {
    AstUtils, EMPTY_SCOPE, type AstNode, type AstNodeDescription, type AstNodeDescriptionProvider,
    type ReferenceInfo, type Scope, type ScopeProvider
} from 'langium';
import type { ComponentType, NameExpression } from '../generated/ast.js';
import {
    isAssignmentExpression, isBlock, isComponentType, isSwitchGroup, isForStatement, isLocalVariableDeclaration,
    isParentComponent, isPortAccess, isStatement, isSubcomponent
} from '../generated/ast.js';
import { allPorts, subcomponentType, subcomponentsOf, elementsOf } from '../components/component-model.js';
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

    constructor(
        private readonly resolver: NameResolver,
        private readonly descriptions: AstNodeDescriptionProvider
    ) {}

    getScope(context: ReferenceInfo): Scope {
        const c = context.container;
        const key = `${c.$type}.${context.property}`;
        const contributed = this.contributions.get(key);
        if (contributed) return contributed(context);
        switch (key) {
            case 'ReferenceType.ref':
                return new LookupScope((n) => this.resolver.resolveType(c, n), () => this.resolver.visible(c, 'type'));
            case 'ComponentTypeRef.ref':
                return new LookupScope((n) => this.resolver.resolveComponent(c, n), () => this.resolver.visible(c, 'component'));
            case 'PortAccess.subcomponent':
                return this.nodes(() => {
                    const comp = AstUtils.getContainerOfType(c, isComponentType);
                    return comp ? subcomponentsOf(comp) : [];
                });
            case 'PortAccess.port':
                return this.nodes(() => {
                    if (!isPortAccess(c)) return [];
                    if (c.subcomponent) {
                        const sub = c.subcomponent.ref;
                        const decl = sub && subcomponentType(sub).decl;
                        return decl ? allPorts(decl).map((p) => p.port) : [];
                    }
                    const comp = AstUtils.getContainerOfType(c, isComponentType);
                    return comp ? allPorts(comp).map((p) => p.port) : [];
                });
            case 'NameExpression.ref':
                return this.expressionScope(c as NameExpression);
            case 'CDAssociationEnd.type':
                return new LookupScope((n) => this.resolver.resolveType(c, n), () => this.resolver.visible(c, 'type'));
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
            return this.nodes(() => keyTarget?.params ?? []);
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

    private localName(expr: AstNode, name: string): AstNode | undefined {
        for (const entry of this.localNames(expr)) {
            if (entry.name === name) return entry.node;
        }
        return undefined;
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
        for (const s of subcomponentsOf(c)) yield { name: s.name, node: s };
        for (const t of c.typeParams) yield { name: t.name, node: t };
    }

    /** A scope over named nodes computed on demand (public for contributed scopes). */
    nodes(get: () => Iterable<AstNode & { name?: string }>): Scope {
        const find = (name: string): AstNodeDescription | undefined => {
            for (const n of get()) if (n.name === name) return this.descriptions.createDescription(n, name);
            return undefined;
        };
        const all = (): AstNodeDescription[] => [...get()].filter((n) => n.name).map((n) => this.descriptions.createDescription(n, n.name!));
        return new LookupScope(find, all);
    }
}
