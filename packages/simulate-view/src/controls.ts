/**
 * The panel's tool bar: application and platform choice (the mode follows the platform), the
 * session buttons, the run controls and the speed. It renders what the session state allows;
 * the controller and the run controls attach the actions.
 */
import type { AppInfo } from './contracts.js';
import { el } from './dom.js';
import { defaultPlatform, platformMode, type SimMode } from './logic.js';
import { toolbarState, type SessionState } from './session.js';

const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 5, 10, 0];

function button(label: string, testid: string, title: string): HTMLButtonElement {
    return el('button', { type: 'button', 'data-testid': testid, title, class: 'maa-sim-button' }, label);
}

function modeName(mode: SimMode): string {
    return mode === 'lockstep' ? 'lock-step' : 'ROS 2';
}

/** What the buttons depend on besides the session. */
export interface ControlsContext {
    session: SessionState;
    /** A rosbridge connection to the running simulator exists. */
    connected: boolean;
    /** The simulator reports itself paused. */
    paused: boolean;
    /** The 3D view is shown. */
    viewShown: boolean;
}

export class Controls {
    readonly element: HTMLElement;
    readonly appSelect = el('select', { 'data-testid': 'sim-app', title: 'Application' });
    readonly platformSelect = el('select', { 'data-testid': 'sim-platform', title: 'Platform' });
    readonly startBtn = button('▶ Start', 'sim-start', 'Generate the platform and start the simulation');
    readonly stopBtn = button('■ Stop', 'sim-stop', 'Stop the simulation');
    readonly pauseBtn = button('Pause', 'sim-pause', 'Pause the simulation (/sim/pause)');
    readonly resumeBtn = button('Resume', 'sim-resume', 'Resume the simulation (/sim/resume)');
    readonly stepBtn = button('Step', 'sim-step', 'Advance the simulation by the given number of periods (/sim/step)');
    readonly stepsInput = el('input', {
        type: 'number',
        min: '1',
        max: '100000',
        value: '1',
        'data-testid': 'sim-steps',
        class: 'maa-sim-steps',
        title: 'Periods per step',
    });
    readonly resetBtn = button('Reset', 'sim-reset', 'Back to the initial scene (/sim/reset)');
    readonly reloadViewBtn = button('↻ 3D view', 'sim-reload-view', 'Reload the 3D view');
    readonly speedSelect = el('select', { 'data-testid': 'sim-speed', title: 'Simulation speed (×real time; max = as fast as possible)' });
    private readonly modeLabel = el('span', { class: 'maa-sim-mode', 'data-testid': 'sim-mode' });
    private apps: AppInfo[] = [];

    constructor() {
        for (const s of SPEEDS) this.speedSelect.append(el('option', { value: String(s) }, s === 0 ? 'max' : `${s}×`));
        this.speedSelect.value = '1';
        this.element = el(
            'div',
            { class: 'maa-sim-controls' },
            this.appSelect,
            this.platformSelect,
            this.modeLabel,
            this.startBtn,
            this.stopBtn,
            el('span', { class: 'maa-sim-sep' }),
            this.pauseBtn,
            this.resumeBtn,
            this.stepBtn,
            this.stepsInput,
            this.resetBtn,
            el('label', { class: 'maa-sim-speed' }, 'Speed ', this.speedSelect),
            this.reloadViewBtn,
        );
    }

    /** The applications the selects offer; the chosen one stays chosen when it is still there. */
    setApps(apps: AppInfo[]): void {
        this.apps = apps;
        const previous = this.appSelect.value;
        this.appSelect.replaceChildren(...apps.map((a) => el('option', { value: a.path, title: a.component }, `${a.name} (${a.path})`)));
        if (apps.length === 0) this.appSelect.append(el('option', { value: '' }, 'no application (.arcapp)'));
        if (previous && apps.some((a) => a.path === previous)) this.appSelect.value = previous;
        this.fillPlatforms();
    }

    /** Chooses an application (and, when given, its platform), as a session found running uses. */
    choose(appPath: string, platform?: string): AppInfo | undefined {
        const app = this.apps.find((a) => a.path === appPath);
        if (!app) return undefined;
        this.appSelect.value = app.path;
        this.fillPlatforms();
        if (platform) this.platformSelect.value = platform;
        return app;
    }

    /** The platforms of the chosen application; those that cannot run are disabled. */
    fillPlatforms(): void {
        const app = this.selectedApp();
        this.platformSelect.replaceChildren();
        if (!app) return;
        for (const p of app.platforms) {
            const mode = platformMode(p.kind);
            const o = el('option', { value: p.name }, `${p.name}${mode ? ` (${modeName(mode)})` : ' (cannot run)'}`);
            if (!mode) o.disabled = true;
            this.platformSelect.append(o);
        }
        const def = defaultPlatform(app);
        if (def) this.platformSelect.value = def;
    }

    selectedApp(): AppInfo | undefined {
        return this.apps.find((a) => a.path === this.appSelect.value);
    }

    selectedPlatform(): string {
        return this.platformSelect.value;
    }

    selectedMode(): SimMode | undefined {
        const p = this.selectedApp()?.platforms.find((x) => x.name === this.platformSelect.value);
        return p ? platformMode(p.kind) : undefined;
    }

    speed(): number {
        return Number(this.speedSelect.value);
    }

    /** The periods of one step, clamped to 1..100000. */
    steps(): number {
        return Math.min(100000, Math.max(1, Math.round(Number(this.stepsInput.value) || 1)));
    }

    /** Enables what the session state and the connection allow (session.ts, toolbarState). */
    render(ctx: ControlsContext): void {
        const mode = this.selectedMode();
        const state = toolbarState(ctx.session, { canRun: !!mode, connected: ctx.connected, paused: ctx.paused, viewShown: ctx.viewShown });
        this.startBtn.disabled = !state.start;
        this.startBtn.title = state.start
            ? 'Generate the platform and start the simulation'
            : ctx.session.kind === 'idle'
              ? 'Choose an application and a platform that can run'
              : 'A simulation is starting or running: stop it first';
        this.stopBtn.disabled = !state.stop;
        for (const b of [this.pauseBtn, this.resumeBtn, this.stepBtn, this.resetBtn]) b.disabled = !state.run;
        this.reloadViewBtn.disabled = !state.reloadView;
        this.speedSelect.disabled = !state.choice;
        this.appSelect.disabled = !state.choice;
        this.platformSelect.disabled = !state.choice;
        this.modeLabel.textContent = mode ? modeName(mode) : '';
        this.pauseBtn.hidden = state.showResume;
        this.resumeBtn.hidden = !state.showResume;
    }
}
