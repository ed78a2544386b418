import { describe, expect, it } from 'vitest';
import { modeActivity } from '@maa/diagram-view/schema';
import { parseAutomatonStates } from '@maa/simulate-view/states';

/** A node → instance lookup as the backend's topic map gives it (port-map.ts). */
const nodes = (entries: Record<string, string>) => (node: string) => entries[node];

// The modes of mode components arrive like automaton states (both platforms publish them on
// /maa/automaton_states under the node path of the component's instance).
describe('modes as live states', () => {
    it('map the mode of the root and of a nested mode component to their instance paths', () => {
        const gearbox = parseAutomatonStates(
            { data: JSON.stringify({ '/gearbox': 'Second', '/gearbox/s10': 'Idle' }) },
            nodes({ '/gearbox': '', '/gearbox/s10': 's10' }),
        );
        expect([...gearbox]).toEqual([
            ['', 'Second'],
            ['s10', 'Idle'],
        ]);
        const pair = parseAutomatonStates(
            { data: JSON.stringify({ '/selector_pair/a': 'Slow', '/selector_pair/b': 'Fast' }) },
            nodes({ '/selector_pair/a': 'a', '/selector_pair/b': 'b' }),
        );
        expect(pair.get('a')).toBe('Slow');
        expect(pair.get('b')).toBe('Fast');
    });

    it('light the elements of the current mode and dim the other modes', () => {
        expect(modeActivity('Second', 'Second')).toBe('active');
        expect(modeActivity('First', 'Second')).toBe('inactive');
        // outside modes, or no mode known (no run, or the component is not a mode component)
        expect(modeActivity(undefined, 'Second')).toBe('none');
        expect(modeActivity('First', undefined)).toBe('none');
        expect(modeActivity('', '')).toBe('none');
    });
});

describe('automaton states', () => {
    it('keep the spelling the topic map gives (no guessing from snake case)', () => {
        const states = parseAutomatonStates(
            { data: JSON.stringify({ '/toast_service_robot/toaster_ctrl': 'Toasting', '/toast_service_robot/arm/': 'Outer.Inner' }) },
            nodes({ '/toast_service_robot/toaster_ctrl': 'toasterCtrl', '/toast_service_robot/arm/': 'arm' }),
        );
        expect([...states]).toEqual([
            ['toasterCtrl', 'Toasting'],
            ['arm', 'Outer.Inner'],
        ]);
    });

    it('drop nodes the map does not know, empty states and malformed messages', () => {
        const known = nodes({ '/r/a': 'a' });
        expect([...parseAutomatonStates({ data: JSON.stringify({ '/other/x': 'S', '/r/a': '' }) }, known)]).toEqual([]);
        expect([...parseAutomatonStates({ data: '{not json' }, known)]).toEqual([]);
        expect([...parseAutomatonStates({ data: '["/r/a"]' }, known)]).toEqual([]);
        expect([...parseAutomatonStates(42, known)]).toEqual([]);
        expect([...parseAutomatonStates(JSON.stringify({ '/r/a': 'S' }), known)]).toEqual([['a', 'S']]);
    });
});
