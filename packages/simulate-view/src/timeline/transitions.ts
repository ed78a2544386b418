/**
 * The state history of each automaton instance over the timeline store: the bands of state
 * names over time (from `/maa/automaton_states`, whose messages carry the state of some or all
 * nodes) and the transitions taken (the `/maa/transitions` events where a node has them, else
 * each change of its state), kept up to date incrementally as messages are appended. Pure.
 */
import { AUTOMATON_STATES_TOPIC, PROGRAM_STEPS_TOPIC, TRANSITIONS_TOPIC } from '@maa/protocol';
import type { TimedMessage, TimelineStore } from './store.js';

/** A state held from `t0` until `t1` (`undefined`: still active at the newest data). */
export interface StateBand {
    state: string;
    t0: number;
    t1: number | undefined;
}

/** A transition taken at time `t` by the automaton of `node`. */
export interface TakenTransition {
    t: number;
    node: string;
    from: string;
    to: string;
    /** Its position in the automaton's transitions (events carry it; a derived one has none). */
    index?: number;
    /** `event`: from `/maa/transitions`; `derived`: a change of the published state. */
    origin: 'event' | 'derived';
}

/** A RobotArm program step (`/maa/program_steps`). */
export interface ProgramStep {
    t: number;
    node: string;
    program: string;
    step: number;
    line: number;
    text: string;
    /** Workspace-relative file of the program, when the event names it. */
    file?: string;
}

export interface NodeHistory {
    node: string;
    bands: StateBand[];
    /** Changes of the published state. */
    derived: TakenTransition[];
    /** `/maa/transitions` events. */
    events: TakenTransition[];
}

/** The JSON object in a `std_msgs/String` message's `data`, `undefined` when it is none. */
export function jsonData(message: unknown): Record<string, unknown> | undefined {
    let data: unknown = message;
    if (data && typeof data === 'object' && 'data' in data) data = (data as { data: unknown }).data;
    if (typeof data !== 'string') return undefined;
    try {
        const parsed: unknown = JSON.parse(data);
        return parsed && typeof parsed === 'object' && !Array.isArray(parsed) ? (parsed as Record<string, unknown>) : undefined;
    } catch {
        return undefined;
    }
}

/** A `/maa/transitions` event (C1), `undefined` when malformed. */
export function parseTransitionEvent(m: TimedMessage): TakenTransition | undefined {
    const d = jsonData(m.message);
    if (!d) return undefined;
    const { node, from, to, index } = d;
    if (typeof node !== 'string' || typeof from !== 'string' || typeof to !== 'string') return undefined;
    return { t: m.t, node, from, to, ...(Number.isInteger(index) ? { index: index as number } : {}), origin: 'event' };
}

/** A `/maa/program_steps` event (C2), `undefined` when malformed. */
export function parseProgramStep(m: TimedMessage): ProgramStep | undefined {
    const d = jsonData(m.message);
    if (!d) return undefined;
    const { node, program, step, line, text, file } = d;
    if (typeof node !== 'string' || typeof program !== 'string' || !Number.isInteger(step) || !Number.isInteger(line)) return undefined;
    return {
        t: m.t,
        node,
        program,
        step: step as number,
        line: line as number,
        text: typeof text === 'string' ? text : '',
        ...(typeof file === 'string' ? { file } : {}),
    };
}

/** The state a node holds at time `t` (the last band begun by then), if any. */
export function stateAt(h: NodeHistory, t: number): string | undefined {
    for (let i = h.bands.length - 1; i >= 0; i--) {
        const band = h.bands[i];
        if (band && band.t0 <= t) return band.state;
    }
    return undefined;
}

/** Follows the store: the state bands and transitions of every node, and the program steps. */
export class TransitionIndex {
    private readonly nodes = new Map<string, NodeHistory>();
    private steps: ProgramStep[] = [];
    private generation = -1;
    private readonly read = new Map<string, number>();

    constructor(private readonly store: TimelineStore) {}

    /** Reads what was appended since the last call (everything again when stored messages moved). */
    update(): void {
        if (this.store.generation !== this.generation) {
            this.generation = this.store.generation;
            this.nodes.clear();
            this.steps = [];
            this.read.clear();
        }
        for (const m of this.next(AUTOMATON_STATES_TOPIC)) this.addStates(m);
        for (const m of this.next(TRANSITIONS_TOPIC)) {
            const e = parseTransitionEvent(m);
            if (e) this.history(e.node).events.push(e);
        }
        for (const m of this.next(PROGRAM_STEPS_TOPIC)) {
            const s = parseProgramStep(m);
            if (s) this.steps.push(s);
        }
    }

    /** The nodes with a state history, in the order they first appeared. */
    histories(): NodeHistory[] {
        return [...this.nodes.values()];
    }

    history(node: string): NodeHistory {
        let h = this.nodes.get(node);
        if (!h) {
            h = { node, bands: [], derived: [], events: [] };
            this.nodes.set(node, h);
        }
        return h;
    }

    /** The transitions of a node: its events when it has any, else its state changes. */
    transitions(node: string): TakenTransition[] {
        const h = this.nodes.get(node);
        if (!h) return [];
        return h.events.length > 0 ? h.events : h.derived;
    }

    /** Every node's transitions, by time. */
    allTransitions(): TakenTransition[] {
        return [...this.nodes.keys()].flatMap((n) => this.transitions(n)).sort((a, b) => a.t - b.t);
    }

    programSteps(): readonly ProgramStep[] {
        return this.steps;
    }

    private next(topic: string): TimedMessage[] {
        const from = this.read.get(topic) ?? 0;
        const ms = this.store.since(topic, from);
        this.read.set(topic, from + ms.length);
        return ms;
    }

    private addStates(m: TimedMessage): void {
        const d = jsonData(m.message);
        if (!d) return;
        for (const [node, state] of Object.entries(d)) {
            if (typeof state !== 'string' || state.length === 0) continue;
            const h = this.history(node);
            const last = h.bands[h.bands.length - 1];
            if (last && last.state === state) continue;
            if (last) {
                last.t1 = m.t;
                h.derived.push({ t: m.t, node, from: last.state, to: state, origin: 'derived' });
            }
            h.bands.push({ state, t0: m.t, t1: undefined });
        }
    }
}

/** The transition taken last at or before `t` in a time-ordered list, `undefined` before the first. */
export function lastAtOrBefore(list: readonly TakenTransition[], t: number): TakenTransition | undefined {
    for (let j = list.length - 1; j >= 0; j--) if (list[j]!.t <= t) return list[j];
    return undefined;
}

/**
 * The transition after (`+1`) or before (`-1`) the selected one in a time-ordered list (from time
 * `t` when none is selected or it is not in the list), `undefined` at either end.
 */
export function stepTransition(
    list: readonly TakenTransition[],
    selected: TakenTransition | undefined,
    t: number,
    direction: 1 | -1,
): TakenTransition | undefined {
    const i = selected ? list.indexOf(selected) : -1;
    if (i >= 0) return list[i + direction];
    if (direction > 0) return list.find((x) => x.t > t);
    for (let j = list.length - 1; j >= 0; j--) if (list[j]!.t < t) return list[j];
    return undefined;
}
