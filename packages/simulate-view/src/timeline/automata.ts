/**
 * The automata table of a run (`automata` of `GET /api/sim/topics`): per automaton instance its
 * component, source file, states and transitions with their source positions, so a transition
 * seen at run time leads back to its line. Read defensively: the table is optional (older
 * generated code has none) and comes from another process. Pure.
 */

export interface AutomatonStateInfo {
    path: string;
    /** 1-based. */
    line: number;
}

export interface AutomatonTransitionInfo {
    /** 0-based position in `allTransitions(automaton)` order (the `index` of `/maa/transitions`). */
    index: number;
    from: string;
    to: string;
    /** `trigger [guard] / action` as the diagram shows it. */
    label: string;
    /** 1-based. */
    line: number;
    column: number;
}

export interface AutomatonInfo {
    instancePath: string;
    /** The instance's ROS node (`/toast_service_robot/ctrl`). */
    node: string;
    /** The component's qualified name. */
    component: string;
    /** Workspace-relative path of the file that declares the automaton. */
    file: string;
    states: AutomatonStateInfo[];
    transitions: AutomatonTransitionInfo[];
}

/** How the view names an automaton's instance: a root component's mode automaton has the path ''. */
export function instanceLabel(instancePath: string): string {
    return instancePath === '' ? '(root)' : instancePath;
}

type Fields = Record<string, unknown>;
const isRecord = (x: unknown): x is Fields => typeof x === 'object' && x !== null && !Array.isArray(x);
const isString = (x: unknown): x is string => typeof x === 'string';
const isInt = (x: unknown): x is number => typeof x === 'number' && Number.isInteger(x);

function stateOf(x: unknown): AutomatonStateInfo | undefined {
    return isRecord(x) && isString(x['path']) && isInt(x['line']) ? { path: x['path'], line: x['line'] } : undefined;
}

function transitionOf(x: unknown): AutomatonTransitionInfo | undefined {
    if (!isRecord(x)) return undefined;
    const { index, from, to, label, line, column } = x;
    if (!isInt(index) || !isString(from) || !isString(to) || !isInt(line)) return undefined;
    return { index, from, to, label: isString(label) ? label : '', line, column: isInt(column) ? column : 1 };
}

/** The automata of a topic-map answer; entries that do not parse are left out, no table is an empty list. */
export function parseAutomata(answer: unknown): AutomatonInfo[] {
    const list = isRecord(answer) ? answer['automata'] : undefined;
    if (!Array.isArray(list)) return [];
    const out: AutomatonInfo[] = [];
    for (const a of list) {
        if (!isRecord(a)) continue;
        const { instancePath, node, component, file, states, transitions } = a;
        if (!isString(instancePath) || !isString(node) || !isString(component) || !isString(file)) continue;
        out.push({
            instancePath,
            node,
            component,
            file,
            states: Array.isArray(states) ? states.map(stateOf).filter((s): s is AutomatonStateInfo => !!s) : [],
            transitions: Array.isArray(transitions) ? transitions.map(transitionOf).filter((t): t is AutomatonTransitionInfo => !!t) : [],
        });
    }
    return out;
}

/**
 * The transition of an automaton a run took: by its index when the event has one, else the
 * first with the same source and target (a derived transition knows only the states).
 */
export function findTransition(
    automaton: AutomatonInfo | undefined,
    t: { from: string; to: string; index?: number },
): AutomatonTransitionInfo | undefined {
    if (!automaton) return undefined;
    if (t.index !== undefined) {
        const byIndex = automaton.transitions.find((x) => x.index === t.index);
        if (byIndex) return byIndex;
    }
    return automaton.transitions.find((x) => x.from === t.from && x.to === t.to);
}
