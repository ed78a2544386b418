import { describe, expect, it } from 'vitest';
import { setBreakpointsContract } from '@maa/protocol';
import { breakpointOfStatus, breakpointRows, breakpointsRequest, describeHit, rowKeyOf } from '../src/breakpoints/model.js';
import { parseAutomata } from '../src/timeline/automata.js';

const CTRL = '/toast_service_robot/ctrl';
const TOASTER = '/toast_service_robot/toaster_ctrl';
// the example's automata table as GET /api/sim/topics serves it (generators-python's AUTOMATA)
const automata = parseAutomata({
    automata: [
        {
            instancePath: 'ctrl',
            node: CTRL,
            component: 'toast.Controller',
            file: 'toast-service/toast/Controller.arc',
            states: ['Idle', 'Loading', 'Toasting', 'Serving'].map((path, i) => ({ path, line: 16 + i })),
            transitions: [
                { index: 0, from: 'Idle', to: 'Loading', label: '[distance < threshold]', line: 22, column: 5 },
                { index: 2, from: 'Toasting', to: 'Serving', label: '[color == ToastColor.GOLDEN]', line: 24, column: 5 },
            ],
        },
        {
            instancePath: 'toasterCtrl',
            node: TOASTER,
            component: 'toast.ToasterController',
            file: 'toast-service/toast/ToasterController.arc',
            states: [
                { path: 'Off', line: 13 },
                { path: 'On', line: 14 },
            ],
            transitions: [
                { index: 2, from: 'On', to: 'Off', label: '[cmd == ToasterCmd.STOP]', line: 23, column: 5 },
                { index: 3, from: 'On', to: 'Off', label: '[slices >= maxSlices]', line: 24, column: 5 },
            ],
        },
    ],
});

describe('the breakpoints list', () => {
    it('lists the states and transitions of every automaton; transitions between the same states share a row', () => {
        const rows = breakpointRows(automata);
        expect(rows.map((a) => a.instancePath)).toEqual(['ctrl', 'toasterCtrl']);
        expect(rows[0]!.states.map((r) => r.text)).toEqual(['Idle', 'Loading', 'Toasting', 'Serving']);
        expect(rows[0]!.transitions.map((r) => [r.text, r.id])).toEqual([
            ['Idle → Loading', 'transition-0'],
            ['Toasting → Serving', 'transition-2'],
        ]);
        expect(rows[1]!.transitions).toHaveLength(1);
        expect(rows[1]!.transitions[0]!.detail).toBe('[cmd == ToasterCmd.STOP]; [slices >= maxSlices]');
        expect(breakpointRows([])).toEqual([]);
    });

    it('sends the checked rows as a request that keeps the SetBreakpoints contract', () => {
        const rows = breakpointRows(automata);
        const request = breakpointsRequest(rows, new Set(['ctrl|Toasting|Serving', 'toasterCtrl|state|On', 'gone|state|X']));
        expect(request).toEqual({
            breakpoints: [
                { node: CTRL, from: 'Toasting', to: 'Serving' },
                { node: TOASTER, state: 'On' },
            ],
        });
        expect(setBreakpointsContract.issues(request)).toEqual([]);
        expect(breakpointsRequest(rows, new Set())).toEqual({ breakpoints: [] });
    });

    it('reads the breakpoint a status names and marks its row', () => {
        const rows = breakpointRows(automata);
        const bp = breakpointOfStatus({ paused: true, breakpoint: { node: CTRL, from: 'Toasting', to: 'Serving' } });
        expect(bp).toEqual({ node: CTRL, from: 'Toasting', to: 'Serving' });
        expect(rowKeyOf(rows, bp!)).toBe('ctrl|Toasting|Serving');
        expect(describeHit(rows, bp!)).toBe('Paused at breakpoint ctrl: Toasting → Serving');
        const state = breakpointOfStatus({ values: { breakpoint: { node: TOASTER, state: 'On' } } });
        expect(rowKeyOf(rows, state!)).toBe('toasterCtrl|state|On');
        expect(rowKeyOf(rows, { node: '/other', state: 'On' })).toBeUndefined();
    });

    it('reads no breakpoint from a status without one or with a malformed one', () => {
        for (const status of [
            undefined,
            null,
            'paused',
            {},
            { breakpoint: null },
            { breakpoint: { state: 'On' } },
            { breakpoint: { node: CTRL, from: 'A' } },
        ])
            expect(breakpointOfStatus(status)).toBeUndefined();
    });
});
