// @vitest-environment happy-dom
/**
 * The port table during a replay (happy-dom): a row per topic of the recording, each showing the
 * recorded value at the replay's time cursor ("–" before its first message), and the live table
 * again once cleared for a run.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { Inspector } from '../src/inspector.js';
import { PortMap } from '../src/port-map.js';
import { TimelineStore } from '../src/timeline/store.js';
import { toastTopicMap } from './toast-topics.js';

const map = toastTopicMap([{ instancePath: 'ctrl', node: '/tsr/ctrl' }]);

/** A recording: the lever goes down at 1 s, the distance is first sent at 0.5 s and falls at 2 s. */
function recording(): TimelineStore {
    const store = new TimelineStore();
    store.addAll([
        { t: 0, topic: '/tsr/ctrl/lever_down', message: { data: false } },
        { t: 1, topic: '/tsr/ctrl/lever_down', message: { data: true } },
        { t: 0.5, topic: '/tsr/distance', message: { data: 0.5 } },
        { t: 2, topic: '/tsr/distance', message: { data: 0.125 } },
        { t: 0, topic: '/joint_states', message: { name: ['a'], position: [1] } },
        { t: 0, topic: '/maa/automaton_states', message: { data: '{"/tsr/ctrl":"Idle"}' } },
    ]);
    return store;
}

const notes: string[] = [];
function inspector(): Inspector {
    const i = new Inspector({ sampleTime: () => 0, valuesChanged: () => undefined, notify: (_s, m) => notes.push(m) });
    document.body.append(i.element);
    return i;
}

/** The shown value by port path (or topic), of the rows the table shows. */
function shown(i: Inspector): Record<string, string> {
    const out: Record<string, string> = {};
    for (const tr of i.element.querySelectorAll<HTMLElement>('tbody tr'))
        out[tr.dataset['portPath'] || tr.dataset['topic']!] = tr.querySelector('.maa-port-value-text')?.textContent ?? '';
    return out;
}

const note = (i: Inspector): HTMLElement => i.element.querySelector<HTMLElement>('[data-testid=port-stale]')!;

afterEach(() => {
    document.body.replaceChildren();
    notes.length = 0;
});

describe('the port table follows the replay cursor', () => {
    it('shows each port’s last recorded value at or before the cursor, "–" before its first', () => {
        const store = recording();
        const i = inspector();
        i.showRecording('TR-1.mcap', store.topics(), new PortMap(map));
        expect(i.replaying).toBe(true);
        // the states are not listed (they go to the diagram); platform topics only on request
        expect(Object.keys(shown(i)).sort()).toEqual(['ctrl.leverDown', 'distance']);
        i.showAt(store, 0);
        expect(shown(i)).toEqual({ 'ctrl.leverDown': 'false', distance: '–' });
        i.showAt(store, 1.5);
        expect(shown(i)).toEqual({ 'ctrl.leverDown': 'true', distance: '0.5' });
        i.showAt(store, 2);
        expect(shown(i)).toEqual({ 'ctrl.leverDown': 'true', distance: '0.125' });
        // back in time
        i.showAt(store, 0.75);
        expect(shown(i)).toEqual({ 'ctrl.leverDown': 'false', distance: '0.5' });
        expect(note(i).hidden).toBe(false);
        expect(note(i).textContent).toBe('Recorded values at 0.75 s (replay of TR-1.mcap)');
        // it is no stopped run's table: the controller does not freeze it
        expect(i.stale).toBe(false);
    });

    it('lists the platform topics of the recording when asked, with their recorded values', () => {
        const store = recording();
        const i = inspector();
        i.showRecording('TR-1.mcap', store.topics(), new PortMap(map));
        const platform = i.element.querySelector<HTMLInputElement>('[data-testid=show-platform-topics]')!;
        platform.checked = true;
        platform.dispatchEvent(new Event('change'));
        i.showAt(store, 1);
        expect(shown(i)['/joint_states']).toBe('a=1');
    });

    it('a recording from elsewhere (no port topics known) lists its topics as platform topics', () => {
        const store = recording();
        const i = inspector();
        i.showRecording('other.mcap', store.topics(), undefined);
        i.showAt(store, 1);
        expect(shown(i)).toEqual({});
        expect(i.element.querySelector('.maa-inspector-empty')?.textContent).toMatch(/platform topics/);
    });

    it('a cursor moved outside a replay changes nothing; clearing for a run ends the replay table', () => {
        const store = recording();
        const i = inspector();
        i.showAt(store, 1); // no replay: nothing to show
        expect(shown(i)).toEqual({});
        expect(note(i).hidden).toBe(true);
        i.showRecording('TR-1.mcap', store.topics(), new PortMap(map));
        i.showAt(store, 1);
        i.clear();
        expect(i.replaying).toBe(false);
        expect(shown(i)).toEqual({});
        expect(note(i).hidden).toBe(true);
        i.showAt(store, 2);
        expect(shown(i)).toEqual({});
    });

    it('offers no injection into a recording (a live run does, for a port fed from outside)', () => {
        const store = recording();
        const i = inspector();
        i.update([{ topic: '/tsr/distance', type: 'std_msgs/msg/Float64' }], new PortMap(map));
        expect(i.element.querySelectorAll('[data-testid=inject-input]')).toHaveLength(1);
        i.showRecording('TR-1.mcap', store.topics(), new PortMap(map));
        expect(i.element.querySelectorAll('[data-testid=inject-input]')).toHaveLength(0);
        expect(notes).toEqual([]);
    });
});
