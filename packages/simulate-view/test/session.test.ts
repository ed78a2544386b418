import { describe, expect, it } from 'vitest';
import {
    INITIAL_SESSION,
    SESSION_EVENT_TYPES,
    accepts,
    idleStatusText,
    isBusy,
    transition,
    type SessionEvent,
    type SessionEventType,
    type SessionState,
} from '../src/session.js';

const idle = (reason: 'initial' | 'stopped' | 'cancelled' | 'failed' | 'ended' = 'initial'): SessionState => ({ kind: 'idle', reason });
const starting: SessionState = { kind: 'starting', adopted: false };
const adoptedStarting: SessionState = { kind: 'starting', adopted: true };
const cancellingOpen: SessionState = { kind: 'cancelling', adopted: false, stopOpen: true };
const cancellingAnswered: SessionState = { kind: 'cancelling', adopted: false, stopOpen: false };
const running: SessionState = { kind: 'running' };
const stopping: SessionState = { kind: 'stopping' };

const ev = (type: SessionEventType): SessionEvent => ({ type });

/** Every allowed transition: state, event, next state. Everything not listed is refused. */
const ALLOWED: [string, SessionState, SessionEvent, SessionState][] = [
    ['idle: start', idle(), ev('start'), starting],
    ['idle: a start found preparing at mount', idle(), ev('adopt-preparing'), adoptedStarting],
    ['idle: a session found running at mount', idle(), ev('adopt-running'), running],
    ['idle after a stop: start again', idle('stopped'), ev('start'), starting],
    ['starting: the start answers', starting, ev('start-succeeded'), running],
    ['starting: the start fails', starting, ev('start-failed'), idle('failed')],
    ['starting: stop cancels', starting, ev('stop'), cancellingOpen],
    ['adopted starting: stop keeps the origin', adoptedStarting, ev('stop'), { kind: 'cancelling', adopted: true, stopOpen: true }],
    ['adopted starting: runs', adoptedStarting, ev('start-succeeded'), running],
    ['adopted starting: did not start', adoptedStarting, ev('start-failed'), idle('failed')],
    ['cancelling: the stop answers first', cancellingOpen, ev('stop-finished'), cancellingAnswered],
    ['cancelling: the start fails while the stop is open', cancellingOpen, ev('start-failed'), stopping],
    ['cancelling: the start got through while the stop is open', cancellingOpen, ev('start-succeeded'), stopping],
    ['cancelled: the start fails (409)', cancellingAnswered, ev('start-failed'), idle('cancelled')],
    ['cancelled: the start got through after all', cancellingAnswered, ev('start-succeeded'), running],
    ['cancelling: stop again once the first stop answered', cancellingAnswered, ev('stop'), cancellingOpen],
    ['running: restart', running, ev('start'), starting],
    ['running: stop', running, ev('stop'), stopping],
    ['running: the session ends', running, { type: 'ended', exitCode: 3 }, { kind: 'idle', reason: 'ended', exitCode: 3 }],
    ['stopping: the stop answers', stopping, ev('stop-finished'), idle('stopped')],
];

const STATES: [string, SessionState][] = [
    ['idle', idle()],
    ['starting', starting],
    ['adopted starting', adoptedStarting],
    ['cancelling (stop open)', cancellingOpen],
    ['cancelling (stop answered)', cancellingAnswered],
    ['running', running],
    ['stopping', stopping],
];

describe('simulation session state machine', () => {
    it('starts idle', () => {
        expect(INITIAL_SESSION).toEqual({ kind: 'idle', reason: 'initial' });
    });

    for (const [name, from, event, to] of ALLOWED) {
        it(`allows ${name}`, () => {
            expect(transition(from, event)).toEqual(to);
            expect(accepts(from, event.type)).toBe(true);
        });
    }

    describe('refuses every other event', () => {
        for (const [name, state] of STATES) {
            const allowed = new Set(ALLOWED.filter(([, from]) => JSON.stringify(from) === JSON.stringify(state)).map(([, , e]) => e.type));
            for (const type of SESSION_EVENT_TYPES.filter((t) => !allowed.has(t))) {
                it(`${name} refuses ${type}`, () => {
                    expect(transition(state, ev(type))).toBeUndefined();
                    expect(accepts(state, type)).toBe(false);
                });
            }
        }
    });

    it('lists every state once in the refusal table and every event type', () => {
        expect(new Set(STATES.map(([, s]) => s.kind))).toEqual(new Set(['idle', 'starting', 'cancelling', 'running', 'stopping']));
        expect(new Set(ALLOWED.map(([, , e]) => e.type))).toEqual(new Set(SESSION_EVENT_TYPES));
    });

    it('does not change the state it is given', () => {
        const state: SessionState = { kind: 'cancelling', adopted: true, stopOpen: true };
        const copy = { ...state };
        transition(state, ev('stop-finished'));
        expect(state).toEqual(copy);
    });

    it('a refused event leaves a full run as it was: double start, stop without a session', () => {
        let s: SessionState = INITIAL_SESSION;
        const apply = (e: SessionEvent): void => {
            s = transition(s, e) ?? s;
        };
        apply(ev('stop'));
        expect(s).toEqual(INITIAL_SESSION);
        apply(ev('start'));
        apply(ev('start'));
        expect(s).toEqual(starting);
        apply(ev('start-succeeded'));
        apply(ev('stop'));
        apply(ev('stop'));
        expect(s).toEqual(stopping);
        apply(ev('ended'));
        expect(s).toEqual(stopping);
        apply(ev('stop-finished'));
        expect(s).toEqual(idle('stopped'));
    });

    it('is busy exactly while a request is open', () => {
        expect(STATES.filter(([, s]) => isBusy(s)).map(([n]) => n)).toEqual([
            'starting',
            'adopted starting',
            'cancelling (stop open)',
            'cancelling (stop answered)',
            'stopping',
        ]);
    });

    it('says why it is idle', () => {
        expect(idleStatusText({ kind: 'idle', reason: 'initial' })).toBe('Not running');
        expect(idleStatusText({ kind: 'idle', reason: 'failed' })).toBe('Not running');
        expect(idleStatusText({ kind: 'idle', reason: 'stopped' })).toBe('Stopped');
        expect(idleStatusText({ kind: 'idle', reason: 'cancelled' })).toBe('Start cancelled');
        expect(idleStatusText({ kind: 'idle', reason: 'ended', exitCode: 2 })).toBe('Simulation ended (exit code 2)');
        expect(idleStatusText({ kind: 'idle', reason: 'ended', exitCode: null })).toBe('Simulation ended');
        expect(idleStatusText({ kind: 'idle', reason: 'ended' })).toBe('Simulation ended');
    });
});
