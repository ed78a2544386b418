import { describe, expect, it } from 'vitest';
import { setBreakpointsContract } from '@maa/protocol';
import { breakpointRows, breakpointsRequest, describeHit } from '../src/breakpoints/model.js';
import { findTransition, instanceLabel, parseAutomata } from '../src/timeline/automata.js';

// The automata table entry of a decomposed component's mode automaton (generators-python's
// AUTOMATA / deployment.json of the modes fixture: the root gear.Gearbox): its modes are the
// states, its mode transitions the transitions, and the panels and breakpoints take it as any automaton.
const GEARBOX = '/gearbox';
const automata = parseAutomata({
    automata: [
        {
            instancePath: '',
            node: GEARBOX,
            component: 'gear.Gearbox',
            file: 'gear/Gearbox.arc',
            states: [
                { path: 'First', line: 10 },
                { path: 'Second', line: 15 },
            ],
            transitions: [
                { index: 0, from: 'First', to: 'Second', label: '[speed < 0]', line: 22, column: 5 },
                { index: 1, from: 'Second', to: 'First', label: '[speed == 0]', line: 23, column: 5 },
            ],
            kind: 'modes',
        },
    ],
});

describe('a mode automaton in the simulate view', () => {
    it('is parsed like an automaton, and a /maa/transitions event finds its mode transition and source line', () => {
        expect(automata).toHaveLength(1);
        expect(automata[0]!.states.map((s) => s.path)).toEqual(['First', 'Second']);
        expect(findTransition(automata[0], { from: 'Second', to: 'First', index: 1 })).toMatchObject({ line: 23, column: 5 });
        // an index the table does not have falls back to the modes; unknown modes find nothing
        expect(findTransition(automata[0], { from: 'First', to: 'Second', index: 7 })?.index).toBe(0);
        expect(findTransition(automata[0], { from: 'First', to: 'Third', index: 9 })).toBeUndefined();
    });

    it('lists its modes and mode transitions as breakpoints that keep the SetBreakpoints contract', () => {
        const rows = breakpointRows(automata);
        expect(rows[0]!.states.map((r) => r.text)).toEqual(['First', 'Second']);
        expect(rows[0]!.transitions.map((r) => [r.text, r.id])).toEqual([
            ['First → Second', 'transition-0'],
            ['Second → First', 'transition-1'],
        ]);
        const request = breakpointsRequest(rows, new Set(['|state|Second', '|Second|First']));
        expect(request).toEqual({
            breakpoints: [
                { node: GEARBOX, state: 'Second' },
                { node: GEARBOX, from: 'Second', to: 'First' },
            ],
        });
        expect(setBreakpointsContract.issues(request)).toEqual([]);
        // the root instance (path '') is named as the panels name it
        expect(describeHit(rows, { node: GEARBOX, state: 'Second' })).toBe('Paused at breakpoint (root): Second');
    });

    it('names the root instance (root) and any other by its path, in the list, the panels and the status', () => {
        expect(instanceLabel('')).toBe('(root)');
        expect(instanceLabel('ctrl')).toBe('ctrl');
        expect(instanceLabel('a.b')).toBe('a.b');
    });
});
