/**
 * The automata table (@maa/protocol's AutomatonEntry): every automaton instance of an application
 * with its states and transitions and where they are written. Both platforms generate it (the
 * timesync app module's `AUTOMATA`, the ros2 `deployment.json`'s `automata`); the IDE's backend
 * serves it with the port topics, and the trace panels and breakpoints resolve `/maa/transitions`
 * (whose `index` is a transition's position here) and `/maa/automaton_states` against it.
 */
import type { InstanceView, ModeTransitionView } from '@maa/generator-core';
import { allStates, allTransitions, ast, sourceOf, statePathName, targetOf, transitionLabel } from '@maa/language-automata';
import type { AutomatonEntry } from '@maa/protocol';
import { AstUtils, type AstNode } from 'langium';

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

/**
 * The entry of one instance whose component has an automaton or a mode automaton (`kind: 'modes'`);
 * undefined for other instances.
 */
export function automatonEntry(instance: InstanceView, node: string): AutomatonEntry | undefined {
    return modeAutomatonEntry(instance, node) ?? stateAutomatonEntry(instance, node);
}

/**
 * A mode component's entry: its modes as states and its mode transitions in declaration order,
 * the order the generated `mode_transition` tries them, so a transition's index is its position
 * there (timesync/mode-transition.njk returns it with the target).
 */
function modeAutomatonEntry(instance: InstanceView, node: string): AutomatonEntry | undefined {
    const component = instance.component;
    const m = component.modes;
    if (!m) return undefined;
    return {
        instancePath: instance.path.join('.'),
        node,
        component: component.qualifiedName,
        file: modelFile(m.node, component.packageName),
        states: m.modes.map((x) => ({ path: x.name, line: position(x.node).line })),
        transitions: m.transitions.map((t, index) => ({
            index,
            from: t.source,
            to: t.target,
            label: modeTransitionLabel(t),
            ...position(t.node),
        })),
        kind: 'modes',
    };
}

/** `trigger [guard]` as written (`""` for neither), like an automaton transition's label. */
function modeTransitionLabel(t: ModeTransitionView): string {
    const trigger = t.trigger.kind === 'port' ? t.trigger.port : t.trigger.kind === 'tick' ? 'Tick' : '';
    const guard = t.guard?.$cstNode?.text;
    return [trigger, guard ? `[${guard}]` : ''].filter(Boolean).join(' ');
}

function stateAutomatonEntry(instance: InstanceView, node: string): AutomatonEntry | undefined {
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
