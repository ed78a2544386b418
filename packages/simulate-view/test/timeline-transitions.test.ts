import { describe, expect, it } from 'vitest';
import { findTransition, parseAutomata, type AutomatonInfo } from '../src/timeline/automata.js';
import { TimelineStore } from '../src/timeline/store.js';
import { AUTOMATON_STATES_TOPIC, PROGRAM_STEPS_TOPIC, TRANSITIONS_TOPIC } from '@maa/protocol';
import {
    TransitionIndex,
    lastAtOrBefore,
    parseProgramStep,
    parseTransitionEvent,
    stateAt,
    stepTransition,
} from '../src/timeline/transitions.js';

const CTRL = '/toast_service_robot/ctrl';
const ARM = '/toast_service_robot/arm';
const states = (t: number, s: Record<string, string>) => ({ t, topic: AUTOMATON_STATES_TOPIC, message: { data: JSON.stringify(s) } });
const event = (t: number, e: unknown) => ({ t, topic: TRANSITIONS_TOPIC, message: { data: JSON.stringify(e) } });

const TABLE = {
    app: 'TR',
    automata: [
        {
            instancePath: 'ctrl',
            node: CTRL,
            component: 'toast.Controller',
            file: 'toast-service/Controller.arc',
            states: [{ path: 'Idle', line: 5 }, { path: 'Toasting', line: 6 }, { path: 'bad' }],
            transitions: [
                { index: 0, from: 'Idle', to: 'Toasting', label: 'start', line: 9, column: 5 },
                { index: 1, from: 'Toasting', to: 'Serving', label: '[done]', line: 10, column: 5 },
                { index: 2, from: 'Toasting', to: 'Serving', label: '[abort]', line: 11, column: 5 },
                { index: 'x' },
            ],
        },
        { instancePath: 'broken' },
        'nonsense',
    ],
};

describe('the automata table', () => {
    it('parses the well-formed entries and leaves out the rest', () => {
        const [a, ...rest] = parseAutomata(TABLE);
        expect(rest).toEqual([]);
        expect(a?.component).toBe('toast.Controller');
        expect(a?.states).toEqual([
            { path: 'Idle', line: 5 },
            { path: 'Toasting', line: 6 },
        ]);
        expect(a?.transitions.map((t) => t.index)).toEqual([0, 1, 2]);
    });

    it('is empty for an answer without a table', () => {
        expect(parseAutomata({ app: 'TR', ports: [] })).toEqual([]);
        expect(parseAutomata(undefined)).toEqual([]);
        expect(parseAutomata({ automata: 'x' })).toEqual([]);
    });

    it('finds a transition by index, else by its states', () => {
        const a = parseAutomata(TABLE)[0] as AutomatonInfo;
        expect(findTransition(a, { from: 'Toasting', to: 'Serving', index: 2 })?.line).toBe(11);
        expect(findTransition(a, { from: 'Toasting', to: 'Serving' })?.line).toBe(10);
        expect(findTransition(a, { from: 'Serving', to: 'Idle' })).toBeUndefined();
        expect(findTransition(undefined, { from: 'Idle', to: 'Toasting' })).toBeUndefined();
    });
});

describe('TransitionIndex', () => {
    it('builds state bands per node from partial and full state messages', () => {
        const store = new TimelineStore();
        store.addAll([
            states(0, { [CTRL]: 'Idle', [ARM]: 'Home' }),
            states(0.1, { [CTRL]: 'Idle' }),
            states(0.2, { [CTRL]: 'Toasting' }),
            states(0.3, { [ARM]: 'Moving', [CTRL]: 'Toasting' }),
            states(0.5, { [CTRL]: 'Serving' }),
        ]);
        const index = new TransitionIndex(store);
        index.update();
        const ctrl = index.histories().find((h) => h.node === CTRL);
        expect(ctrl?.bands).toEqual([
            { state: 'Idle', t0: 0, t1: 0.2 },
            { state: 'Toasting', t0: 0.2, t1: 0.5 },
            { state: 'Serving', t0: 0.5, t1: undefined },
        ]);
        expect(index.transitions(CTRL).map((t) => `${t.from}->${t.to}@${t.t}`)).toEqual(['Idle->Toasting@0.2', 'Toasting->Serving@0.5']);
        expect(index.allTransitions().map((t) => t.node)).toEqual([CTRL, ARM, CTRL]);
    });

    it('follows appended messages and starts over when stored ones move', () => {
        const store = new TimelineStore();
        const index = new TransitionIndex(store);
        store.add(states(0, { [CTRL]: 'Idle' }));
        index.update();
        store.add(states(1, { [CTRL]: 'Toasting' }));
        index.update();
        expect(index.transitions(CTRL)).toHaveLength(1);
        store.add(states(0.5, { [CTRL]: 'Serving' })); // older: inserted before
        index.update();
        expect(index.transitions(CTRL).map((t) => t.to)).toEqual(['Serving', 'Toasting']);
        store.clear();
        index.update();
        expect(index.histories()).toEqual([]);
    });

    it('prefers the transition events of a node over its state changes', () => {
        const store = new TimelineStore();
        store.addAll([
            states(0, { [CTRL]: 'Idle' }),
            states(1, { [CTRL]: 'Toasting' }),
            event(1, { node: CTRL, from: 'Idle', to: 'Toasting', index: 0 }),
            event(1.5, { node: CTRL, from: 'Toasting', to: 'Toasting', index: 4 }),
            event(2, { node: CTRL, to: 'Toasting' }),
        ]);
        const index = new TransitionIndex(store);
        index.update();
        expect(index.transitions(CTRL).map((t) => [t.t, t.index, t.origin])).toEqual([
            [1, 0, 'event'],
            [1.5, 4, 'event'],
        ]);
    });

    it('ignores malformed messages', () => {
        const store = new TimelineStore();
        store.addAll([
            { t: 0, topic: AUTOMATON_STATES_TOPIC, message: { data: 'not json' } },
            { t: 0, topic: AUTOMATON_STATES_TOPIC, message: { data: '[1]' } },
            { t: 0, topic: AUTOMATON_STATES_TOPIC, message: 42 },
            states(0.1, { [CTRL]: '' }),
            { t: 0.2, topic: PROGRAM_STEPS_TOPIC, message: { data: '{"node": 1}' } },
        ]);
        const index = new TransitionIndex(store);
        index.update();
        expect(index.histories()).toEqual([]);
        expect(index.programSteps()).toEqual([]);
        expect(parseTransitionEvent({ t: 0, topic: TRANSITIONS_TOPIC, message: { data: 5 } })).toBeUndefined();
    });

    it('reads program steps', () => {
        const m = {
            t: 3,
            topic: PROGRAM_STEPS_TOPIC,
            message: { data: JSON.stringify({ node: ARM, program: 'serve', step: 2, line: 14, text: 'moveTo(plate);' }) },
        };
        expect(parseProgramStep(m)).toEqual({ t: 3, node: ARM, program: 'serve', step: 2, line: 14, text: 'moveTo(plate);' });
        const store = new TimelineStore();
        store.add(m);
        const index = new TransitionIndex(store);
        index.update();
        expect(index.programSteps()).toHaveLength(1);
    });
});

describe('stepping through transitions', () => {
    const list = [1, 2, 2, 3].map((t, i) => ({ t, node: CTRL, from: `s${i}`, to: `s${i + 1}`, origin: 'derived' as const }));

    it('steps from the selected transition, also between two at the same time', () => {
        expect(stepTransition(list, list[1], 0, 1)).toBe(list[2]);
        expect(stepTransition(list, list[2], 0, -1)).toBe(list[1]);
        expect(stepTransition(list, list[3], 0, 1)).toBeUndefined();
        expect(stepTransition(list, list[0], 0, -1)).toBeUndefined();
    });

    it('steps from a time when nothing is selected', () => {
        expect(stepTransition(list, undefined, 1.5, 1)).toBe(list[1]);
        expect(stepTransition(list, undefined, 2.5, -1)).toBe(list[2]);
        expect(stepTransition(list, undefined, 0.5, -1)).toBeUndefined();
        expect(stepTransition([], undefined, 0, 1)).toBeUndefined();
    });
});

describe('stateAt', () => {
    const history = {
        node: CTRL,
        bands: [
            { state: 'Toasting', t0: 1, t1: 2 },
            { state: 'Serving', t0: 2, t1: undefined },
        ],
        derived: [],
        events: [],
    };

    it('names the state entered at the newest time, whose band has no width yet', () => {
        expect(stateAt(history, 2)).toBe('Serving');
        expect(stateAt(history, 1.5)).toBe('Toasting');
    });

    it('names none before the first band', () => {
        expect(stateAt(history, 0.5)).toBeUndefined();
    });

    it('finds the transition taken last at or before a time, none before the first', () => {
        const list = [1, 2.5, 2.5, 4].map((t, i) => ({ t, node: '/n', from: `S${i}`, to: `S${i + 1}` }));
        expect(lastAtOrBefore(list, 3)).toBe(list[2]);
        expect(lastAtOrBefore(list, 2.5)).toBe(list[2]);
        expect(lastAtOrBefore(list, 10)).toBe(list[3]);
        expect(lastAtOrBefore(list, 0.5)).toBeUndefined();
        expect(lastAtOrBefore([], 1)).toBeUndefined();
    });
});
