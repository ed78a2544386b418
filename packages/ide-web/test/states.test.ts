import { describe, expect, it } from 'vitest';
import { modeActivity } from '../src/diagram/schema.js';
import { parseAutomatonStates } from '../src/simulate/states.js';

// The modes of mode components arrive like automaton states (both platforms publish them on
// /maa/automaton_states under the node path of the component's instance).
describe('modes as live states', () => {
    it('map the mode of the root and of a nested mode component to their instance paths', () => {
        const gearbox = parseAutomatonStates({ data: JSON.stringify({ '/gearbox': 'Second', '/gearbox/s10': 'Idle' }) }, 'gear.Gearbox');
        expect([...gearbox]).toEqual([
            ['', 'Second'],
            ['s10', 'Idle'],
        ]);
        const pair = parseAutomatonStates(
            { data: JSON.stringify({ '/selector_pair/a': 'Slow', '/selector_pair/b': 'Fast' }) },
            'pick.SelectorPair',
            ['a', 'b', 'a.g1', 'b.g10'],
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
