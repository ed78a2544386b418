import type { AstNode, ValidationAcceptor, ValidationChecks } from 'langium';
import type { AdlAstType, AutoConnect, ComponentType, Connector, PortAccess, Subcomponent } from '../../generated/ast.js';
import type { AdlServices } from '../../adl-module.js';
import {
    behaviorsOf,
    isComposed,
    subcomponentType,
    subcomponentsOf,
    type PortInfo,
    type Timing,
    elementsOf,
} from '../../components/component-model.js';
import { currentVariant, inSubcomponent } from '../../components/variant-context.js';
import type { TypeRelations } from '../../types/type-relations.js';
import { EMPTY_SUBSTITUTION, isErroneous, printType } from '../../types/sym-type.js';
import { Codes } from '../codes.js';
import { PortTables } from './port-tables.js';
import { ComponentFacts } from './port-cache.js';
import { impliedConnectors, type ImpliedConnector } from '../../components/autoconnect.js';

/**
 * The connectors declared in the modes of a component's mode automaton (language-automata's
 * `mode automaton { mode M { ... } }`), read by `$type` since the host's AST does not know modes.
 */
function modeConnectors(c: ComponentType): Connector[] {
    const out: Connector[] = [];
    for (const b of behaviorsOf(c)) {
        const automaton = b.behavior as (AstNode & { elements?: AstNode[] }) | undefined;
        if (automaton?.$type !== 'ModeAutomaton') continue;
        for (const m of automaton.elements ?? []) {
            if (m.$type !== 'Mode') continue;
            for (const e of (m as AstNode & { elements?: AstNode[] }).elements ?? []) if (e.$type === 'Connector') out.push(e as Connector);
        }
    }
    return out;
}

const STRENGTH: Readonly<Record<Timing, number>> = { untimed: 0, timed: 1, sync: 2 };

interface End {
    readonly access: PortAccess;
    readonly info: PortInfo;
    /** The subcomponent the port belongs to; undefined for the component's own ports. */
    readonly sub?: Subcomponent;
}

/** Context conditions on connectors: directions, types, timings, senders, connectedness, causality. */
export class ConnectorChecks {
    private readonly rel: TypeRelations;
    private readonly facts: ComponentFacts;

    constructor(services: AdlServices) {
        this.rel = services.maa.TypeRelations;
        this.facts = new ComponentFacts(services.shared);
    }

    readonly checks: ValidationChecks<AdlAstType> = {
        ComponentType: (c, accept) => {
            const connectors = elementsOf(c).filter((e): e is Connector => e.$type === 'Connector');
            const tables = new PortTables();
            const resolved = connectors.map((con) => ({
                con,
                source: this.end(c, con.source, tables),
                targets: con.targets.map((t) => this.end(c, t, tables)),
            }));
            for (const r of resolved) this.checkConnector(r.source, r.targets, accept);
            if (isComposed(c)) {
                // Connectors implied by `autoconnect` feed only ports no written connector feeds
                // and connect ports of one type, so they count for connectedness and causality.
                const implied = impliedConnectors(c);
                this.checkSenders(resolved, accept);
                // The connectors of modes (checked with their mode, language-automata) connect
                // ports too: a port connected in some mode is connected.
                const inModes = modeConnectors(c).map((con) => ({
                    con,
                    source: this.end(c, con.source, tables),
                    targets: con.targets.map((t) => this.end(c, t, tables)),
                }));
                this.checkConnectedness(c, [...resolved, ...inModes], implied, accept);
                this.checkCausality(c, resolved, implied, accept);
            }
        },
    };

    private end(c: ComponentType, access: PortAccess, tables: PortTables): End | undefined {
        const name = access.port?.$refText ?? ''; // no port: partially parsed
        if (access.subcomponent) {
            // In a configuration, the subcomponent of that name the configuration has (variation points may declare several).
            const sub = currentVariant()
                ? subcomponentsOf(c).find((x) => x.name === access.subcomponent?.$refText)
                : access.subcomponent.ref;
            if (!sub) return undefined;
            const { decl, subst } = subcomponentType(sub);
            const info = decl && tables.port(sub, name, () => this.facts.portsOfSub(sub, decl, subst));
            return info ? { access, info, sub } : undefined;
        }
        const info = tables.port(c, name, () => this.facts.portsOf(c));
        return info ? { access, info } : undefined;
    }

    private checkConnector(source: End | undefined, targets: Array<End | undefined>, accept: ValidationAcceptor): void {
        let sourceOk = true;
        if (source) {
            const ok = source.sub ? source.info.direction === 'out' : source.info.direction === 'in';
            if (!ok) {
                sourceOk = false;
                accept(
                    'error',
                    `Connector source '${text(source)}' must be an incoming port of the component or an outgoing port of a subcomponent, but it is ${source.sub ? 'an incoming port of subcomponent' : 'an outgoing port of component'} '${source.sub?.name ?? source.info.owner.name}'.`,
                    { node: source.access, code: Codes.SourceDirectionMismatch },
                );
            }
        }
        for (const target of targets) {
            if (!target) continue;
            const ok = target.sub ? target.info.direction === 'in' : target.info.direction === 'out';
            if (!ok) {
                accept(
                    'error',
                    `Connector target '${text(target)}' must be an outgoing port of the component or an incoming port of a subcomponent, but it is ${target.sub ? 'an outgoing port of subcomponent' : 'an incoming port of component'} '${target.sub?.name ?? target.info.owner.name}'.`,
                    { node: target.access, code: Codes.TargetDirectionMismatch },
                );
                continue;
            }
            if (!source || !sourceOk) continue;
            const st = source.info.type;
            const tt = target.info.type;
            if (!isErroneous(st) && !isErroneous(tt) && !this.rel.isAssignable(tt, st)) {
                accept(
                    'error',
                    `Connector '${text(source)} -> ${text(target)}' connects a port of type ${printType(st)} to a port of type ${printType(tt)}; ${printType(st)} is not assignable to ${printType(tt)}.`,
                    { node: target.access, code: Codes.ConnectorTypeMismatch },
                );
            }
            // An incoming port of a composed component without a declared timing takes the timing of the subcomponents it feeds.
            const inferred = !source.sub && !source.info.explicitTiming && target.sub !== undefined;
            if (!inferred && STRENGTH[source.info.timing] < STRENGTH[target.info.timing]) {
                accept(
                    'error',
                    `Connector '${text(source)} -> ${text(target)}' connects a ${source.info.timing} port to a ${target.info.timing} port; a ${target.info.timing} port needs a source that is at least as strongly timed.`,
                    { node: target.access, code: Codes.TimingMismatch },
                );
            }
        }
    }

    private checkSenders(resolved: Array<{ con: Connector; targets: Array<End | undefined> }>, accept: ValidationAcceptor): void {
        const seen = new Map<string, PortAccess>();
        for (const { targets } of resolved) {
            for (const t of targets) {
                if (!t) continue;
                const key = `${t.sub?.name ?? ''}.${t.info.name}`;
                const first = seen.get(key);
                if (first)
                    accept(
                        'error',
                        `Port '${text(t)}' receives messages from more than one connector; every port has at most one sender.`,
                        { node: t.access, code: Codes.MultipleSenders },
                    );
                else seen.set(key, t.access);
            }
        }
    }

    private checkConnectedness(
        c: ComponentType,
        resolved: Array<{ source?: End; targets: Array<End | undefined> }>,
        implied: readonly ImpliedConnector[],
        accept: ValidationAcceptor,
    ): void {
        const used = new Set<string>();
        for (const r of resolved) {
            for (const e of [r.source, ...r.targets]) if (e) used.add(`${e.sub?.name ?? ''}.${e.info.name}`);
        }
        for (const i of implied) {
            for (const e of [i.source, i.target]) used.add(`${e.sub?.name ?? ''}.${e.info.name}`);
        }
        for (const sub of subcomponentsOf(c)) {
            const { decl, subst } = subcomponentType(sub);
            if (!decl) continue;
            for (const p of this.facts.portsOfSub(sub, decl, subst)) {
                if (used.has(`${sub.name}.${p.name}`)) continue;
                if (p.direction === 'in') {
                    accept(
                        'error',
                        `Incoming port '${p.name}' of subcomponent '${sub.name}' is not connected; it would never receive a message.`,
                        { node: sub, property: 'name', code: Codes.UnconnectedSubInPort },
                    );
                } else {
                    accept('warning', `Outgoing port '${p.name}' of subcomponent '${sub.name}' is not connected; its messages are lost.`, {
                        node: sub,
                        property: 'name',
                        code: Codes.UnconnectedSubOutPort,
                    });
                }
            }
        }
        for (const p of this.facts.portsOf(c)) {
            if (used.has(`.${p.name}`)) continue;
            if (p.direction === 'in') {
                accept('warning', `Incoming port '${p.name}' of composed component '${c.name}' is not forwarded to any subcomponent.`, {
                    node: p.owner === c ? p.port : c,
                    property: 'name',
                    code: Codes.UnusedInPort,
                });
            } else {
                accept('warning', `Outgoing port '${p.name}' of composed component '${c.name}' has no sender.`, {
                    node: p.owner === c ? p.port : c,
                    property: 'name',
                    code: Codes.UnusedOutPort,
                });
            }
        }
    }

    /**
     * Feedback cycles must be strongly causal: every cycle through subcomponents passes a
     * delayed port (directly or inside a composed subcomponent), else its value in a time slice
     * would depend on itself.
     */
    private checkCausality(
        c: ComponentType,
        resolved: Array<{ con: Connector; source?: End; targets: Array<End | undefined> }>,
        implied: readonly ImpliedConnector[],
        accept: ValidationAcceptor,
    ): void {
        const edges = new Map<string, Array<{ to: string; con?: Connector | AutoConnect }>>();
        const add = (from: string, to: string, con?: Connector | AutoConnect): void => {
            const list = edges.get(from) ?? [];
            list.push({ to, con });
            edges.set(from, list);
        };
        for (const r of resolved) {
            if (!r.source?.sub) continue;
            for (const t of r.targets) if (t?.sub) add(`${r.source.sub.name}.${r.source.info.name}`, `${t.sub.name}.${t.info.name}`, r.con);
        }
        for (const i of implied) {
            if (i.source.sub && i.target.sub)
                add(`${i.source.sub.name}.${i.source.info.name}`, `${i.target.sub.name}.${i.target.info.name}`, i.declaration);
        }
        for (const sub of subcomponentsOf(c)) {
            const decl = subcomponentType(sub).decl;
            if (!decl) continue;
            if (!isComposed(decl)) {
                // Every input of an atomic component may pass to every undelayed output: one node
                // between them instead of all pairs (quadratic in its ports).
                const hub = `${sub.name}.#`;
                for (const p of this.facts.portsOfSub(sub, decl, EMPTY_SUBSTITUTION)) {
                    if (p.direction === 'in') add(`${sub.name}.${p.name}`, hub);
                    else if (!p.delayed) add(hub, `${sub.name}.${p.name}`);
                }
                continue;
            }
            for (const [i, o] of inSubcomponent(sub, () => this.instantaneousPaths(decl, new Set()).paths))
                add(`${sub.name}.${i}`, `${sub.name}.${o}`);
        }
        const state = new Map<string, 1 | 2>();
        const reported = new Set<Connector | AutoConnect>();
        // Depth-first search with an explicit stack (a chain of thousands of subcomponents would
        // overflow the call stack); each frame knows the last connector on the path to its node.
        const visit = (start: string): void => {
            const stack: Array<{ node: string; next: number; last?: Connector | AutoConnect }> = [{ node: start, next: 0 }];
            state.set(start, 1);
            while (stack.length > 0) {
                const frame = stack[stack.length - 1]!;
                const e = (edges.get(frame.node) ?? [])[frame.next++];
                if (!e) {
                    state.set(frame.node, 2);
                    stack.pop();
                    continue;
                }
                const last = e.con ?? frame.last;
                const s = state.get(e.to);
                if (s === 1) {
                    if (last && !reported.has(last)) {
                        reported.add(last);
                        accept(
                            'error',
                            `The feedback loop through port '${e.to}' has no delay: its value in a time slice would depend on itself. Make an outgoing port on the loop <<delayed>>.`,
                            { node: last, code: Codes.FeedbackNotCausal },
                        );
                    }
                } else if (s === undefined) {
                    state.set(e.to, 1);
                    stack.push({ node: e.to, next: 0, last });
                }
            }
        };
        for (const n of [...edges.keys()]) if (!state.has(n)) visit(n);
    }

    /**
     * Pairs (incoming, outgoing) of a component type's ports between which messages pass within
     * one time slice; `cut` tells whether the walk met a component type already on its way (a
     * cycle of component types, whose result depends on where the walk began). Results without
     * a cut are the same from everywhere and kept once per component type (ComponentFacts).
     */
    private instantaneousPaths(decl: ComponentType, seen: Set<ComponentType>): Paths {
        const cached = this.facts.cachedPaths(decl);
        if (cached) return { paths: cached, cut: false };
        const computed = this.computePaths(decl, seen);
        if (!computed.cut) this.facts.storePaths(decl, computed.paths);
        return computed;
    }

    private computePaths(decl: ComponentType, seen: Set<ComponentType>): Paths {
        const ports = this.facts.portsOf(decl);
        const ins = ports.filter((p) => p.direction === 'in');
        const outs = ports.filter((p) => p.direction === 'out');
        if (!isComposed(decl) || seen.has(decl)) {
            const paths = ins.flatMap((i) => outs.filter((o) => !o.delayed).map((o) => [i.name, o.name] as const));
            return { paths, cut: seen.has(decl) };
        }
        seen.add(decl);
        const edges = new Map<string, string[]>();
        const add = (a: string, b: string): void => {
            const targets = edges.get(a);
            if (targets) targets.push(b);
            else edges.set(a, [b]);
        };
        for (const con of elementsOf(decl)) {
            if (con.$type !== 'Connector') continue;
            const s = `${con.source.subcomponent?.$refText ?? ''}.${con.source.port?.$refText ?? ''}`;
            for (const t of con.targets) add(s, `${t.subcomponent?.$refText ?? ''}.${t.port?.$refText ?? ''}`);
        }
        for (const i of impliedConnectors(decl))
            add(`${i.source.sub?.name ?? ''}.${i.source.info.name}`, `${i.target.sub?.name ?? ''}.${i.target.info.name}`);
        let cut = false;
        for (const sub of subcomponentsOf(decl)) {
            const d = subcomponentType(sub).decl;
            if (!d) continue;
            const inner = inSubcomponent(sub, () => this.instantaneousPaths(d, seen));
            cut ||= inner.cut;
            for (const [i, o] of inner.paths) add(`${sub.name}.${i}`, `${sub.name}.${o}`);
        }
        const result: Array<readonly [string, string]> = [];
        for (const i of ins) {
            const reach = new Set<string>();
            const stack = [`.${i.name}`];
            while (stack.length > 0) {
                const n = stack.pop()!;
                for (const m of edges.get(n) ?? [])
                    if (!reach.has(m)) {
                        reach.add(m);
                        stack.push(m);
                    }
            }
            for (const o of outs) if (reach.has(`.${o.name}`) && !o.delayed) result.push([i.name, o.name]);
        }
        seen.delete(decl);
        return { paths: result, cut };
    }
}

interface Paths {
    readonly paths: ReadonlyArray<readonly [string, string]>;
    readonly cut: boolean;
}

function text(e: End): string {
    return e.sub ? `${e.sub.name}.${e.info.name}` : e.info.name;
}
