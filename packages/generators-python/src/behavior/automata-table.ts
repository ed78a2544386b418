/**
 * The automata table (@maa/protocol's AutomatonEntry): every automaton instance of an application
 * with its states and transitions and where they are written. Both platforms generate it (the
 * timesync app module's `AUTOMATA`, the ros2 `deployment.json`'s `automata`); the IDE's backend
 * serves it with the port topics, and the trace panels and breakpoints resolve `/maa/transitions`
 * (whose `index` is a transition's position here) and `/maa/automaton_states` against it.
 */
import type { InstanceView } from '@maa/generator-core';
import { allStates, allTransitions, ast, sourceOf, statePathName, targetOf, transitionLabel } from '@maa/language-automata';
import type { AutomatonEntry } from '@maa/protocol';
import { AstUtils, type AstNode } from 'langium';

/** A state's dotted path from its top state (`Outer.Inner`), as on `/maa/automaton_states`. */

/**
 * A model file relative to the model root: the folder of its package and its file name (MontiArc
 * keeps a package's models in the folder of its name; the generator does not know the model root).
 */
export function modelFile(node: AstNode, packageName: string): string {
    const uri = AstUtils.getDocument(node).uri;
    const name = uri.path.slice(uri.path.lastIndexOf('/') + 1);
    return packageName ? `${packageName.replace(/\./g, '/')}/${name}` : name;
}

function position(node: AstNode): { line: number; column: number } {
    const start = node.$cstNode?.range.start;
    return { line: (start?.line ?? 0) + 1, column: (start?.character ?? 0) + 1 };
}

/** The entry of one instance whose component has an automaton; undefined for other instances. */
export function automatonEntry(instance: InstanceView, node: string): AutomatonEntry | undefined {
    const component = instance.component;
    const automaton = component.behavior?.node;
    if (!automaton || !ast.isAutomaton(automaton)) return undefined;
    const states = allStates(automaton).map((s) => ({ path: statePathName(s), line: position(s).line }));
    const transitions = allTransitions(automaton).flatMap((t, index) => {
        const from = sourceOf(t);
        const to = targetOf(t);
        return from && to ? [{ index, from: statePathName(from), to: statePathName(to), label: transitionLabel(t), ...position(t) }] : [];
    });
    return {
        instancePath: instance.path.join('.'),
        node,
        component: component.qualifiedName,
        file: modelFile(automaton, component.packageName),
        states,
        transitions,
    };
}
