import { describe, expect, it } from 'vitest';
import { emptyText } from '../src/inspector.js';
import { clampFraction, DEFAULT_VIEW_FRACTION, fractionAt, MAX_FRACTION, MIN_FRACTION, storedFraction } from '../src/layout.js';
import { lastRunNote } from '../src/logic.js';
import { toolbarState, type SessionState, type ToolbarContext } from '../src/session.js';

const ctx: ToolbarContext = { canRun: true, connected: true, paused: false, viewShown: true };

describe('the tool bar (issue 19: start disabled while a run starts or runs)', () => {
    it('offers Start only when no session is starting, running or stopping', () => {
        expect(toolbarState({ kind: 'idle', reason: 'initial' }, ctx).start).toBe(true);
        expect(toolbarState({ kind: 'idle', reason: 'stopped' }, ctx).start).toBe(true);
        const busy: SessionState[] = [
            { kind: 'starting', adopted: false },
            { kind: 'starting', adopted: true },
            { kind: 'cancelling', adopted: false, stopOpen: true },
            { kind: 'running' },
            { kind: 'stopping' },
        ];
        for (const s of busy) expect(toolbarState(s, ctx).start, s.kind).toBe(false);
    });

    it('offers Stop while a start is open or a session runs, not when idle or stopping', () => {
        expect(toolbarState({ kind: 'starting', adopted: false }, ctx).stop).toBe(true);
        expect(toolbarState({ kind: 'running' }, ctx).stop).toBe(true);
        expect(toolbarState({ kind: 'idle', reason: 'initial' }, ctx).stop).toBe(false);
        expect(toolbarState({ kind: 'stopping' }, ctx).stop).toBe(false);
    });

    it('refuses Start without a runnable platform, and the run controls without a connection', () => {
        expect(toolbarState({ kind: 'idle', reason: 'initial' }, { ...ctx, canRun: false }).start).toBe(false);
        expect(toolbarState({ kind: 'running' }, ctx).run).toBe(true);
        expect(toolbarState({ kind: 'running' }, { ...ctx, connected: false }).run).toBe(false);
        expect(toolbarState({ kind: 'starting', adopted: false }, ctx).run).toBe(false);
        expect(toolbarState({ kind: 'starting', adopted: false }, ctx).choice).toBe(false);
        expect(toolbarState({ kind: 'running' }, { ...ctx, paused: true }).showResume).toBe(true);
    });
});

describe("the 3D view's room", () => {
    it('follows the pointer within the bounds both sides need', () => {
        expect(fractionAt(300, 100, 400)).toBeCloseTo(0.5);
        expect(fractionAt(100, 100, 400)).toBe(MIN_FRACTION);
        expect(fractionAt(10_000, 100, 400)).toBe(MAX_FRACTION);
        expect(fractionAt(300, 100, 0)).toBe(DEFAULT_VIEW_FRACTION); // a box not laid out yet
    });

    it('reads the stored share, and the default for anything else', () => {
        expect(storedFraction({ viewFraction: 0.7 })).toBe(0.7);
        expect(storedFraction({ viewFraction: 2 })).toBe(MAX_FRACTION);
        for (const bad of [undefined, null, 'x', 3, {}, { viewFraction: 'wide' }, { viewFraction: Number.NaN }])
            expect(storedFraction(bad)).toBe(DEFAULT_VIEW_FRACTION);
        expect(clampFraction(Number.POSITIVE_INFINITY)).toBe(DEFAULT_VIEW_FRACTION);
    });
});

describe('the port table after a run', () => {
    it("says whose values it keeps, with the run's last time", () => {
        expect(lastRunNote('stopped', 12.345)).toMatch(/^Last values of the stopped run \(t 12\.35 s\)/);
        expect(lastRunNote('ended')).toMatch(/^Last values of the run that ended: /);
        expect(lastRunNote('over', Number.NaN)).toMatch(/^Last values of the last run: /);
    });

    it('says why it shows no row', () => {
        expect(emptyText(0, '')).toBe('Port topics appear here during a run.');
        expect(emptyText(3, 'xyz')).toBe('No topic matches the filter.');
        expect(emptyText(3, '  ')).toMatch(/platform topics/);
    });
});
