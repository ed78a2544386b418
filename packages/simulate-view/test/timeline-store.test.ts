import { describe, expect, it } from 'vitest';
import { TimelineStore, type TimedMessage, type TimelineChange } from '../src/timeline/store.js';

const msg = (t: number, topic = '/a', data: unknown = t): TimedMessage => ({ t, topic, message: { data } });

function recorder(store: TimelineStore): TimelineChange[] {
    const seen: TimelineChange[] = [];
    store.onChange((w) => seen.push(w));
    return seen;
}

describe('TimelineStore', () => {
    it('is empty at first', () => {
        const s = new TimelineStore();
        expect(s.start).toBeUndefined();
        expect(s.end).toBeUndefined();
        expect(s.cursor).toBeUndefined();
        expect(s.topics()).toEqual([]);
        expect(s.latestAt('/a', 10)).toBeUndefined();
        expect(s.range('/a', 0, 10)).toEqual([]);
    });

    it('answers latestAt with the last message at or before the time', () => {
        const s = new TimelineStore();
        for (const t of [0.1, 0.2, 0.2, 0.5]) s.add(msg(t, '/a', `v${t}`));
        expect(s.latestAt('/a', 0.05)).toBeUndefined();
        expect(s.latestAt('/a', 0.1)?.t).toBe(0.1);
        expect(s.latestAt('/a', 0.3)?.t).toBe(0.2);
        expect(s.latestAt('/a', 99)?.t).toBe(0.5);
        expect(s.latestAt('/b', 99)).toBeUndefined();
        expect(s.start).toBe(0.1);
        expect(s.end).toBe(0.5);
    });

    it('keeps messages of the same time in arrival order', () => {
        const s = new TimelineStore();
        s.add(msg(1, '/a', 'first'));
        s.add(msg(1, '/a', 'second'));
        expect(s.latestAt('/a', 1)?.message).toEqual({ data: 'second' });
        expect(s.range('/a', 1, 1).map((m) => m.message)).toEqual([{ data: 'first' }, { data: 'second' }]);
    });

    it('inserts an older message in time order', () => {
        const s = new TimelineStore();
        s.add(msg(1));
        s.add(msg(3));
        s.add(msg(2));
        s.add(msg(0.5));
        expect(s.range('/a', 0, 10).map((m) => m.t)).toEqual([0.5, 1, 2, 3]);
        expect(s.start).toBe(0.5);
        expect(s.latestAt('/a', 2.5)?.t).toBe(2);
    });

    it('answers range inclusively and per topic', () => {
        const s = new TimelineStore();
        s.addAll([msg(0), msg(1), msg(2), msg(3), msg(1.5, '/b')]);
        expect(s.range('/a', 1, 2).map((m) => m.t)).toEqual([1, 2]);
        expect(s.range('/a', 1.1, 1.9)).toEqual([]);
        expect(s.range('/a', 3, 1)).toEqual([]);
        expect(s.range('/b', 0, 10).map((m) => m.t)).toEqual([1.5]);
        expect(s.topics()).toEqual(['/a', '/b']);
        expect(s.count('/a')).toBe(4);
    });

    it('refuses messages without a topic or a finite time', () => {
        const s = new TimelineStore();
        const seen = recorder(s);
        s.add({ t: Number.NaN, topic: '/a', message: {} });
        s.add({ t: Infinity, topic: '/a', message: {} });
        s.add({ t: 1, topic: '', message: {} });
        s.addAll([{ t: 1, topic: 42 as unknown as string, message: {} }]);
        expect(s.topics()).toEqual([]);
        expect(seen).toEqual([]);
    });

    it('notifies data once per add and once per addAll', () => {
        const s = new TimelineStore();
        const seen = recorder(s);
        s.add(msg(1));
        s.addAll([msg(2), msg(3), msg(4)]);
        s.addAll([]);
        expect(seen).toEqual(['data', 'data']);
    });

    it('notifies a cursor change only when it changes, and ignores a non-finite cursor', () => {
        const s = new TimelineStore();
        const seen = recorder(s);
        s.cursor = 2;
        s.cursor = 2;
        s.cursor = Number.NaN;
        expect(s.cursor).toBe(2);
        s.cursor = undefined;
        expect(seen).toEqual(['cursor', 'cursor']);
    });

    it('shows the cursor time, else the newest data', () => {
        const s = new TimelineStore();
        s.addAll([msg(1), msg(5)]);
        expect(s.shownTime).toBe(5);
        s.cursor = 2;
        expect(s.shownTime).toBe(2);
    });

    it('clears messages and cursor', () => {
        const s = new TimelineStore();
        s.addAll([msg(1), msg(2, '/b')]);
        s.cursor = 1;
        const seen = recorder(s);
        s.clear();
        expect(s.topics()).toEqual([]);
        expect(s.start).toBeUndefined();
        expect(s.end).toBeUndefined();
        expect(s.cursor).toBeUndefined();
        expect(seen).toEqual(['data', 'cursor']);
    });

    it('stops notifying a disposed listener', () => {
        const s = new TimelineStore();
        const seen: TimelineChange[] = [];
        const sub = s.onChange((w) => seen.push(w));
        s.add(msg(1));
        sub.dispose();
        s.add(msg(2));
        expect(seen).toEqual(['data']);
    });

    it('drops the oldest messages of a topic beyond its bound and moves start', () => {
        const s = new TimelineStore({ maxPerTopic: 10 });
        for (let i = 0; i < 25; i++) s.add(msg(i));
        s.add(msg(3, '/b'));
        expect(s.count('/a')).toBeLessThanOrEqual(10);
        expect(s.latestAt('/a', 100)?.t).toBe(24);
        expect(s.start).toBe(3);
        for (let i = 0; i < 25; i++) s.add(msg(10 + i, '/b'));
        expect(s.start).toBeGreaterThan(3);
        expect(() => new TimelineStore({ maxPerTopic: 0 })).toThrow(/maxPerTopic/);
    });
});

describe('TimelineStore for readers that follow appends', () => {
    it('keeps its generation while messages are appended and changes it when stored ones move', () => {
        const s = new TimelineStore({ maxPerTopic: 10 });
        const g0 = s.generation;
        s.add(msg(1));
        s.add(msg(2));
        expect(s.generation).toBe(g0);
        expect(s.since('/a', 1).map((m) => m.t)).toEqual([2]);
        expect(s.since('/none', 0)).toEqual([]);
        s.add(msg(1.5));
        const g1 = s.generation;
        expect(g1).not.toBe(g0);
        for (let i = 0; i < 20; i++) s.add(msg(10 + i));
        const g2 = s.generation;
        expect(g2).not.toBe(g1);
        s.clear();
        expect(s.generation).not.toBe(g2);
    });
});

describe('windows around a time and stepping between messages', () => {
    const store = (): TimelineStore => {
        const s = new TimelineStore();
        s.addAll([msg(0), msg(1), msg(2), msg(3), msg(4), msg(5), msg(0.5, '/b'), msg(2.5, '/b')]);
        return s;
    };

    it('gives the message in effect at t with a few before and after it, not the whole history', () => {
        const s = store();
        expect(s.around('/a', 2.5, 1, 2).map((m) => m.t)).toEqual([1, 2, 3, 4]);
        expect(s.around('/a', 2, 1, 1).map((m) => m.t)).toEqual([1, 2, 3]);
        // at either end: what there is
        expect(s.around('/a', 0, 3, 1).map((m) => m.t)).toEqual([0, 1]);
        expect(s.around('/a', 9, 2, 3).map((m) => m.t)).toEqual([3, 4, 5]);
    });

    it('gives only later messages before the first one, nothing for an unknown topic or negative counts', () => {
        const s = store();
        expect(s.around('/a', -1, 3, 2).map((m) => m.t)).toEqual([0, 1]);
        expect(s.around('/nope', 1, 3, 3)).toEqual([]);
        expect(s.around('/a', 2, -5, -5).map((m) => m.t)).toEqual([2]);
    });

    it('finds the next and previous message time of any topic', () => {
        const s = store();
        expect(s.adjacentTime(0, 1)).toBe(0.5);
        expect(s.adjacentTime(0.5, 1)).toBe(1);
        expect(s.adjacentTime(2.2, 1)).toBe(2.5);
        expect(s.adjacentTime(2.5, -1)).toBe(2);
        expect(s.adjacentTime(1, -1)).toBe(0.5);
    });

    it('finds none past either end or in an empty store', () => {
        const s = store();
        expect(s.adjacentTime(5, 1)).toBeUndefined();
        expect(s.adjacentTime(0, -1)).toBeUndefined();
        expect(new TimelineStore().adjacentTime(1, 1)).toBeUndefined();
    });
});
