/**
 * What a component type is, read from the symbols: its interface, subcomponents and behavior kind
 * (through generator-core's architecture view, as the generators see it) and, for an automaton,
 * its declared states and transitions with where they are in the model.
 */
import type { AstNode } from 'langium';
import { buildArchitecture, type ComponentView } from '@maa/generator-core';
import type { ast as adl } from '@maa/language-adl';
import { allStates, allTransitions, type ast as automata, sourceOf, statePath, targetOf } from '@maa/language-automata';
import type { BehaviorKind } from '@maa/protocol/grading';

/** The view of one component type (its own ports, inherited ones included; subcomponents; behavior). */
export function componentView(component: adl.ComponentType): ComponentView {
    return buildArchitecture(component).root;
}

/** The behavior kind a structure requirement names: what the component's behavior is written in. */
export function behaviorKind(view: ComponentView): BehaviorKind {
    if (view.handwritten) return 'handwritten';
    if (!view.atomic || view.modes) return 'composed';
    const language = view.behavior?.language;
    if (language === 'automaton' || language === 'robotarm' || language === 'compute') return language;
    return 'none';
}

export interface DeclaredState {
    /** The state's path from the top level, dotted (`Outer.Inner`), as the run-time reports it. */
    readonly path: string;
    readonly node: AstNode;
}

export interface DeclaredTransition {
    /** Paths of the source and target states. */
    readonly source: string;
    readonly target: string;
    readonly node: AstNode;
}

export interface AutomatonFacts {
    readonly states: readonly DeclaredState[];
    /** Every transition, self-loops (and internal transitions) included. */
    readonly transitions: readonly DeclaredTransition[];
}

const pathOf = (s: automata.State): string =>
    statePath(s)
        .map((x) => x.name)
        .join('.');

/** The states and transitions of an automaton component (undefined when its behavior is no automaton). */
export function automatonFacts(view: ComponentView): AutomatonFacts | undefined {
    if (view.behavior?.language !== 'automaton' || view.behavior.node.$type !== 'Automaton') return undefined;
    const automaton = view.behavior.node as automata.Automaton;
    const states = allStates(automaton).map((s) => ({ path: pathOf(s), node: s as AstNode }));
    const transitions: DeclaredTransition[] = [];
    for (const t of allTransitions(automaton)) {
        const source = sourceOf(t);
        const target = targetOf(t);
        if (source && target) transitions.push({ source: pathOf(source), target: pathOf(target), node: t });
    }
    return { states, transitions };
}
