/**
 * The replay's controls: in the tool bar the Record toggle (the next start records), the
 * recordings and the Replay button; below it the time bar of an open replay (play/pause, speed,
 * the time slider, the time shown). Only DOM; replay/session.ts attaches the actions.
 */
import { el } from '../dom.js';
import type { SimRecordingInfo } from './api.js';
import { timeLabel } from './logic.js';

const SPEEDS = [0.25, 0.5, 1, 2, 4, 10];

function button(label: string, testid: string, title: string): HTMLButtonElement {
    return el('button', { type: 'button', 'data-testid': testid, title, class: 'maa-sim-button' }, label);
}

export class ReplayBar {
    readonly recordToggle = el('input', { type: 'checkbox', 'data-testid': 'sim-record' });
    readonly recordLabel = el(
        'label',
        { class: 'maa-sim-record', title: 'Record the next run to recordings/<App>-<time>.mcap (MCAP, opens in Foxglove too)' },
        this.recordToggle,
        ' Record',
    );
    readonly recordingSelect = el('select', { 'data-testid': 'sim-recordings', title: 'Recordings (recordings/ in the workspace)' });
    readonly replayBtn = button(
        'Replay',
        'sim-replay',
        'Open the chosen recording: the 3D scene, the diagram and the panels follow a time slider',
    );
    /** What goes into the tool bar. */
    readonly toolbarItems: HTMLElement[] = [el('span', { class: 'maa-sim-sep' }), this.recordLabel, this.recordingSelect, this.replayBtn];

    readonly playBtn = button('▶', 'replay-play', 'Play / pause');
    readonly speedSelect = el('select', { 'data-testid': 'replay-speed', title: 'Replay speed (×simulated time)' });
    readonly slider = el('input', {
        type: 'range',
        min: '0',
        max: '0',
        // any time (the recording's own resolution); the arrow keys step from event to event (replay/session.ts)
        step: 'any',
        value: '0',
        'data-testid': 'replay-slider',
        title: 'Time (← →: the previous / next recorded message)',
        class: 'maa-replay-slider',
    });
    readonly timeText = el('span', { class: 'maa-replay-time', 'data-testid': 'replay-time' }, timeLabel(undefined, undefined));
    readonly nameText = el('span', { class: 'maa-replay-name', 'data-testid': 'replay-name' });
    readonly closeBtn = button('✕', 'replay-close', 'Close the replay');
    /** The time bar, shown while a replay is open. */
    readonly element = el(
        'div',
        { class: 'maa-replay-bar', 'data-testid': 'replay-bar', hidden: '' },
        this.nameText,
        this.playBtn,
        el('label', { class: 'maa-sim-speed' }, '', this.speedSelect),
        this.slider,
        this.timeText,
        this.closeBtn,
    );

    constructor() {
        for (const s of SPEEDS) this.speedSelect.append(el('option', { value: String(s) }, `${s}×`));
        this.speedSelect.value = '1';
        this.setRecordings([]);
    }

    get speed(): number {
        const v = Number(this.speedSelect.value);
        return Number.isFinite(v) && v > 0 ? v : 1;
    }

    setRecordings(list: readonly SimRecordingInfo[]): void {
        const previous = this.recordingSelect.value;
        this.recordingSelect.replaceChildren(
            ...list.map((r) =>
                el('option', { value: r.name, title: `${r.app ?? '?'} on ${r.platform ?? '?'}, ${(r.size / 1e6).toFixed(1)} MB` }, r.name),
            ),
        );
        if (list.length === 0) this.recordingSelect.append(el('option', { value: '' }, 'no recordings'));
        if (previous && list.some((r) => r.name === previous)) this.recordingSelect.value = previous;
    }

    /** Shows the time bar for a recording spanning `start`..`end`. */
    open(name: string, start: number, end: number): void {
        this.nameText.textContent = name;
        this.slider.min = String(start);
        this.slider.max = String(end);
        this.element.hidden = false;
    }

    close(): void {
        this.element.hidden = true;
        this.setPlaying(false);
    }

    /** Renders the cursor (the slider and the time). */
    show(t: number, end: number): void {
        this.slider.value = String(t);
        this.timeText.textContent = timeLabel(t, end);
    }

    setPlaying(playing: boolean): void {
        this.playBtn.textContent = playing ? '❚❚' : '▶';
        this.playBtn.dataset['playing'] = String(playing);
    }

    /** Replay is offered when a recording is chosen and no run is under way. */
    render(runActive: boolean): void {
        this.replayBtn.disabled = runActive || !this.recordingSelect.value;
        this.recordToggle.disabled = runActive;
    }
}
