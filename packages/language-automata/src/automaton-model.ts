import { AstUtils, CstUtils, type AstNode, type CstNode } from 'langium';
import { DEFAULT_TIMING, TIMINGS, type Timing } from '@maa/language-adl';
import type { Automaton, InternalTransition, Port, State, StateAction, Transition } from './generated/ast.js';
import { isAutomaton, isBehaviorDeclaration, isPort, isState } from './generated/ast.js';
import { portHeader } from '@maa/language-adl';

/**
 * Derived facts about automata that the checks, the scopes and the behavior generators share.
 * Pure functions over the AST; they only read `$type`, so they work on the AST of any language
 * family build that composes this grammar.
 */

/** A regular or an internal transition. */
export type AnyTransition = Transition | InternalTransition;

/** What makes a transition fire. A transition without event is triggered by the tick (timed). */
export type Trigger =
    | { readonly kind: 'none' }
    | { readonly kind: 'tick' }
    | { readonly kind: 'port'; readonly port: Port | undefined; readonly name: string };

export function isAnyTransition(node: unknown): node is AnyTransition {
    const t = (node as AstNode | undefined)?.$type;
    return t === 'Transition' || t === 'InternalTransition';
}

/**
 * The timing of an automaton: the timing stereotype of its behavior declaration
 * (`<<sync>> automaton { }`), else `timed` (MontiArc's event-driven automata).
 */
export function automatonTiming(a: Automaton): Timing {
    const decl = a.$container;
    const names = isBehaviorDeclaration(decl) ? (decl.stereotype?.values.map((v) => v.name) ?? []) : [];
    return names.find((n): n is Timing => (TIMINGS as readonly string[]).includes(n)) ?? DEFAULT_TIMING;
}

/** The automaton a node belongs to. */
export function enclosingAutomaton(node: AstNode): Automaton | undefined {
    return AstUtils.getContainerOfType(node, isAutomaton);
}

/** The direct substates of a state, or the top-level states of an automaton (declaration order). */
export function substates(level: Automaton | State): State[] {
    return (level.elements as AstNode[]).filter(isState);
}

/** Every state of an automaton, in declaration order (pre-order: a state before its substates). */
export function allStates(a: Automaton): State[] {
    const out: State[] = [];
    const visit = (level: Automaton | State): void => {
        for (const s of substates(level)) {
            out.push(s);
            visit(s);
        }
    };
    visit(a);
    return out;
}

/** Whether a state is hierarchical (has substates). */
export function isHierarchical(s: State): boolean {
    return substates(s).length > 0;
}

/** The states declared `initial` at one level. */
export function initialStates(level: Automaton | State): State[] {
    return substates(level).filter((s) => s.initial);
}

/**
 * The state a level starts in: its (first) initial state; a hierarchical state without one is
 * entered in its first substate, as MontiArc's simulator does.
 */
export function startState(level: Automaton | State): State | undefined {
    return initialStates(level)[0] ?? (isState(level) ? substates(level)[0] : undefined);
}

/** The chain of states from the top level down to `s` (both included). */
export function statePath(s: State): State[] {
    const path: State[] = [];
    for (let n: AstNode | undefined = s; n && isState(n); n = n.$container) path.unshift(n);
    return path;
}

/** A state's dotted path from its top state (`Outer.Inner`): how `/maa/automaton_states` and the diagrams name it. */
export function statePathName(s: State): string {
    return statePath(s)
        .map((p) => p.name)
        .join('.');
}

/** `trigger [guard] / action` as written, whitespace collapsed: the diagram's label and the automata table's. */
export function transitionLabel(t: AnyTransition): string {
    const text = (n: AstNode | undefined): string => (n?.$cstNode?.text ?? '').replace(/\s+/g, ' ').trim();
    const parts: string[] = [];
    if (t.tick) parts.push('Tick');
    else if (t.event) parts.push(t.event.$refText);
    if (t.guard) parts.push(`[${text(t.guard)}]`);
    if (t.action) parts.push(`/ ${text(t.action)}`);
    return parts.join(' ');
}

/** Every transition of an automaton, regular and internal, in declaration order. */
export function allTransitions(a: Automaton): AnyTransition[] {
    return AstUtils.streamAllContents(a).filter(isAnyTransition).toArray();
}

/** The source state of a transition: the referenced state, or the enclosing state of an internal one. */
export function sourceOf(t: AnyTransition): State | undefined {
    return t.$type === 'InternalTransition' ? t.$container : t.source?.ref; // no source: partially parsed
}

/** The target state of a transition (an internal transition stays in its state). */
export function targetOf(t: AnyTransition): State | undefined {
    return t.$type === 'InternalTransition' ? t.$container : t.target?.ref;
}

export function triggerOf(t: AnyTransition): Trigger {
    if (t.tick) return { kind: 'tick' };
    if (t.event) return { kind: 'port', port: t.event.ref, name: t.event.$refText };
    return { kind: 'none' };
}

/** The `entry`/`exit`/`do` actions of a state, in declaration order. */
export function stateActions(s: State, kind: StateAction['kind']): StateAction[] {
    return (s.elements as AstNode[]).filter((e): e is StateAction => e.$type === 'StateAction' && (e as StateAction).kind === kind);
}

/** The direction of a port (`in`/`out`); ports in a comma list take it from the port before. */
export function portDirection(p: Port): 'in' | 'out' | undefined {
    return portHeader(p as Parameters<typeof portHeader>[0]).direction;
}

export function isIncomingPort(node: unknown): node is Port {
    return isPort(node) && portDirection(node) === 'in';
}

/** A short human-readable name of a transition, e.g. `S -> T` or `-> (internal in S)`. */
export function describeTransition(t: AnyTransition): string {
    if (t.$type === 'InternalTransition') return `internal transition of state '${t.$container.name}'`;
    return `transition '${t.source?.$refText ?? '?'} -> ${t.target?.$refText ?? '?'}'`; // partially parsed: '?';
}

/**
 * The CST of a transition's head: from its first token up to its trigger (source, `->`, target,
 * guard, event), without the action; the place to report problems of the whole transition.
 */
export function transitionHead(t: AnyTransition): { start: CstNode; end: CstNode } | undefined {
    const cst = t.$cstNode;
    if (!cst) return undefined;
    let first: CstNode | undefined;
    let last: CstNode | undefined;
    for (const leaf of CstUtils.flattenCst(cst)) {
        if (leaf.hidden) continue;
        if (leaf.astNode === t && (leaf.text === '/' || leaf.text === ';')) break;
        first ??= leaf;
        last = leaf;
    }
    return first && last ? { start: first, end: last } : undefined;
}
