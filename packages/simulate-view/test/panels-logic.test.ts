import { describe, expect, it } from 'vitest';
import { nodeLabel, type PanelContext } from '../src/panels/context.js';
import { droppedNote, logEntries } from '../src/panels/log-panel.js';
import { messageJson } from '../src/panels/messages-panel.js';
import { feedsTopic } from '../src/timeline/feed.js';
import type { ProgramStep, TakenTransition } from '../src/timeline/transitions.js';

describe('the topics a live run records in the timeline', () => {
    const isPort = (t: string) => t === '/toast_service_robot/ctrl/arm';

    it('records port topics, platform topics and the /maa/ event topics', () => {
        expect(feedsTopic({ topic: '/toast_service_robot/ctrl/arm', type: 'std_msgs/msg/Int32' }, isPort)).toBe(true);
        expect(feedsTopic({ topic: '/sensors/distance', type: 'std_msgs/msg/Int32' }, isPort)).toBe(true);
        expect(feedsTopic({ topic: '/joint_states', type: 'sensor_msgs/msg/JointState' }, isPort)).toBe(true);
        expect(feedsTopic({ topic: '/maa/automaton_states', type: 'std_msgs/msg/String' }, isPort)).toBe(true);
        expect(feedsTopic({ topic: '/maa/transitions', type: 'std_msgs/msg/String' }, isPort)).toBe(true);
    });

    it('leaves out the clock, unknown and heavy topics', () => {
        expect(feedsTopic({ topic: '/clock', type: 'rosgraph_msgs/msg/Clock' }, isPort)).toBe(false);
        expect(feedsTopic({ topic: '/rosout', type: 'rcl_interfaces/msg/Log' }, isPort)).toBe(false);
        expect(feedsTopic({ topic: '/maa/camera', type: 'sensor_msgs/msg/Image' }, isPort)).toBe(false);
        expect(feedsTopic({ topic: '/toast_service_robot/ctrl/arm', type: 'sensor_msgs/msg/PointCloud2' }, isPort)).toBe(false);
    });
});

describe('the log of transitions and program steps', () => {
    const tr = (t: number, to: string): TakenTransition => ({ t, node: '/r/ctrl', from: 'A', to, origin: 'derived' });
    const step = (t: number, n: number): ProgramStep => ({ t, node: '/r/arm', program: 'serve', step: n, line: 3 + n, text: 'x' });

    it('merges them by time, transitions first at the same time', () => {
        const entries = logEntries([tr(1, 'B'), tr(3, 'C')], [step(1, 0), step(2, 1)]);
        expect(entries.map((e) => `${e.kind}@${e.t}`)).toEqual(['transition@1', 'step@1', 'step@2', 'transition@3']);
    });

    it('keeps the newest entries only', () => {
        const entries = logEntries(
            Array.from({ length: 10 }, (_, i) => tr(i, `S${i}`)),
            [],
            3,
        );
        expect(entries.map((e) => e.t)).toEqual([7, 8, 9]);
        expect(logEntries([], [])).toEqual([]);
    });
});

describe('the raw message view', () => {
    it('shows a message as indented JSON', () => {
        expect(messageJson({ data: 3 })).toBe('{\n  "data": 3\n}');
        expect(messageJson(undefined)).toBe('undefined');
    });

    it('shortens a long message and survives one that is no JSON', () => {
        const long = messageJson({ data: 'x'.repeat(10_000) });
        expect(long.length).toBeLessThan(4100);
        expect(long).toMatch(/more characters\)$/);
        const cyclic: Record<string, unknown> = {};
        cyclic['self'] = cyclic;
        expect(messageJson(cyclic)).toBe('[object Object]');
    });
});

describe('node labels', () => {
    const ctx = (instanceOf: (n: string) => string | undefined) =>
        ({
            instanceOf,
            automata: () => [
                { instancePath: 'unit.ctrl', node: '/r/unit/ctrl', component: 'C', file: 'f.arc', states: [], transitions: [] },
            ],
        }) as unknown as PanelContext;

    it('names a node by its instance path, from the port map or the automata table', () => {
        expect(
            nodeLabel(
                ctx((n) => (n === '/r/ctrl' ? 'ctrl' : undefined)),
                '/r/ctrl',
            ),
        ).toBe('ctrl');
        expect(
            nodeLabel(
                ctx(() => undefined),
                '/r/unit/ctrl',
            ),
        ).toBe('unit.ctrl');
        expect(
            nodeLabel(
                ctx(() => ''),
                '/r',
            ),
        ).toBe('(root)');
        expect(
            nodeLabel(
                ctx(() => undefined),
                '/other',
            ),
        ).toBe('/other');
    });
});

describe('the note over a log that lists only its newest entries', () => {
    it('says how many of how many it shows', () => {
        expect(droppedNote(500, 1234)).toBe('showing the newest 500 of 1234 entries');
    });

    it('says nothing when every entry is listed', () => {
        expect(droppedNote(12, 12)).toBe('');
        expect(droppedNote(0, 0)).toBe('');
    });
});
