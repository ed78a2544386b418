import { describe, expect, test } from 'vitest';
import type { AstNode } from 'langium';
import { computeCoverage, coverageShare } from '../src/index.js';

const node = {} as AstNode;
const facts = {
    states: ['Idle', 'Busy', 'Busy.Fetch', 'Busy.Deliver', 'Error'].map((path) => ({ path, node })),
    transitions: [
        { source: 'Idle', target: 'Busy', node },
        { source: 'Busy.Fetch', target: 'Busy.Deliver', node },
        { source: 'Busy', target: 'Idle', node },
        { source: 'Busy', target: 'Idle', node }, // a second one with another guard: one pair
        { source: 'Busy', target: 'Error', node },
        { source: 'Idle', target: 'Idle', node }, // self-loop: not observable
    ],
};

describe('automaton coverage from state traces', () => {
    test('states visited (a substate visits its superstate) and state changes taken', () => {
        const coverage = computeCoverage(facts, [
            ['Idle', 'Idle', 'Busy.Fetch', 'Busy.Deliver'],
            ['Busy.Deliver', 'Idle'],
        ]);
        expect(coverage.states).toEqual([
            { path: 'Idle', visited: true },
            { path: 'Busy', visited: true },
            { path: 'Busy.Fetch', visited: true },
            { path: 'Busy.Deliver', visited: true },
            { path: 'Error', visited: false },
        ]);
        expect(coverage.transitions).toEqual([
            { source: 'Idle', target: 'Busy', taken: true },
            { source: 'Busy.Fetch', target: 'Busy.Deliver', taken: true },
            { source: 'Busy', target: 'Idle', taken: true },
            { source: 'Busy', target: 'Error', taken: false },
        ]);
        expect(coverage.selfLoops).toBe(1);
    });

    test('a change inside a superstate does not take a transition into it', () => {
        const coverage = computeCoverage(facts, [['Busy.Fetch', 'Busy.Deliver']]);
        expect(coverage.transitions.find((t) => t.source === 'Idle' && t.target === 'Busy')?.taken).toBe(false);
    });

    test('no traces: nothing covered', () => {
        const coverage = computeCoverage(facts, []);
        expect(coverage.states.every((s) => !s.visited)).toBe(true);
        expect(coverage.transitions.every((t) => !t.taken)).toBe(true);
    });

    test('the share of points: covered share over the required share, at most 1', () => {
        expect(coverageShare(3, 4, 1)).toBe(0.75);
        expect(coverageShare(3, 4, 0.75)).toBe(1);
        expect(coverageShare(1, 4, 0.5)).toBe(0.5);
        expect(coverageShare(0, 4, 0)).toBe(1);
        expect(coverageShare(0, 0, 1)).toBe(1);
    });
});
