import type { AstNode } from 'langium';
import { type ast as adl, behaviorsOf } from '@maa/language-adl';
import { allTransitions, sourceOf, statePathName, substates, targetOf, transitionLabel, type ast } from '@maa/language-automata';
import { componentQualifiedName } from '@maa/generator-core';
import type { BuildContext } from './context.js';
import { labelId, stateId, transitionId } from './ids.js';
import { TYPES, type MaaGraph, type MaaLabel, type StateNode, type TransitionEdge } from './model.js';
import { addModeAutomaton } from './mode-diagram.js';
import { labelSize, shortenTransitionLabel } from './sizes.js';

type State = ast.State;

/**
 * The automaton view of a component: its states (substates nested in their state), the initial
 * ones marked, and its transitions with `trigger [guard] / action` labels. An internal
 * transition is a loop on its state. A decomposed component shows its mode automaton
 * (mode-diagram.ts). Empty when the component has neither.
 */
export function buildAutomatonDiagram(component: adl.ComponentType, ctx: BuildContext): MaaGraph {
    const qualifiedName = componentQualifiedName(component);
    const graph: MaaGraph = { type: TYPES.graph, id: ctx.id(`automaton:${qualifiedName}`), component: qualifiedName, children: [] };
    const automaton = behaviorsOf(component)
        .map((b) => b.behavior as AstNode | undefined)
        .find((b): b is ast.Automaton => b?.$type === 'Automaton');
    if (!automaton) {
        addModeAutomaton(component, graph, ctx); // a decomposed component's mode automaton, if any
        return graph;
    }

    const nodes = new Map<State, StateNode>();
    const addStates = (level: ast.Automaton | State, into: StateNode[]): void => {
        for (const s of substates(level)) {
            const path = statePathName(s);
            const id = ctx.id(stateId(path), s);
            const node: StateNode = {
                type: TYPES.state,
                id,
                name: s.name,
                initial: s.initial,
                statePath: path,
                children: [label(TYPES.stateLabel, labelId(id, 'name'), s.name, s)],
            };
            const severity = ctx.severity(s);
            if (severity) node.severity = severity;
            ctx.trace(node, s);
            nodes.set(s, node);
            into.push(node);
            const inner: StateNode[] = [];
            addStates(s, inner);
            node.children!.push(...inner);
        }
    };
    const top: StateNode[] = [];
    addStates(automaton, top);
    graph.children.push(...top);

    const pairs = new Map<string, number>();
    // `index`: the position in allTransitions order, counted over every transition (a run's transition events name it).
    for (const [index, t] of allTransitions(automaton).entries()) {
        const source = sourceOf(t);
        const target = targetOf(t);
        const from = source && nodes.get(source);
        const to = target && nodes.get(target);
        if (!from || !to) continue;
        const base = transitionId(from.statePath, to.statePath);
        const n = pairs.get(base) ?? 0;
        pairs.set(base, n + 1);
        const text = transitionLabel(t);
        const id = ctx.id(n === 0 ? base : `${base}#${n}`, t);
        const edge: TransitionEdge = {
            type: TYPES.transition,
            id,
            sourceId: from.id,
            targetId: to.id,
            label: text,
            transitionIndex: index,
            children: [],
        };
        if (text) {
            // A long label is shortened (its full text is the edge's `label` and the label's `fullText`).
            const l = label(TYPES.transitionLabel, labelId(id, 'label'), shortenTransitionLabel(text), t);
            if (l.text !== text) l.fullText = text;
            edge.children!.push(l);
        }
        ctx.trace(edge, t);
        const container = edgeContainer(source!, target!);
        (container ? nodes.get(container)!.children! : graph.children).push(edge);
    }
    return graph;

    function label(type: string, id: string, text: string, source: AstNode): MaaLabel {
        const l: MaaLabel = { type, id: ctx.id(id), text, size: labelSize(type, text) };
        ctx.trace(l, source);
        return l;
    }
}

/**
 * Where an edge between two states belongs: ELK's choice of an edge's container (the node its
 * coordinates are relative to), which Sprotty must match (routing points are relative to the
 * edge's parent): the common parent of siblings and of a loop, the state itself for an edge to
 * or from its own substate, else the deepest common ancestor. `undefined` is the graph.
 */
function edgeContainer(from: State, to: State): State | undefined {
    const parent = (s: State): State | undefined => (s.$container.$type === 'State' ? (s.$container as State) : undefined);
    if (parent(from) === parent(to)) return parent(from);
    if (parent(to) === from) return from;
    if (parent(from) === to) return to;
    const above = new Set<State>();
    for (let s = parent(from); s; s = parent(s)) above.add(s);
    for (let s = parent(to); s; s = parent(s)) if (above.has(s)) return s;
    return undefined;
}
