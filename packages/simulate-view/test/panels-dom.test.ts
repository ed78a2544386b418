// @vitest-environment happy-dom
/**
 * The panels mounted in a DOM (happy-dom): each panel over a timeline store fed with messages as a
 * lock-step run of the example sends them, what it renders, the shared time cursor, clicking a
 * transition (the reveal it sends), stepping through transitions, the wheel and drag on a plot.
 */
import { AUTOMATON_STATES_TOPIC, PROGRAM_STEPS_TOPIC, TRANSITIONS_TOPIC } from '@maa/protocol';
import { afterEach, describe, expect, it } from 'vitest';
import type { RevealMessage } from '../src/host-messages.js';
import { Panels } from '../src/panels/index.js';
import { MAX_ENTRIES } from '../src/panels/log-panel.js';
import type { AutomatonInfo } from '../src/timeline/automata.js';
import { TimelineStore, type TimedMessage } from '../src/timeline/store.js';

const CTRL = '/toast_service_robot/ctrl';
const ARM = '/toast_service_robot/arm';
const DISTANCE = '/toast_service_robot/distance';
const LEVER = '/toast_service_robot/ctrl/lever_down';

const automata: AutomatonInfo[] = [
    {
        instancePath: 'ctrl',
        node: CTRL,
        component: 'toast.Controller',
        file: 'toast-service/toast/Controller.arc',
        states: [
            { path: 'Idle', line: 6 },
            { path: 'Toasting', line: 7 },
            { path: 'Serving', line: 8 },
        ],
        transitions: [
            { index: 0, from: 'Idle', to: 'Toasting', label: 'start', line: 18, column: 9 },
            { index: 2, from: 'Toasting', to: 'Serving', label: '[color == GOLDEN]', line: 20, column: 9 },
        ],
    },
];

const json = (o: unknown) => ({ data: JSON.stringify(o) });

/** 4 s of a run: ctrl goes Idle → Toasting (1 s) → Serving (2.5 s); the distance every 0.1 s; two program steps of the arm. */
function runMessages(): TimedMessage[] {
    const ms: TimedMessage[] = [
        { t: 0, topic: AUTOMATON_STATES_TOPIC, message: json({ [CTRL]: 'Idle', [ARM]: 'Ready' }) },
        { t: 1, topic: AUTOMATON_STATES_TOPIC, message: json({ [CTRL]: 'Toasting', [ARM]: 'Ready' }) },
        { t: 2.5, topic: AUTOMATON_STATES_TOPIC, message: json({ [CTRL]: 'Serving', [ARM]: 'Moving' }) },
        { t: 1, topic: TRANSITIONS_TOPIC, message: json({ node: CTRL, from: 'Idle', to: 'Toasting', index: 0 }) },
        { t: 2.5, topic: TRANSITIONS_TOPIC, message: json({ node: CTRL, from: 'Toasting', to: 'Serving', index: 2 }) },
        { t: 2.5, topic: TRANSITIONS_TOPIC, message: json({ node: ARM, from: 'Ready', to: 'Moving' }) },
        {
            t: 3,
            topic: PROGRAM_STEPS_TOPIC,
            message: json({ node: ARM, program: 'serve', step: 0, line: 4, text: 'move to plate', file: 'toast-service/serve.rap' }),
        },
        { t: 3.5, topic: PROGRAM_STEPS_TOPIC, message: json({ node: ARM, program: 'serve', step: 1, line: 5, text: 'open' }) },
        { t: 0, topic: LEVER, message: { data: false } },
        { t: 1, topic: LEVER, message: { data: true } },
    ];
    for (let i = 0; i <= 40; i++) ms.push({ t: i / 10, topic: DISTANCE, message: { data: 0.5 - i / 100 } });
    return ms;
}

interface Mounted {
    store: TimelineStore;
    panels: Panels;
    reveals: RevealMessage[];
    /** Waits for the panels' next drawing (they draw at the next animation frame). */
    drawn(): Promise<void>;
    q(testid: string): HTMLElement[];
}

const mounted: Panels[] = [];

function mount(messages: TimedMessage[] = runMessages(), table: AutomatonInfo[] = automata): Mounted {
    const store = new TimelineStore();
    const reveals: RevealMessage[] = [];
    const panels = new Panels(store, { reveal: (m) => reveals.push(m) });
    mounted.push(panels);
    document.body.append(panels.element);
    store.addAll(messages);
    panels.setRunInfo(table, (node) => table.find((a) => a.node === node)?.instancePath);
    return {
        store,
        panels,
        reveals,
        drawn: async () => {
            panels.redraw();
            await new Promise<void>((resolve) => requestAnimationFrame(() => resolve()));
        },
        q: (testid) => [...panels.element.querySelectorAll<HTMLElement>(`[data-testid=${testid}]`)],
    };
}

/** A click as the time-based panels see it: pointer down and up at one place on `target`. */
function click(target: Element): void {
    for (const type of ['pointerdown', 'pointerup'])
        target.dispatchEvent(new PointerEvent(type, { bubbles: true, button: 0, clientX: 10, clientY: 5, pointerId: 1 }));
}

const windowOf = (panels: Panels): number[] => (panels.element.dataset['window'] ?? '').split(' ').map(Number);

afterEach(() => {
    for (const p of mounted.splice(0)) p.dispose();
    document.body.replaceChildren();
});

describe('the state timeline panel', () => {
    it('draws a row per automaton with bands named by state and a mark per transition', async () => {
        const { q, drawn } = mount();
        await drawn();
        const rows = q('states-row');
        expect(rows.map((r) => r.dataset['node'])).toEqual([CTRL, ARM]);
        const bands = [...rows[0]!.querySelectorAll<HTMLElement>('[data-testid=state-band]')].map((b) => b.textContent);
        expect(bands).toEqual(['Idle', 'Toasting', 'Serving']);
        const marks = [...rows[0]!.querySelectorAll<HTMLElement>('[data-testid=transition-mark]')].map(
            (m) => `${m.dataset['from']}→${m.dataset['to']}`,
        );
        expect(marks).toEqual(['Idle→Toasting', 'Toasting→Serving']);
        // the instance path names the row, with the state held at the newest time
        expect(rows[0]!.querySelector('.maa-states-label')?.textContent).toBe('ctrl · Serving');
    });

    it('says so when the store is empty', async () => {
        const { q, drawn, panels } = mount([]);
        await drawn();
        expect(q('states-row')).toHaveLength(0);
        const empty = panels.element.querySelector<HTMLElement>('[data-testid=states-panel] .maa-panel-empty');
        expect(empty?.hidden).toBe(false);
        expect(empty?.textContent).toMatch(/appear here during a run/);
    });

    it('clicking a transition moves the cursor there and sends its reveal (source line, diagram highlight)', async () => {
        const { q, drawn, store, reveals } = mount();
        await drawn();
        click(q('transition-mark').find((m) => m.dataset['to'] === 'Serving')!);
        expect(store.cursor).toBe(2.5);
        expect(reveals).toEqual([
            {
                type: 'reveal',
                file: 'toast-service/toast/Controller.arc',
                line: 20,
                column: 9,
                highlight: {
                    component: 'toast.Controller',
                    instancePath: 'ctrl',
                    state: 'Serving',
                    transition: { from: 'Toasting', to: 'Serving', index: 2 },
                },
            },
        ]);
        await drawn();
        expect(q('states-selected')[0]?.textContent).toBe('ctrl: Toasting → Serving ([color == GOLDEN]) at 2.500 s');
        expect(
            q('transition-mark')
                .find((m) => m.dataset['to'] === 'Serving')
                ?.classList.contains('maa-selected'),
        ).toBe(true);
    });

    it("a click in a row between marks shows that row's transition taken last by then, the cursor staying there", async () => {
        const { q, drawn, store, reveals } = mount();
        await drawn();
        const row = q('states-row').find((r) => r.dataset['node'] === CTRL)!;
        const track = row.querySelector('.maa-states-track')!;
        Object.defineProperty(track, 'getBoundingClientRect', { value: () => ({ left: 0, top: 0, width: 400, height: 20 }) });
        const [t0, t1] = windowOf(mounted[0]!);
        const x = ((3 - t0!) / (t1! - t0!)) * 400;
        for (const type of ['pointerdown', 'pointerup'])
            track.dispatchEvent(new PointerEvent(type, { bubbles: true, button: 0, clientX: x, pointerId: 1 }));
        expect(store.cursor).toBeCloseTo(3, 6);
        // ctrl's Toasting -> Serving at 2.5 s, not the arm's transition at the same time
        expect(reveals.map((r) => [r.line, r.highlight?.state])).toEqual([[20, 'Serving']]);
    });

    it('a transition of an automaton the run does not describe moves the cursor but reveals nothing', async () => {
        const { q, drawn, store, reveals } = mount();
        await drawn();
        const armRow = q('states-row').find((r) => r.dataset['node'] === ARM)!;
        click(armRow.querySelector('[data-testid=transition-mark]')!);
        expect(store.cursor).toBe(2.5);
        expect(reveals).toEqual([]);
        await drawn();
        // named by its node: the run's table does not know it
        expect(q('states-selected')[0]?.textContent).toBe(`${ARM}: Ready → Moving at 2.500 s`);
    });

    it('steps to the next and previous transition of the selected component, and stops at either end', async () => {
        const { q, drawn, store, reveals } = mount();
        await drawn();
        const [prev, next] = [q('transition-prev')[0]!, q('transition-next')[0]!];
        next.click(); // nothing selected, no cursor: from the newest time there is no later one
        expect(store.cursor).toBeUndefined();
        store.cursor = 0.5;
        next.click();
        expect(store.cursor).toBe(1);
        next.click();
        expect(store.cursor).toBe(2.5);
        next.click(); // the last one: stays
        expect(store.cursor).toBe(2.5);
        prev.click();
        expect(store.cursor).toBe(1);
        expect(reveals.map((r) => r.line)).toEqual([18, 20, 18]);
        await drawn();
        expect(q('states-selected')[0]?.textContent).toMatch(/^ctrl: Idle → Toasting/);
    });
});

describe('the plots panel', () => {
    it('offers the topics with numeric values and draws a chosen series with its value at the cursor', async () => {
        const { panels, q, drawn, store } = mount();
        panels.show('plots');
        await drawn();
        const topic = q('plot-topic')[0] as HTMLSelectElement;
        const topics = [...topic.options].map((o) => o.value);
        expect(topics).toContain(DISTANCE);
        expect(topics).toContain(LEVER);
        // JSON strings (the states, the transitions) are no numbers
        expect(topics).not.toContain(AUTOMATON_STATES_TOPIC);
        topic.value = DISTANCE;
        topic.dispatchEvent(new Event('change'));
        const field = q('plot-field')[0] as HTMLSelectElement;
        expect([...field.options].map((o) => o.value)).toEqual(['data']);
        field.value = 'data'; // happy-dom selects no option of a filled select by itself
        q('plot-add-series')[0]!.click();
        store.cursor = 2;
        await drawn();
        const line = panels.element.querySelector('.maa-plot-line');
        expect(line?.getAttribute('d')).toMatch(/^M /);
        expect(panels.element.querySelector('.maa-plot-cursor')).not.toBeNull();
        expect(q('plot-series-value')[0]?.textContent).toBe('0.3');
        // the axis is labelled in simulated seconds
        expect(panels.element.querySelectorAll('.maa-plot-tick').length).toBeGreaterThan(1);
    });

    it('offers nothing and draws no line over an empty store', async () => {
        const { panels, q, drawn } = mount([]);
        panels.show('plots');
        await drawn();
        expect((q('plot-topic')[0] as HTMLSelectElement).options).toHaveLength(0);
        q('plot-add-series')[0]!.click(); // no topic chosen: no series
        await drawn();
        expect(q('plot-series')).toHaveLength(0);
        expect(panels.element.querySelector('.maa-plot-line')).toBeNull();
    });

    it('a click on a point of a plot sets the cursor there and shows the transition taken last by then', async () => {
        const { panels, drawn, store, reveals } = mount();
        panels.show('plots');
        await drawn();
        const drawing = panels.element.querySelector('svg.maa-plot-svg')!;
        Object.defineProperty(drawing, 'getBoundingClientRect', { value: () => ({ left: 0, top: 0, width: 400, height: 140 }) });
        const [t0, t1] = windowOf(panels);
        const xAt = (t: number) => ((t - t0!) / (t1! - t0!)) * 400;
        // at 2 s: ctrl went Idle -> Toasting at 1 s, the arm has not moved yet
        for (const type of ['pointerdown', 'pointerup'])
            drawing.dispatchEvent(new PointerEvent(type, { bubbles: true, button: 0, clientX: xAt(2), pointerId: 1 }));
        expect(store.cursor).toBeCloseTo(2, 6);
        expect(reveals.map((r) => [r.line, r.highlight?.transition])).toEqual([[18, { from: 'Idle', to: 'Toasting', index: 0 }]]);
        // before any transition: the cursor moves, nothing is shown
        for (const type of ['pointerdown', 'pointerup'])
            drawing.dispatchEvent(new PointerEvent(type, { bubbles: true, button: 0, clientX: xAt(0.5), pointerId: 1 }));
        expect(store.cursor).toBeCloseTo(0.5, 6);
        expect(reveals).toHaveLength(1);
    });

    it('the wheel zooms the time window (and keeps the page from scrolling), a drag pans it', async () => {
        const { panels, drawn } = mount();
        panels.show('plots');
        await drawn();
        const [t0, t1] = windowOf(panels);
        const drawing = panels.element.querySelector('svg.maa-plot-svg')!;
        const wheel = new WheelEvent('wheel', { deltaY: -300, clientX: 0, bubbles: true, cancelable: true });
        drawing.dispatchEvent(wheel);
        expect(wheel.defaultPrevented).toBe(true);
        await drawn();
        const [z0, z1] = windowOf(panels);
        expect(z1! - z0!).toBeCloseTo((t1! - t0!) * Math.exp(-1), 6);
        // a wheel down zooms out again
        drawing.dispatchEvent(new WheelEvent('wheel', { deltaY: 300, clientX: 0, bubbles: true, cancelable: true }));
        await drawn();
        const [o0, o1] = windowOf(panels);
        expect(o1! - o0!).toBeCloseTo(t1! - t0!, 6);
        // a drag (the drawing has no layout here: its width is the 50 px fallback of getBoundingClientRect's 0) pans
        Object.defineProperty(drawing, 'getBoundingClientRect', { value: () => ({ left: 0, top: 0, width: 400, height: 140 }) });
        drawing.dispatchEvent(new PointerEvent('pointerdown', { bubbles: true, button: 0, clientX: 300, pointerId: 1 }));
        drawing.dispatchEvent(new PointerEvent('pointermove', { bubbles: true, clientX: 200, pointerId: 1 }));
        drawing.dispatchEvent(new PointerEvent('pointerup', { bubbles: true, button: 0, clientX: 200, pointerId: 1 }));
        await drawn();
        const [p0, p1] = windowOf(panels);
        expect(p0! - o0!).toBeCloseTo((o1! - o0!) / 4, 6);
        expect(p1! - p0!).toBeCloseTo(o1! - o0!, 6);
    });
});

describe('the messages panel', () => {
    it('lists the topics with their counts and the messages around the cursor, the one in effect marked', async () => {
        const { panels, q, drawn, store } = mount();
        panels.show('messages');
        store.cursor = 2.05;
        await drawn();
        const topics = q('messages-topic');
        expect(topics.map((b) => b.dataset['topic'])).toEqual(store.topics());
        q('messages-topic')
            .find((b) => b.dataset['topic'] === DISTANCE)!
            .click();
        await drawn();
        expect(q('messages-topic').find((b) => b.dataset['topic'] === DISTANCE)?.textContent).toBe(`${DISTANCE}41`);
        const current = q('message-current');
        expect(current).toHaveLength(1);
        expect(current[0]?.textContent).toMatch(/^2\.000 s/);
        // three before and three after the current one: a window, not the whole history
        expect(q('message')).toHaveLength(6);
        // clicking another message moves the cursor to it
        q('message').at(-1)!.click();
        expect(store.cursor).toBeCloseTo(2.3, 9);
    });

    it('says that no message of the topic was sent yet before its first one, and shows the empty store', async () => {
        const late: TimedMessage[] = [
            { t: 0, topic: DISTANCE, message: { data: 1 } },
            { t: 5, topic: '/not/a/port', message: { data: 'late' } },
        ];
        const { panels, q, drawn, store } = mount(late);
        panels.show('messages');
        store.cursor = 1;
        await drawn();
        q('messages-topic')
            .find((b) => b.dataset['topic'] === '/not/a/port')!
            .click();
        await drawn();
        expect(q('messages-view')[0]?.textContent).toMatch(/\/not\/a\/port at 1\.000 s \(no message yet\)/);
        expect(q('message-current')).toHaveLength(0);
        expect(q('message')).toHaveLength(1); // the one after the cursor

        const empty = mount([]);
        empty.panels.show('messages');
        await empty.drawn();
        expect(empty.q('messages-topic')).toHaveLength(0);
        expect(empty.q('messages-view')[0]?.textContent).toBe('Messages appear here during a run.');
    });
});

describe('the log panel', () => {
    it('lists transitions and program steps by time; clicking a step moves the cursor and reveals its line', async () => {
        const { panels, q, drawn, store, reveals } = mount();
        panels.show('log');
        await drawn();
        const entries = q('log-entry');
        expect(entries.map((e) => `${e.dataset['kind']} ${e.textContent}`)).toEqual([
            'transition 1.000 sctrlIdle → Toasting',
            'transition 2.500 sctrlToasting → Serving',
            `transition 2.500 s${ARM}Ready → Moving`,
            `step 3.000 s${ARM}serve step 1: move to plate (line 4)`,
            `step 3.500 s${ARM}serve step 2: open (line 5)`,
        ]);
        expect(q('log-dropped')[0]?.hidden).toBe(true);
        entries[3]!.click();
        expect(store.cursor).toBe(3);
        expect(reveals).toEqual([{ type: 'reveal', file: 'toast-service/serve.rap', line: 4 }]);
        // a step whose event names no file reveals nothing
        entries[4]!.click();
        expect(store.cursor).toBe(3.5);
        expect(reveals).toHaveLength(1);
    });

    it('says how many entries it leaves out beyond the newest ones', async () => {
        const many: TimedMessage[] = [];
        for (let i = 0; i < MAX_ENTRIES + 20; i++)
            many.push({ t: i, topic: AUTOMATON_STATES_TOPIC, message: json({ [CTRL]: i % 2 ? 'Toasting' : 'Idle' }) });
        const { panels, q, drawn } = mount(many);
        panels.show('log');
        await drawn();
        expect(q('log-entry')).toHaveLength(MAX_ENTRIES);
        const note = q('log-dropped')[0]!;
        expect(note.hidden).toBe(false);
        // 520 state messages: 519 changes
        expect(note.textContent).toBe(`showing the newest ${MAX_ENTRIES} of ${MAX_ENTRIES + 19} entries`);
    });

    it('shows the empty log of an empty store', async () => {
        const { panels, q, drawn } = mount([]);
        panels.show('log');
        await drawn();
        expect(q('log-entry')).toHaveLength(0);
        expect(q('log-dropped')[0]?.hidden).toBe(true);
    });
});

describe('the shared time cursor', () => {
    it('every panel shows the cursor; Live follows the newest data again', async () => {
        const { panels, q, drawn, store } = mount();
        store.cursor = 1.5;
        await drawn();
        expect(q('panels-time')[0]?.textContent).toBe('cursor 1.500 s');
        expect(panels.element.querySelector('.maa-states-cursor')).not.toBeNull();
        // the state held at the cursor
        expect(q('states-row')[0]?.querySelector('.maa-states-label')?.textContent).toBe('ctrl · Toasting');
        panels.show('plots');
        await drawn();
        expect(panels.element.querySelector('.maa-plot-cursor')).not.toBeNull();
        (q('panels-live')[0] as HTMLButtonElement).click();
        expect(store.cursor).toBeUndefined();
        await drawn();
        expect(q('panels-time')[0]?.textContent).toBe('live 4.000 s');
        expect(panels.element.querySelector('.maa-plot-cursor')).toBeNull();
        expect((q('panels-live')[0] as HTMLButtonElement).disabled).toBe(true);
    });

    it('a cursor that is no number is refused, the panels keep what they show', async () => {
        const { q, drawn, store } = mount();
        store.cursor = 2;
        store.cursor = Number.NaN;
        await drawn();
        expect(store.cursor).toBe(2);
        expect(q('panels-time')[0]?.textContent).toBe('cursor 2.000 s');
    });
});
