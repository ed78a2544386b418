import { AUTOMATON_STATES_TOPIC } from '@maa/protocol';
import { describe, expect, it } from 'vitest';
import { PortMap } from '../src/port-map.js';
import { activeStatesAt, advance, arrowDirection, diagramValuesAt, LatestOnly, replayStatusLine, timeLabel } from '../src/replay/logic.js';
import { TimelineStore } from '../src/timeline/store.js';
import { toastTopicMap } from './toast-topics.js';

const map = toastTopicMap([
    { instancePath: 'ctrl', node: '/tsr/ctrl' },
    { instancePath: 'arm', node: '/tsr/arm' },
]);

const states = (o: Record<string, string>) => ({ data: JSON.stringify(o) });

/** A recording of 3 s: the lever goes down at 1 s, the distance falls, ctrl switches states at 1 s and 2 s. */
function recording(): TimelineStore {
    const store = new TimelineStore();
    store.addAll([
        { t: 0, topic: '/tsr/ctrl/lever_down', message: { data: false } },
        { t: 1, topic: '/tsr/ctrl/lever_down', message: { data: true } },
        { t: 0, topic: '/tsr/distance', message: { data: 0.5 } },
        { t: 2, topic: '/tsr/distance', message: { data: 0.125 } },
        { t: 0, topic: '/joint_states', message: { name: ['a'], position: [1] } },
        { t: 0, topic: AUTOMATON_STATES_TOPIC, message: states({ '/tsr/ctrl': 'Idle', '/tsr/arm': 'Ready' }) },
        // ROS 2: a node publishes only its own state at a switch
        { t: 1, topic: AUTOMATON_STATES_TOPIC, message: states({ '/tsr/ctrl': 'Toasting' }) },
        { t: 2, topic: AUTOMATON_STATES_TOPIC, message: states({ '/tsr/ctrl': 'Serving' }) },
        { t: 3, topic: AUTOMATON_STATES_TOPIC, message: states({ '/tsr/arm': 'Moving' }) },
    ]);
    return store;
}

describe('replay: what the diagram shows at the cursor', () => {
    const ports = new PortMap(map);

    it('gives each port the last value recorded at or before the time, platform topics left out', () => {
        const store = recording();
        expect(diagramValuesAt(store, ports, 0.5)).toEqual(
            new Map([
                ['ctrl.leverDown', 'false'],
                ['distance', '0.5'],
            ]),
        );
        expect(diagramValuesAt(store, ports, 1)).toEqual(
            new Map([
                ['ctrl.leverDown', 'true'],
                ['distance', '0.5'],
            ]),
        );
        expect(diagramValuesAt(store, ports, 2.5).get('distance')).toBe('0.125');
    });

    it('shows no value before a port had one', () => {
        const store = recording();
        expect(diagramValuesAt(store, ports, -1).size).toBe(0);
        expect(diagramValuesAt(new TimelineStore(), ports, 1).size).toBe(0);
    });

    it('gives every automaton its state at the time, from messages that name only some nodes', () => {
        const store = recording();
        expect(activeStatesAt(store, ports, 0)).toEqual(
            new Map([
                ['ctrl', 'Idle'],
                ['arm', 'Ready'],
            ]),
        );
        expect(activeStatesAt(store, ports, 1.5)).toEqual(
            new Map([
                ['ctrl', 'Toasting'],
                ['arm', 'Ready'],
            ]),
        );
        expect(activeStatesAt(store, ports, 3)).toEqual(
            new Map([
                ['ctrl', 'Serving'],
                ['arm', 'Moving'],
            ]),
        );
    });

    it('has no states before the first message or from malformed ones', () => {
        const store = recording();
        expect(activeStatesAt(store, ports, -1).size).toBe(0);
        const bad = new TimelineStore();
        bad.add({ t: 0, topic: AUTOMATON_STATES_TOPIC, message: { data: '{not json' } });
        bad.add({ t: 1, topic: AUTOMATON_STATES_TOPIC, message: { data: 7 } });
        expect(activeStatesAt(bad, ports, 2).size).toBe(0);
        expect(activeStatesAt(new TimelineStore(), ports, 2).size).toBe(0);
    });
});

describe('replay: playing and seeking', () => {
    it('advances the cursor by wall time × speed and stops at the end', () => {
        expect(advance(1, 0.5, 2, 10)).toEqual({ cursor: 2, ended: false });
        expect(advance(9.5, 1, 1, 10)).toEqual({ cursor: 10, ended: true });
        expect(advance(3, -1, 1, 10)).toEqual({ cursor: 3, ended: false }); // a clock going back does not rewind
    });

    it('labels the time', () => {
        expect(timeLabel(1.234, 30)).toBe('1.23 s / 30.00 s');
        expect(timeLabel(undefined, undefined)).toBe('– / –');
    });

    it('seeks one call at a time, skipping to the newest time asked for', async () => {
        const calls: number[] = [];
        const answers: (() => void)[] = [];
        const seeker = new LatestOnly(
            (t) =>
                new Promise<void>((resolve) => {
                    calls.push(t);
                    answers.push(resolve);
                }),
        );
        expect(seeker.idle).toBe(true);
        seeker.request(1);
        seeker.request(2);
        seeker.request(3);
        expect(calls).toEqual([1]); // one under way, only the newest waits
        expect(seeker.idle).toBe(false);
        answers.shift()!();
        await new Promise<void>((r) => queueMicrotask(r));
        await Promise.resolve();
        expect(calls).toEqual([1, 3]);
        answers.shift()!();
        await new Promise<void>((r) => setTimeout(r, 0));
        expect(seeker.idle).toBe(true);
    });

    it('goes on seeking after a failed call', async () => {
        const calls: number[] = [];
        const seeker = new LatestOnly(async (t) => {
            calls.push(t);
            if (t === 1) throw new Error('replay server gone');
        });
        seeker.request(1);
        await new Promise<void>((r) => setTimeout(r, 0));
        seeker.request(2);
        await new Promise<void>((r) => setTimeout(r, 0));
        expect(calls).toEqual([1, 2]);
        expect(seeker.idle).toBe(true);
    });
});

describe('replay: the status line', () => {
    it('says the recording, the time and the toast there', () => {
        expect(replayStatusLine('TR-1.mcap', { time: 12.345, toast_level: 1.02, toast_on_plate: true })).toBe(
            'replay TR-1.mcap · t 12.35 s · toast 1.02 on plate',
        );
        expect(replayStatusLine('TR-1.mcap', { time: 1, toast_level: 0, toast_on_plate: false })).toBe(
            'replay TR-1.mcap · t 1.00 s · toast 0.00',
        );
        expect(replayStatusLine('TR-1.mcap', {})).toBe('replay TR-1.mcap');
    });
});

describe('replay: the arrow keys on the time slider', () => {
    it('→ and ↑ step to the next recorded message, ← and ↓ to the previous', () => {
        expect(arrowDirection('ArrowRight')).toBe(1);
        expect(arrowDirection('ArrowUp')).toBe(1);
        expect(arrowDirection('ArrowLeft')).toBe(-1);
        expect(arrowDirection('ArrowDown')).toBe(-1);
    });

    it('other keys keep what the slider does with them (Home, End, Page Up)', () => {
        for (const key of ['Home', 'End', 'PageUp', 'a', '']) expect(arrowDirection(key)).toBeUndefined();
    });
});
