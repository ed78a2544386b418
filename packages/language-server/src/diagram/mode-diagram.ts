import type { AstNode } from 'langium';
import type { ast as adl } from '@maa/language-adl';
import { modeAutomatonView } from '@maa/generator-core';
import type { BuildContext } from './context.js';
import { labelId, stateId, transitionId } from './ids.js';
import { TYPES, type MaaGraph, type MaaLabel, type StateNode, type TransitionEdge } from './model.js';
import { labelSize, shortenTransitionLabel } from './sizes.js';

/**
 * The automaton view of a decomposed component's mode automaton: its modes as states (the
 * initial one marked, `statePath` the mode's name, so the IDE highlights the current mode of a
 * run like an automaton's state) and its mode transitions with `trigger [guard]` labels.
 * Fills `graph`; false when the component has no mode automaton.
 */
export function addModeAutomaton(component: adl.ComponentType, graph: MaaGraph, ctx: BuildContext): boolean {
    const view = modeAutomatonView(component);
    if (!view) return false;
    const nodes = new Map<string, StateNode>();
    for (const m of view.modes) {
        if (nodes.has(m.name)) continue; // a duplicate mode (automaton/duplicate-state): shown once
        const id = ctx.id(stateId(m.name), m.node);
        const node: StateNode = {
            type: TYPES.state,
            id,
            name: m.name,
            initial: m.initial,
            statePath: m.name,
            children: [label(TYPES.stateLabel, labelId(id, 'name'), m.name, m.node)],
        };
        const severity = ctx.severity(m.node);
        if (severity) node.severity = severity;
        ctx.trace(node, m.node);
        nodes.set(m.name, node);
        graph.children.push(node);
    }
    const pairs = new Map<string, number>();
    for (const [index, t] of view.transitions.entries()) {
        const from = nodes.get(t.source);
        const to = nodes.get(t.target);
        if (!from || !to) continue;
        const base = transitionId(t.source, t.target);
        const n = pairs.get(base) ?? 0;
        pairs.set(base, n + 1);
        const text = modeTransitionLabel(t.trigger, t.guard);
        const id = ctx.id(n === 0 ? base : `${base}#${n}`, t.node);
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
            const l = label(TYPES.transitionLabel, labelId(id, 'label'), shortenTransitionLabel(text), t.node);
            if (l.text !== text) l.fullText = text;
            edge.children!.push(l);
        }
        ctx.trace(edge, t.node);
        graph.children.push(edge);
    }
    return true;

    function label(type: string, id: string, text: string, source: AstNode): MaaLabel {
        const l: MaaLabel = { type, id: ctx.id(id), text, size: labelSize(type, text) };
        ctx.trace(l, source);
        return l;
    }
}

/** `trigger [guard]` as written, whitespace collapsed (`Tick`, a port's name, or nothing). */
function modeTransitionLabel(trigger: { kind: string; port?: string }, guard: AstNode | undefined): string {
    const parts: string[] = [];
    if (trigger.kind === 'tick') parts.push('Tick');
    else if (trigger.kind === 'port' && trigger.port) parts.push(trigger.port);
    const text = (guard?.$cstNode?.text ?? '').replace(/\s+/g, ' ').trim();
    if (text) parts.push(`[${text}]`);
    return parts.join(' ');
}
