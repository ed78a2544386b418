/**
 * The simulate panel's controller: the session (session.ts) driven by the tool bar's buttons and
 * the backend's answers (start, stop, a session found at mount, one that ends on its own), the
 * run controls over rosbridge (pause, resume, step, reset, speed), and the live connection of a
 * running session (live-run.ts).
 */
import type { AppInfo, Disposable, SimulateHost } from './contracts.js';
import { BackendError, type SimApi, type SimStatusAnswer } from './backend.js';
import type { Controls } from './controls.js';
import { errorText } from './dom.js';
import type { Inspector } from './inspector.js';
import { LiveRun } from './live-run.js';
import { lastRunNote, preparingLine, type RunEnd } from './logic.js';
import { INITIAL_SESSION, idleStatusText, transition, type SessionEvent, type SessionState } from './session.js';
import type { StatusView } from './status-view.js';
import type { LiveTimeline } from './timeline/feed.js';
import type { Viewer } from './viewer.js';

/** Polling `/api/sim/status` while a start request is open (ROS 2: interface build, minutes). */
const START_POLL_MS = 1000;
/** Polling `/api/sim/status` during a run (a session can end on its own). */
const BACKEND_POLL_MS = 2000;

export interface ControllerParts {
    host: SimulateHost;
    controls: Controls;
    status: StatusView;
    inspector: Inspector;
    viewer: Viewer;
    /** The backend's simulation API (backend.ts). */
    api: SimApi;
    /** The rosbridge WebSocket URL (endpoints.ts). */
    rosbridge: string;
    /** The session's timeline (store and panels) a run feeds. */
    timeline?: LiveTimeline;
}

export class SimulationController implements Disposable {
    private session: SessionState = INITIAL_SESSION;
    private run: LiveRun | undefined;
    private backendPoll: ReturnType<typeof setInterval> | undefined;
    private disposed = false;

    constructor(private readonly parts: ControllerParts) {
        const { controls } = parts;
        controls.startBtn.addEventListener('click', () => void this.start());
        controls.stopBtn.addEventListener('click', () => void this.stop());
        controls.reloadViewBtn.addEventListener('click', () => parts.viewer.reload());
        controls.pauseBtn.addEventListener('click', () => void this.run?.control('/sim/pause'));
        controls.resumeBtn.addEventListener('click', () => void this.run?.control('/sim/resume'));
        controls.stepBtn.addEventListener('click', () => void this.run?.control('/sim/step', { steps: controls.steps() }));
        controls.resetBtn.addEventListener('click', () => void this.reset());
        controls.speedSelect.addEventListener('change', () => {
            if (this.session.kind === 'running') void this.run?.control('/sim/set_speed', { speed: controls.speed() });
        });
        controls.appSelect.addEventListener('change', () => {
            controls.fillPlatforms();
            this.render();
        });
        controls.appSelect.addEventListener('focus', () => void this.loadApps());
        controls.platformSelect.addEventListener('change', () => this.render());
        this.render();
    }

    get state(): SessionState {
        return this.session;
    }

    /** The simulation time of the attached run (`undefined`: none, or no clock yet). */
    clockSeconds(): number | undefined {
        return this.run?.clockSeconds;
    }

    /** The values of the diagram are due now (the inspector's watch boxes changed). */
    pushValues(): void {
        this.run?.tick(true);
    }

    /**
     * Starts the chosen application and platform (the commands of a host without the tool bar:
     * the VS Code extension's Start Simulation); false when the panel does not know them.
     */
    async startWith(appPath: string, platform: string): Promise<boolean> {
        await this.loadApps();
        const app = this.parts.controls.choose(appPath, platform);
        if (!app || this.parts.controls.selectedPlatform() !== platform) return false;
        this.render();
        await this.start();
        return true;
    }

    /** Resets the running simulation (`/sim/reset`) and clears the plots; false without a connected run. */
    async reset(): Promise<boolean> {
        if (!this.run?.connected) return false;
        this.parts.inspector.clearSamples();
        await this.run.control('/sim/reset');
        return true;
    }

    /** Lists the applications, then adopts a session the backend already prepares or runs. */
    async mount(): Promise<void> {
        await this.loadApps();
        try {
            await this.adopt(await this.parts.api.status());
        } catch {
            /* backend without a session API: nothing to attach */
        }
    }

    dispose(): void {
        if (this.disposed) return;
        this.disposed = true;
        this.detach();
    }

    private async loadApps(): Promise<void> {
        let apps: AppInfo[];
        try {
            apps = await this.parts.host.apps();
        } catch (e) {
            apps = [];
            this.parts.status.showError(`Could not list the applications: ${errorText(e)}`);
        }
        this.parts.controls.setApps(apps);
        this.render();
    }

    /** Applies an event; a refused one changes nothing (false). */
    private dispatch(event: SessionEvent): boolean {
        const next = transition(this.session, event);
        if (!next) return false;
        this.session = next;
        if (next.kind === 'idle') this.parts.status.set(idleStatusText(next));
        this.render();
        return true;
    }

    private render(): void {
        this.parts.controls.render({
            session: this.session,
            connected: this.run?.connected ?? false,
            paused: this.run?.paused ?? false,
            viewShown: this.parts.viewer.shown,
        });
    }

    async start(): Promise<void> {
        const { controls, status, host } = this.parts;
        const app = controls.selectedApp();
        const mode = controls.selectedMode();
        const platform = controls.selectedPlatform();
        if (!app || !mode || !this.dispatch({ type: 'start' })) return;
        status.showError(undefined);
        const label = `${app.name} on ${platform}`;
        status.set(`Starting ${label} (generating)…`);
        this.detach();
        const stopPolling = this.pollWhileStarting(label);
        try {
            await this.parts.api.start(app.path, platform, mode, controls.speed());
            stopPolling();
            host.notify('info', `Simulation of ${app.name} started (${mode === 'lockstep' ? 'lock-step' : 'ROS 2'})`);
            if (this.dispatch({ type: 'start-succeeded' }) && this.session.kind === 'running') this.attach(app.path, platform);
        } catch (e) {
            stopPolling();
            const cancelled = this.session.kind === 'cancelling';
            let log = e instanceof BackendError ? e.log : [];
            if (log.length === 0) log = await lastLog(this.parts.api);
            this.dispatch({ type: 'start-failed' });
            if (!cancelled) {
                status.showError(`Start failed: ${errorText(e)}`, log);
                host.notify('error', `Simulation start failed: ${errorText(e)}`);
            }
        } finally {
            stopPolling();
        }
    }

    async stop(): Promise<void> {
        const { status, host } = this.parts;
        if (!this.dispatch({ type: 'stop' })) return;
        // the table keeps the values as they are now (ROS 2 nodes leave their topics while they stop)
        this.freezeInspector('stopped');
        try {
            await this.parts.api.stop();
            host.notify('info', 'Simulation stopped');
        } catch (e) {
            status.showError(`Stop failed: ${errorText(e)}`, e instanceof BackendError ? e.log : []);
        } finally {
            this.detach();
            this.dispatch({ type: 'stop-finished' });
            if (this.session.kind === 'cancelling') status.set('Stopped');
        }
    }

    /** A session found at mount: a start still preparing (another window, or before a reload), or a running one. */
    private async adopt(first: SimStatusAnswer): Promise<void> {
        if (first.replay) return; // a replay session: replay/session.ts reattaches to it
        let st = first;
        const app = st.app && (st.preparing || st.running) ? this.parts.controls.choose(st.app, st.platform) : undefined;
        if (st.preparing && !this.disposed && this.dispatch({ type: 'adopt-preparing' })) {
            const stopPolling = this.pollWhileStarting(`${app?.name ?? st.app ?? 'the application'} on ${st.platform ?? '?'}`);
            try {
                while (st.preparing && !this.disposed) {
                    await new Promise((r) => setTimeout(r, START_POLL_MS));
                    st = await this.parts.api.status();
                }
            } finally {
                stopPolling();
            }
            if (this.disposed) return;
            const cancelled = this.session.kind === 'cancelling';
            if (st.running) {
                if (this.dispatch({ type: 'start-succeeded' }) && this.session.kind === 'running') this.attachFound(st);
                return;
            }
            this.dispatch({ type: 'start-failed' });
            if (!cancelled && st.log?.length) this.parts.status.showError('The simulation did not start', st.log);
            return;
        }
        if (st.running && !this.disposed && this.dispatch({ type: 'adopt-running' })) {
            this.attachFound(st);
        }
    }

    /**
     * Polls `/api/sim/status` while a start request is open: the status line shows the elapsed
     * time and the last progress line, the progress box the log's last lines (ROS 2 mode prepares
     * its environment first: venv setup, interface package build, docs/ide.md). Returns the stop.
     */
    private pollWhileStarting(label: string): () => void {
        const { status } = this.parts;
        const t0 = Date.now();
        let stopped = false;
        let inFlight = false;
        const tick = async (): Promise<void> => {
            if (stopped || inFlight) return;
            inFlight = true;
            let st: SimStatusAnswer | undefined;
            try {
                st = await this.parts.api.status();
            } catch {
                st = undefined;
            } finally {
                inFlight = false;
            }
            if (stopped || this.disposed) return;
            status.set(preparingLine(label, Math.round((Date.now() - t0) / 1000), st));
            status.showProgress(st?.log ?? []);
        };
        const timer = setInterval(() => void tick(), START_POLL_MS);
        return () => {
            if (stopped) return;
            stopped = true;
            clearInterval(timer);
            status.hideProgress();
        };
    }

    /** Connects to a session found running: its app and platform as the backend reports them. */
    private attachFound(st: SimStatusAnswer): void {
        const { controls } = this.parts;
        this.attach(st.app ?? controls.selectedApp()?.path ?? '', st.platform ?? controls.selectedPlatform());
    }

    /** Connects to the running session: the 3D view, rosbridge, topics, status polling. */
    private attach(app: string, platform: string): void {
        const { host, inspector, status, viewer } = this.parts;
        this.detach();
        inspector.clear(); // the last run's values go
        viewer.show();
        this.run = new LiveRun({
            app,
            platform,
            api: this.parts.api,
            rosbridge: this.parts.rosbridge,
            diagram: host.diagram,
            inspector,
            status,
            running: () => this.session.kind === 'running',
            changed: () => this.render(),
            notify: (severity, message) => host.notify(severity, message),
            ...(this.parts.timeline ? { timeline: this.parts.timeline } : {}),
        });
        this.backendPoll = setInterval(() => void this.pollBackend(), BACKEND_POLL_MS);
        this.render();
    }

    /** Disconnects and clears everything a run showed but the port table's last values (marked as such). */
    private detach(end: RunEnd = 'over'): void {
        if (this.backendPoll !== undefined) clearInterval(this.backendPoll);
        this.backendPoll = undefined;
        this.freezeInspector(end);
        this.run?.dispose();
        this.run = undefined;
        this.parts.viewer.hide();
        this.render();
    }

    /** Marks the port table as the last run's (once per run: a stop freezes it before the detach). */
    private freezeInspector(end: RunEnd): void {
        const { inspector } = this.parts;
        if (!this.run || inspector.stale) return;
        inspector.freeze(lastRunNote(end, this.run.clockSeconds));
    }

    /** A session that ended on its own (the simulator exited): its exit code and log are shown. */
    private async pollBackend(): Promise<void> {
        if (this.session.kind !== 'running') return;
        let st: SimStatusAnswer;
        try {
            st = await this.parts.api.status();
        } catch {
            return;
        }
        if (st.running || this.session.kind !== 'running') return;
        this.detach('ended');
        this.dispatch({ type: 'ended', exitCode: st.exitCode });
        if (st.exitCode) this.parts.status.showError(`The simulation ended with exit code ${st.exitCode}`, st.log ?? []);
    }
}

/** The backend's log of the last session (for a failed start whose answer had none). */
async function lastLog(api: SimApi): Promise<string[]> {
    try {
        return (await api.status()).log ?? [];
    } catch {
        return [];
    }
}
