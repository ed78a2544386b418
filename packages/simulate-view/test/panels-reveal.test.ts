import { describe, expect, it } from 'vitest';
import { parseFromWebview } from '../src/host-messages.js';
import { automatonOf, revealProgramStep, revealTransition } from '../src/panels/reveal.js';
import type { AutomatonInfo } from '../src/timeline/automata.js';

const CTRL = '/toast_service_robot/ctrl';
const automata: AutomatonInfo[] = [
    {
        instancePath: 'ctrl',
        node: CTRL,
        component: 'toast.Controller',
        file: 'toast-service/Controller.arc',
        states: [
            { path: 'Toasting', line: 7 },
            { path: 'Serving', line: 8 },
            { path: 'Done', line: 9 },
        ],
        transitions: [{ index: 3, from: 'Toasting', to: 'Serving', label: '[color == GOLDEN]', line: 20, column: 9 }],
    },
];

describe('the reveal of a selected transition', () => {
    it('names the transition line and the highlight, for an event with its index', () => {
        const m = revealTransition(automata, { t: 2, node: CTRL, from: 'Toasting', to: 'Serving', index: 3, origin: 'event' });
        expect(m).toEqual({
            type: 'reveal',
            file: 'toast-service/Controller.arc',
            line: 20,
            column: 9,
            highlight: {
                component: 'toast.Controller',
                instancePath: 'ctrl',
                state: 'Serving',
                transition: { from: 'Toasting', to: 'Serving', index: 3 },
            },
        });
        // what the panel sends is what the extension accepts
        expect(parseFromWebview(m)).toEqual(m);
    });

    it('finds a derived transition by its states', () => {
        expect(revealTransition(automata, { t: 2, node: CTRL, from: 'Toasting', to: 'Serving', origin: 'derived' })?.line).toBe(20);
    });

    it("falls back to the target state's line when the table lists no such transition", () => {
        const m = revealTransition(automata, { t: 2, node: CTRL, from: 'Serving', to: 'Done', origin: 'derived' });
        expect(m?.line).toBe(9);
        expect(m?.column).toBeUndefined();
        expect(m?.highlight).toEqual({ component: 'toast.Controller', instancePath: 'ctrl', state: 'Done' });
    });

    it('reveals nothing for a node or state the table does not know', () => {
        expect(revealTransition(automata, { t: 2, node: '/other', from: 'A', to: 'B', origin: 'derived' })).toBeUndefined();
        expect(revealTransition(automata, { t: 2, node: CTRL, from: 'X', to: 'Y', origin: 'derived' })).toBeUndefined();
        expect(revealTransition([], { t: 2, node: CTRL, from: 'Toasting', to: 'Serving', origin: 'derived' })).toBeUndefined();
        expect(automatonOf(automata, '/other')).toBeUndefined();
    });

    it('reveals a program step only when it names its file', () => {
        const step = { t: 1, node: '/r/arm', program: 'serve', step: 0, line: 4, text: 'open();' };
        expect(revealProgramStep(step)).toBeUndefined();
        expect(revealProgramStep({ ...step, file: 'toast-service/serve.rap' })).toEqual({
            type: 'reveal',
            file: 'toast-service/serve.rap',
            line: 4,
        });
    });
});
