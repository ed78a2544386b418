import { cdPackageOf } from '@maa/language-cd';
import type { AutoConnect, CDType, ComponentType, Connector, PortAccess, Subcomponent } from '../generated/ast.js';
import { allPorts, elementsOf, findPort, subcomponentType, subcomponentsOf, type PortInfo } from './component-model.js';
import { UNBOX_OF } from '../types/builtin-library.js';
import type { SymType } from '../types/sym-type.js';

/**
 * MontiArc's `autoconnect` (a comfort construct of decomposed components): the connectors it
 * implies. Pure functions over the AST, so the checks, the generators and the diagram see the
 * same connectors.
 *
 * - `autoconnect port;` connects every port that no written connector feeds (an outgoing port
 *   of the component, an incoming port of a subcomponent) from the one possible source port of
 *   the same name and the same type: an incoming port of the component or an outgoing port of
 *   another subcomponent.
 * - `autoconnect type;` does the same with every possible source of the same type, whatever its
 *   name.
 * - `autoconnect off;` (and no `autoconnect`) implies nothing.
 *
 * A target with no or several candidate sources stays unconnected (and the connectedness checks
 * report it as before). "The same type" is type identity, where a primitive and its box count as
 * one type (`int` and `Integer`); no widening or subtyping, so an implied connector never needs
 * a conversion.
 */

export type AutoConnectKind = 'port' | 'type' | 'off';

export interface ImpliedEnd {
    /** The subcomponent the port belongs to; undefined for a port of the component itself. */
    readonly sub?: Subcomponent;
    readonly info: PortInfo;
}

export interface ImpliedConnector {
    readonly source: ImpliedEnd;
    readonly target: ImpliedEnd;
    /** The `autoconnect` declaration that implies the connector. */
    readonly declaration: AutoConnect;
}

/** The `autoconnect` declarations of a component (more than one is an error; the first counts). */
export function autoConnectsOf(c: ComponentType): AutoConnect[] {
    return elementsOf(c).filter((e): e is AutoConnect => e.$type === 'AutoConnect');
}

/** The effective autoconnect mode of a component. */
export function autoConnectKind(c: ComponentType): AutoConnectKind {
    return autoConnectsOf(c)[0]?.kind ?? 'off';
}

function endKey(sub: string | undefined, port: string): string {
    return `${sub ?? ''}.${port}`;
}

/** Keys (`sub.port`, `.port` for the component's own) of the ports that written connectors feed. */
function explicitTargets(c: ComponentType): Set<string> {
    const result = new Set<string>();
    for (const e of elementsOf(c)) {
        if (e.$type !== 'Connector') continue;
        for (const t of (e as Connector).targets) result.add(accessKey(t));
    }
    return result;
}

function accessKey(a: PortAccess): string {
    return endKey(a.subcomponent?.$refText, a.port?.$refText ?? '');
}

/** The connectors that a component's `autoconnect` implies, in a deterministic order. */
export function impliedConnectors(c: ComponentType): ImpliedConnector[] {
    const declaration = autoConnectsOf(c)[0];
    if (!declaration || declaration.kind === 'off') return [];
    const subs = subcomponentsOf(c);
    if (subs.length === 0) return [];
    const sources: ImpliedEnd[] = [];
    const targets: ImpliedEnd[] = [];
    for (const p of allPorts(c)) (p.direction === 'in' ? sources : targets).push({ info: p });
    for (const sub of subs) {
        const { decl, subst } = subcomponentType(sub);
        if (!decl) continue;
        for (const p of allPorts(decl, subst)) (p.direction === 'out' ? sources : targets).push({ sub, info: p });
    }
    const fed = explicitTargets(c);
    const result: ImpliedConnector[] = [];
    for (const target of targets) {
        if (fed.has(endKey(target.sub?.name, target.info.name))) continue;
        const candidates = sources.filter(
            (s) =>
                (s.sub === undefined || s.sub !== target.sub) &&
                (declaration.kind === 'type' || s.info.name === target.info.name) &&
                sameType(s.info.type, target.info.type),
        );
        if (candidates.length === 1) result.push({ source: candidates[0]!, target, declaration });
    }
    return result;
}

/** The port an end of an implied connector names, looked up again (for callers that hold names). */
export function impliedEndPort(c: ComponentType, end: ImpliedEnd): PortInfo | undefined {
    if (!end.sub) return findPort(c, end.info.name);
    const { decl, subst } = subcomponentType(end.sub);
    return decl && findPort(decl, end.info.name, subst);
}

/** Type identity, with a primitive and its box as one type. Erroneous types are never the same. */
export function sameType(a: SymType, b: SymType): boolean {
    const pa = primitiveName(a);
    const pb = primitiveName(b);
    if (pa !== undefined || pb !== undefined) return pa === pb;
    if (a.kind !== b.kind) return false;
    switch (a.kind) {
        case 'object': {
            const o = b as typeof a;
            return a.decl === o.decl && a.args.length === o.args.length && a.args.every((x, i) => sameType(x, o.args[i]!));
        }
        case 'typevar':
            return a.decl === (b as typeof a).decl;
        case 'array':
            return sameType(a.component, (b as typeof a).component);
        default:
            return false;
    }
}

function primitiveName(t: SymType): string | undefined {
    if (t.kind === 'primitive') return t.name;
    if (t.kind === 'object' && t.args.length === 0) {
        const prim = UNBOX_OF.get(t.decl.name);
        if (prim && isJavaLang(t.decl)) return prim;
    }
    return undefined;
}

function isJavaLang(decl: CDType): boolean {
    return cdPackageOf(decl) === 'java.lang';
}
