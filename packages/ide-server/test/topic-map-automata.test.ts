import { describe, expect, it } from 'vitest';
import { automataTable, inWorkspace } from '../src/topic-map.js';

/** The automata table of a timesync app module (`AUTOMATA`, one JSON entry a line), as the backend reads it. */
const entry = {
    instancePath: 'ctrl',
    node: '/robot/ctrl',
    component: 'p.Ctrl',
    file: 'p/Ctrl.arc',
    states: [
        { path: 'A', line: 3 },
        { path: 'A.B', line: 4 },
    ],
    transitions: [{ index: 0, from: 'A', to: 'A.B', label: '[x > 0] / { y = 1; }', line: 6, column: 5 }],
};
const module = (lines: string[]) =>
    ['PORT_TOPICS: dict[str, tuple[str, str]] = {', '}', 'AUTOMATA: dict[str, str] = {', ...lines, '}', ''].join('\n');
const line = (key: string, value: unknown) => `    ${JSON.stringify(key)}: ${JSON.stringify(JSON.stringify(value))},`;

describe('the automata table of a timesync app module', () => {
    it('reads every entry, escapes and all', () => {
        expect(automataTable(module([line('ctrl', entry)]))).toEqual([entry]);
        expect(inWorkspace([entry], 'apps/robot')[0]?.file).toBe('apps/robot/p/Ctrl.arc');
        expect(inWorkspace([entry], '')[0]?.file).toBe('p/Ctrl.arc');
    });

    it('is empty for a build generated before the table existed', () => {
        expect(automataTable('PORT_TOPICS: dict[str, tuple[str, str]] = {\n}\n')).toEqual([]);
    });

    it('refuses an entry that is no JSON or breaks the contract, naming the instance', () => {
        expect(() => automataTable(module(['    "ctrl": "{not json",']))).toThrow(/AUTOMATA entry of ctrl is no JSON/);
        expect(() => automataTable(module([line('ctrl', { ...entry, node: 'ctrl' })]))).toThrow(
            /AUTOMATA entry of ctrl is invalid: \/node/,
        );
        expect(() => automataTable(module([line('ctrl', { ...entry, transitions: [{ index: -1 }] })]))).toThrow(/invalid/);
    });
});
