import { AstUtils, type AstNode } from 'langium';
import type { BehaviorDeclaration, ComponentType, ComponentTypeRef, MCType, Port, Stereotype, Subcomponent } from '../generated/ast.js';
import { isComponentType } from '../generated/ast.js';
import { bind, typeOfMCType } from '../types/type-resolver.js';
import { configuredElements } from './variant-context.js';
import { EMPTY_SUBSTITUTION, substitute, type Substitution, type SymType } from '../types/sym-type.js';

/**
 * Derived facts about components that several checks, the generators and the diagram need:
 * effective ports (own and inherited, with substituted types and timing), subcomponents,
 * behaviors. Pure functions over the AST.
 */

export type Timing = 'untimed' | 'timed' | 'sync';
export const TIMINGS: readonly Timing[] = ['untimed', 'timed', 'sync'];
/** The timing of a port that declares none and whose component's behavior declares none. */
export const DEFAULT_TIMING: Timing = 'timed';

export interface PortInfo {
    readonly port: Port;
    readonly name: string;
    readonly direction: 'in' | 'out';
    readonly type: SymType;
    readonly timing: Timing;
    /** Whether the timing was written on the port (rather than inherited from behavior or default). */
    readonly explicitTiming: boolean;
    readonly delayed: boolean;
    /** The component type that declares the port (differs from the asked one for inherited ports). */
    readonly owner: ComponentType;
}

/**
 * The elements of a component body (empty while the body is still being typed); the elements
 * of variation points (`varif`) as the current configuration selects them (variant-context.ts).
 */
export function elementsOf(c: ComponentType): ComponentType['body']['elements'] {
    return configuredElements(c.body);
}

export function stereotypeNames(...stereotypes: Array<Stereotype | undefined>): string[] {
    return stereotypes.flatMap((s) => s?.values.map((v) => v.name) ?? []);
}

export function timingsOf(...stereotypes: Array<Stereotype | undefined>): Timing[] {
    return stereotypeNames(...stereotypes).filter((n): n is Timing => (TIMINGS as readonly string[]).includes(n));
}

export function behaviorsOf(c: ComponentType): BehaviorDeclaration[] {
    return elementsOf(c).filter((e): e is BehaviorDeclaration => e.$type === 'BehaviorDeclaration');
}

/** The timing a component's behavior declares (`<<sync>> automaton { }`), if any. */
export function behaviorTiming(c: ComponentType): Timing | undefined {
    for (const b of behaviorsOf(c)) {
        const t = timingsOf(b.stereotype)[0];
        if (t) return t;
    }
    return undefined;
}

/**
 * Direction, type and stereotypes of a port: in `port in int a, b, out int c;` the port `b`
 * has none of its own and takes those of `a`.
 */
export function portHeader(port: Port): {
    direction: 'in' | 'out';
    type: MCType | undefined;
    stereotype?: Stereotype;
    declaration?: Stereotype;
} {
    const decl = port.$container;
    const ports = decl?.ports ?? [port];
    for (let i = Math.max(ports.indexOf(port), 0); i >= 0; i--) {
        const p = ports[i]!;
        if (p.direction) return { direction: p.direction, type: p.type, stereotype: p.stereotype, declaration: decl?.stereotype };
    }
    return { direction: 'in', type: undefined, declaration: decl?.stereotype };
}

export function ownPorts(c: ComponentType, s: Substitution = EMPTY_SUBSTITUTION): PortInfo[] {
    const result: PortInfo[] = [];
    const fromBehavior = behaviorTiming(c);
    for (const e of elementsOf(c)) {
        if (e.$type !== 'PortDeclaration') continue;
        for (const p of e.ports) {
            const h = portHeader(p);
            const declared = timingsOf(h.stereotype, h.declaration)[0];
            result.push({
                port: p,
                name: p.name,
                direction: h.direction,
                type: typeOfMCType(h.type, s),
                timing: declared ?? fromBehavior ?? DEFAULT_TIMING,
                explicitTiming: declared !== undefined,
                delayed: stereotypeNames(h.stereotype, h.declaration).includes('delayed'),
                owner: c,
            });
        }
    }
    return result;
}

/** Resolved parent component types with the substitution their type arguments define. */
export function parentsOf(
    c: ComponentType,
    s: Substitution = EMPTY_SUBSTITUTION,
): Array<{ decl: ComponentType; subst: Substitution; ref: ComponentTypeRef }> {
    const result: Array<{ decl: ComponentType; subst: Substitution; ref: ComponentTypeRef }> = [];
    for (const p of c.parents) {
        const decl = p.type?.ref?.ref;
        if (!decl) continue;
        result.push({ decl, subst: substitutionFor(p.type, s), ref: p.type });
    }
    return result;
}

/** The substitution that instantiating a component type through `ref` defines. */
export function substitutionFor(ref: ComponentTypeRef, outer: Substitution = EMPTY_SUBSTITUTION): Substitution {
    const decl = ref?.ref?.ref;
    if (!decl) return EMPTY_SUBSTITUTION;
    return bind(
        decl.typeParams,
        ref.typeArgs.map((a) => typeOfMCType(a, outer)),
    );
}

/** Own and inherited ports; an own port hides an inherited port of the same name. */
export function allPorts(c: ComponentType, s: Substitution = EMPTY_SUBSTITUTION, seen = new Set<ComponentType>()): PortInfo[] {
    if (seen.has(c)) return [];
    seen.add(c);
    const own = ownPorts(c, s);
    const names = new Set(own.map((p) => p.name));
    const inherited: PortInfo[] = [];
    for (const parent of parentsOf(c, s)) {
        for (const p of allPorts(parent.decl, composeSubst(parent.subst, s), seen)) {
            if (!names.has(p.name)) {
                names.add(p.name);
                inherited.push(p);
            }
        }
    }
    return [...own, ...inherited];
}

function composeSubst(inner: Substitution, outer: Substitution): Substitution {
    if (outer.size === 0) return inner;
    const m = new Map(inner);
    for (const [k, v] of inner) m.set(k, substitute(v, outer));
    return m;
}

export function findPort(c: ComponentType, name: string, s: Substitution = EMPTY_SUBSTITUTION): PortInfo | undefined {
    return allPorts(c, s).find((p) => p.name === name);
}

/** Subcomponents declared in a component: instantiations and in-place instances of inner types. */
export function subcomponentsOf(c: ComponentType): Subcomponent[] {
    const result: Subcomponent[] = [];
    for (const e of elementsOf(c)) {
        if (e.$type === 'ComponentInstantiation') result.push(...e.instances);
        else if (e.$type === 'ComponentType') result.push(...e.instances);
    }
    return result;
}

export function isComposed(c: ComponentType): boolean {
    return subcomponentsOf(c).length > 0;
}

/** The component type a subcomponent instantiates and the substitution of its type arguments. */
export function subcomponentType(sub: Subcomponent): { decl: ComponentType | undefined; subst: Substitution; ref?: ComponentTypeRef } {
    const container = sub.$container;
    if (container.$type === 'ComponentType') return { decl: container, subst: EMPTY_SUBSTITUTION };
    return { decl: container.type?.ref?.ref, subst: substitutionFor(container.type), ref: container.type };
}

/** The component type that (directly) contains a node. */
export function enclosingComponent(node: AstNode): ComponentType | undefined {
    return AstUtils.getContainerOfType(node, isComponentType);
}

export function innerComponentTypes(c: ComponentType): ComponentType[] {
    return elementsOf(c).filter(isComponentType);
}
