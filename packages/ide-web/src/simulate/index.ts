/**
 * The simulate panel: `mountSimulatePanel(container, host)` (contracts.ts). Starts and stops a
 * simulation session through the backend, drives it through the simulator's rosbridge services
 * (docs/simulation.md) over the proxied rosbridge, embeds the viser view, and offers a port
 * inspector with live values, plots and input injection. During a run the diagram shows the
 * port values and the active automaton states.
 */
import './simulate.css';
import type { AppInfo, Disposable, SimulateHost } from '../contracts.js';
import { RosConnection, rosbridgeUrl, type TopicInfo } from '../ros/index.js';
import { BackendError, simApi, type SimStatusAnswer } from './backend.js';
import { clockSeconds, enumLiteralsOf, formatRosValue, isEnumMessage, numericValue, parseInjectedValue, type FormatOptions } from './format.js';
import { defaultPlatform, platformMode, preparingLine, statusLine, unwrapStatus, type SimMode, type SimStatus } from './logic.js';
import { SampleWindow, sparklinePath } from './plot.js';
import { parseAutomatonStates } from './states.js';
import { topicIndex, topicToPort, type PortTopic } from './topics.js';

const AUTOMATON_STATES = '/maa/automaton_states';
const DIAGRAM_PERIOD_MS = 100; // 10 Hz
const STATUS_PERIOD_MS = 1000;
/** Polling `/api/sim/status` while a start request is open (ROS 2: interface build, minutes). */
const START_POLL_MS = 1000;
const TOPICS_PERIOD_MS = 3000;
const SPEEDS = [0.1, 0.25, 0.5, 1, 2, 5, 10, 0];

interface DiagramExtras {
    knownPortPaths?: () => string[];
    knownInstancePaths?: () => string[];
}

function el<K extends keyof HTMLElementTagNameMap>(tag: K, attrs: Record<string, string> = {}, ...children: (Node | string)[]): HTMLElementTagNameMap[K] {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) {
        if (k === 'class') e.className = v;
        else e.setAttribute(k, v);
    }
    e.append(...children);
    return e;
}

const SVG_NS = 'http://www.w3.org/2000/svg';

/** One row of the port inspector. */
interface Row {
    info: TopicInfo;
    port?: PortTopic;
    tr: HTMLTableRowElement;
    watch: HTMLInputElement;
    valueCell: HTMLElement;
    plotPath: SVGPathElement;
    plotCell: HTMLElement;
    samples: SampleWindow;
    last?: unknown;
    lastText?: string;
    dirty: boolean;
    numeric: boolean;
    sub?: Disposable;
}

export function mountSimulatePanel(container: HTMLElement, host: SimulateHost): Disposable {
    container.dataset['testid'] = 'simulate-panel';
    container.classList.add('maa-simulate');

    // --- controls ---------------------------------------------------------------------------------
    const appSelect = el('select', { 'data-testid': 'sim-app', title: 'Application' });
    const platformSelect = el('select', { 'data-testid': 'sim-platform', title: 'Platform' });
    const modeLabel = el('span', { class: 'maa-sim-mode', 'data-testid': 'sim-mode' });
    const btn = (label: string, testid: string, title: string): HTMLButtonElement => {
        const b = el('button', { type: 'button', 'data-testid': testid, title, class: 'maa-sim-button' }, label);
        return b;
    };
    const startBtn = btn('▶ Start', 'sim-start', 'Generate the platform and start the simulation');
    const stopBtn = btn('■ Stop', 'sim-stop', 'Stop the simulation');
    const pauseBtn = btn('Pause', 'sim-pause', 'Pause the simulation (/sim/pause)');
    const resumeBtn = btn('Resume', 'sim-resume', 'Resume the simulation (/sim/resume)');
    const stepBtn = btn('Step', 'sim-step', 'Advance the simulation by the given number of periods (/sim/step)');
    const stepsInput = el('input', { type: 'number', min: '1', max: '100000', value: '1', 'data-testid': 'sim-steps', class: 'maa-sim-steps', title: 'Periods per step' });
    const resetBtn = btn('Reset', 'sim-reset', 'Back to the initial scene (/sim/reset)');
    const reloadViewBtn = btn('↻ 3D view', 'sim-reload-view', 'Reload the 3D view');
    const speedSelect = el('select', { 'data-testid': 'sim-speed', title: 'Simulation speed (×real time; max = as fast as possible)' });
    for (const s of SPEEDS) speedSelect.append(el('option', { value: String(s) }, s === 0 ? 'max' : `${s}×`));
    speedSelect.value = '1';
    const controls = el(
        'div',
        { class: 'maa-sim-controls' },
        appSelect,
        platformSelect,
        modeLabel,
        startBtn,
        stopBtn,
        el('span', { class: 'maa-sim-sep' }),
        pauseBtn,
        resumeBtn,
        stepBtn,
        stepsInput,
        resetBtn,
        el('label', { class: 'maa-sim-speed' }, 'Speed ', speedSelect),
        reloadViewBtn,
    );
    const statusText = el('span', { class: 'maa-sim-status', 'data-testid': 'sim-status' }, 'Not running');
    const errorBox = el('div', { class: 'maa-sim-error', 'data-testid': 'sim-error', hidden: '' });
    const progressLog = el('pre', { class: 'maa-sim-log maa-sim-progress-log', 'data-testid': 'sim-progress-log' });
    const progressBox = el('div', { class: 'maa-sim-progress', 'data-testid': 'sim-progress', hidden: '' }, progressLog);
    const viewer = el('div', { class: 'maa-sim-viewer' });
    const viewerPlaceholder = el('div', { class: 'maa-sim-placeholder' }, 'The 3D view appears here once the simulation runs.');
    viewer.append(viewerPlaceholder);
    let iframe: HTMLIFrameElement | undefined;

    // --- port inspector ---------------------------------------------------------------------------
    const filterInput = el('input', { type: 'search', placeholder: 'Filter ports…', class: 'maa-inspector-filter', 'data-testid': 'port-filter' });
    const allOnDiagram = el('input', { type: 'checkbox', 'data-testid': 'values-all' });
    allOnDiagram.checked = true;
    const showPlatform = el('input', { type: 'checkbox', 'data-testid': 'show-platform-topics' });
    const tbody = el('tbody');
    const table = el(
        'table',
        { class: 'maa-inspector-table' },
        el('thead', {}, el('tr', {}, el('th', { title: 'Watch: plot the value' }, 'Watch'), el('th', {}, 'Port'), el('th', {}, 'Value'), el('th', {}, 'Inject'))),
        tbody,
    );
    const inspectorEmpty = el('div', { class: 'maa-inspector-empty' }, 'Port topics appear here during a run.');
    const inspector = el(
        'div',
        { class: 'maa-sim-inspector', 'data-testid': 'port-inspector' },
        el(
            'div',
            { class: 'maa-inspector-header' },
            filterInput,
            el('label', { title: 'Show every port value on the diagram (otherwise only watched ones)' }, allOnDiagram, ' all values on diagram'),
            el('label', { title: 'Also list the simulator topics (/clock, /joint_states, sensors, actuators)' }, showPlatform, ' platform topics'),
        ),
        inspectorEmpty,
        table,
    );
    container.replaceChildren(
        controls,
        el('div', { class: 'maa-sim-statusbar' }, statusText),
        errorBox,
        progressBox,
        el('div', { class: 'maa-sim-body' }, viewer, inspector),
    );

    // --- state -------------------------------------------------------------------------------------
    let apps: AppInfo[] = [];
    let running = false;
    let busy = false;
    /** A start request is open (the stop button then cancels it). */
    let starting = false;
    /** Enum literals per message type (ROS 2 mode's enum messages), `null` when there are none. */
    const enumLiterals = new Map<string, string[] | null>();
    let ros: RosConnection | undefined;
    let rootComponent = '';
    let simStatus: SimStatus = {};
    let clock: number | undefined;
    let activeStates = new Map<string, string>();
    let statesDirty = false;
    const rows = new Map<string, Row>();
    const subs: Disposable[] = [];
    const timers: ReturnType<typeof setInterval>[] = [];
    let disposed = false;
    let attachGeneration = 0;

    const extras = host.diagram as unknown as DiagramExtras;
    const knownPortPaths = (): string[] => (typeof extras.knownPortPaths === 'function' ? extras.knownPortPaths() : []);
    const knownInstancePaths = (): string[] | undefined => (typeof extras.knownInstancePaths === 'function' ? extras.knownInstancePaths() : undefined);

    function showError(message: string | undefined, log: string[] = []): void {
        if (!message) {
            errorBox.hidden = true;
            errorBox.replaceChildren();
            return;
        }
        errorBox.hidden = false;
        const children: Node[] = [el('div', { class: 'maa-sim-error-message' }, message)];
        if (log.length > 0) children.push(el('pre', { class: 'maa-sim-log', 'data-testid': 'sim-log' }, log.slice(-40).join('\n')));
        const close = el('button', { type: 'button', class: 'maa-sim-error-close', title: 'Dismiss' }, '×');
        close.addEventListener('click', () => showError(undefined));
        errorBox.replaceChildren(close, ...children);
    }

    function selectedApp(): AppInfo | undefined {
        return apps.find((a) => a.path === appSelect.value);
    }

    function selectedMode(): SimMode | undefined {
        const app = selectedApp();
        const p = app?.platforms.find((x) => x.name === platformSelect.value);
        return p ? platformMode(p.kind) : undefined;
    }

    function updateButtons(): void {
        const mode = selectedMode();
        startBtn.disabled = busy || !mode;
        stopBtn.disabled = starting ? false : busy || !running;
        for (const b of [pauseBtn, resumeBtn, stepBtn, resetBtn]) b.disabled = !running || !ros;
        reloadViewBtn.disabled = !iframe;
        speedSelect.disabled = busy;
        appSelect.disabled = busy;
        platformSelect.disabled = busy;
        modeLabel.textContent = mode ? (mode === 'lockstep' ? 'lock-step' : 'ROS 2') : '';
        pauseBtn.hidden = !!simStatus.paused;
        resumeBtn.hidden = !simStatus.paused;
    }

    function fillPlatforms(): void {
        const app = selectedApp();
        platformSelect.replaceChildren();
        if (!app) return;
        for (const p of app.platforms) {
            const mode = platformMode(p.kind);
            const o = el('option', { value: p.name }, `${p.name}${mode ? ` (${mode === 'lockstep' ? 'lock-step' : 'ROS 2'})` : ' (cannot run)'}`);
            if (!mode) o.disabled = true;
            platformSelect.append(o);
        }
        const def = defaultPlatform(app);
        if (def) platformSelect.value = def;
    }

    async function loadApps(): Promise<void> {
        try {
            apps = await host.apps();
        } catch (e) {
            apps = [];
            showError(`Could not list the applications: ${errorText(e)}`);
        }
        const previous = appSelect.value;
        appSelect.replaceChildren(...apps.map((a) => el('option', { value: a.path, title: a.component }, `${a.name} (${a.path})`)));
        if (apps.length === 0) appSelect.append(el('option', { value: '' }, 'no application (.arcapp)'));
        if (previous && apps.some((a) => a.path === previous)) appSelect.value = previous;
        fillPlatforms();
        updateButtons();
    }

    appSelect.addEventListener('change', () => {
        fillPlatforms();
        updateButtons();
    });
    appSelect.addEventListener('focus', () => void loadApps());
    platformSelect.addEventListener('change', updateButtons);

    // --- session -----------------------------------------------------------------------------------
    startBtn.addEventListener('click', () => void start());
    reloadViewBtn.addEventListener('click', () => {
        if (iframe) iframe.src = '/sim/viser/';
    });
    stopBtn.addEventListener('click', () => void stop());

    async function start(): Promise<void> {
        const app = selectedApp();
        const mode = selectedMode();
        if (!app || !mode) return;
        busy = true;
        showError(undefined);
        const label = `${app.name} on ${platformSelect.value}`;
        statusText.textContent = `Starting ${label} (generating)…`;
        starting = true;
        updateButtons();
        detach();
        const stopPolling = pollWhileStarting(label);
        try {
            await simApi.start(app.path, platformSelect.value, mode, Number(speedSelect.value));
            stopPolling();
            host.notify('info', `Simulation of ${app.name} started (${mode === 'lockstep' ? 'lock-step' : 'ROS 2'})`);
            running = true;
            rootComponent = app.component;
            attach();
        } catch (e) {
            stopPolling();
            running = false;
            let log = e instanceof BackendError ? e.log : [];
            if (log.length === 0) {
                try {
                    log = (await simApi.status()).log ?? [];
                } catch {
                    /* no log */
                }
            }
            statusText.textContent = 'Not running';
            if (cancelled) {
                statusText.textContent = 'Start cancelled';
            } else {
                showError(`Start failed: ${errorText(e)}`, log);
                host.notify('error', `Simulation start failed: ${errorText(e)}`);
            }
        } finally {
            stopPolling();
            starting = false;
            cancelled = false;
            busy = false;
            updateButtons();
        }
    }

    /** Set by a stop during an open start: the start's failure (409) is then no error. */
    let cancelled = false;

    /**
     * Polls `/api/sim/status` while the start request is open: the status line shows the elapsed
     * time and the last progress line, the progress box the log's last lines (ROS 2 mode prepares
     * its environment first: venv setup, interface package build, docs/ide.md). Returns the stop.
     */
    function pollWhileStarting(label: string): () => void {
        const t0 = Date.now();
        let stopped = false;
        let inFlight = false;
        const tick = async (): Promise<void> => {
            if (stopped || inFlight) return;
            inFlight = true;
            let st: SimStatusAnswer | undefined;
            try {
                st = await simApi.status();
            } catch {
                st = undefined;
            } finally {
                inFlight = false;
            }
            if (stopped || disposed) return;
            const seconds = Math.round((Date.now() - t0) / 1000);
            statusText.textContent = preparingLine(label, seconds, st);
            const log = st?.log ?? [];
            if (log.length > 0) {
                progressLog.textContent = log.slice(-12).join('\n');
                progressBox.hidden = false;
                progressLog.scrollTop = progressLog.scrollHeight;
            }
        };
        const timer = setInterval(() => void tick(), START_POLL_MS);
        return () => {
            if (stopped) return;
            stopped = true;
            clearInterval(timer);
            progressBox.hidden = true;
            progressLog.textContent = '';
        };
    }

    async function stop(): Promise<void> {
        if (starting) cancelled = true;
        busy = true;
        updateButtons();
        try {
            await simApi.stop();
            host.notify('info', 'Simulation stopped');
        } catch (e) {
            showError(`Stop failed: ${errorText(e)}`, e instanceof BackendError ? e.log : []);
        } finally {
            running = false;
            detach();
            statusText.textContent = 'Stopped';
            busy = false;
            updateButtons();
        }
    }

    /** Connects to the running session: rosbridge, viser, topics, status polling. */
    function attach(): void {
        const generation = ++attachGeneration;
        if (!iframe) {
            iframe = el('iframe', { 'data-testid': 'viser-frame', class: 'maa-viser-frame', title: 'Simulation (viser)', src: '/sim/viser/' });
            viewer.replaceChildren(iframe);
        } else {
            iframe.src = '/sim/viser/';
        }
        const url = rosbridgeUrl(window.location);
        /** Connects, retrying a few times: the proxied endpoint may need a moment after a start. */
        const connect = async (attempt: number): Promise<void> => {
            const conn = new RosConnection(url);
            ros = conn;
            updateButtons();
            try {
                await conn.whenConnected(10_000);
            } catch (e) {
                conn.dispose();
                if (ros === conn) ros = undefined;
                if (generation !== attachGeneration) return;
                if (attempt < 4) {
                    statusText.textContent = `Connecting to the simulator (attempt ${attempt + 1})…`;
                    await new Promise((r) => setTimeout(r, 1000 * attempt));
                    if (generation === attachGeneration) return connect(attempt + 1);
                    return;
                }
                throw e;
            }
            if (generation !== attachGeneration) {
                conn.dispose();
                return;
            }
            statusText.textContent = 'Connected';
            updateButtons();
            subs.push(
                conn.onState((s, detail) => {
                    if ((s === 'error' || s === 'closed') && running && generation === attachGeneration) statusText.textContent = `rosbridge ${s}${detail ? `: ${detail}` : ''}`;
                }),
            );
            subs.push(
                conn.subscribe('/clock', 'rosgraph_msgs/msg/Clock', (m) => {
                    const t = clockSeconds(m);
                    if (t !== undefined) clock = t;
                }, 100),
            );
            subs.push(
                conn.subscribe(AUTOMATON_STATES, 'std_msgs/msg/String', (m) => {
                    activeStates = parseAutomatonStates(m, rootComponent, knownInstancePaths());
                    statesDirty = true;
                }, DIAGRAM_PERIOD_MS),
            );
            void refreshTopics();
            void pollStatus();
        };
        connect(1).catch((e: unknown) => {
            if (generation !== attachGeneration) return;
            showError(`Could not connect to the simulator's rosbridge at ${url}: ${errorText(e)}`);
        });
        timers.push(setInterval(() => void pollStatus(), STATUS_PERIOD_MS));
        timers.push(setInterval(() => void refreshTopics(), TOPICS_PERIOD_MS));
        timers.push(setInterval(() => void pollBackend(), 2000));
        timers.push(setInterval(pushToDiagram, DIAGRAM_PERIOD_MS));
    }

    /** Disconnects and clears everything a run showed. */
    function detach(): void {
        attachGeneration++;
        for (const t of timers.splice(0)) clearInterval(t);
        for (const s of subs.splice(0)) s.dispose();
        for (const r of rows.values()) r.sub?.dispose();
        rows.clear();
        tbody.replaceChildren();
        inspectorEmpty.hidden = false;
        ros?.dispose();
        ros = undefined;
        clock = undefined;
        simStatus = {};
        activeStates = new Map();
        statesDirty = false;
        if (iframe) {
            iframe.remove();
            iframe = undefined;
            viewer.replaceChildren(viewerPlaceholder);
        }
        try {
            host.diagram.setLiveValues(new Map());
            host.diagram.setActiveStates(new Map());
        } catch {
            /* the diagram may be gone */
        }
        updateButtons();
    }

    async function pollStatus(): Promise<void> {
        const conn = ros;
        if (!conn || conn.connectionState !== 'connected') return;
        try {
            simStatus = unwrapStatus(await conn.callService('/sim/get_status', {}, 5000));
            statusText.textContent = statusLine(simStatus, clock);
            updateButtons();
        } catch {
            if (clock !== undefined) statusText.textContent = statusLine(simStatus, clock);
        }
    }

    async function pollBackend(): Promise<void> {
        if (!running) return;
        let st: SimStatusAnswer;
        try {
            st = await simApi.status();
        } catch {
            return;
        }
        if (!st.running && running) {
            running = false;
            detach();
            statusText.textContent = `Simulation ended${st.exitCode !== undefined && st.exitCode !== null ? ` (exit code ${st.exitCode})` : ''}`;
            if (st.exitCode) showError(`The simulation ended with exit code ${st.exitCode}`, st.log ?? []);
            updateButtons();
        }
    }

    // --- controls over rosbridge --------------------------------------------------------------------
    async function control(service: string, args: Record<string, unknown> = {}): Promise<void> {
        const conn = ros;
        if (!conn) return;
        try {
            const res = await conn.callService(service, args, service === '/sim/reset' ? 60_000 : 10_000);
            if (res && res.success === false) host.notify('warning', `${service}: ${res.message ?? 'failed'}`);
            const st = res?.status;
            if (st && typeof st === 'object') simStatus = unwrapStatus(st);
            await pollStatus();
        } catch (e) {
            host.notify('error', errorText(e));
        }
    }
    pauseBtn.addEventListener('click', () => void control('/sim/pause'));
    resumeBtn.addEventListener('click', () => void control('/sim/resume'));
    stepBtn.addEventListener('click', () => {
        const steps = Math.min(100000, Math.max(1, Math.round(Number(stepsInput.value) || 1)));
        void control('/sim/step', { steps });
    });
    resetBtn.addEventListener('click', () => {
        for (const r of rows.values()) r.samples.clear();
        void control('/sim/reset');
    });
    speedSelect.addEventListener('change', () => {
        if (running) void control('/sim/set_speed', { speed: Number(speedSelect.value) });
    });

    // --- topics and the inspector -------------------------------------------------------------------
    async function refreshTopics(): Promise<void> {
        const conn = ros;
        if (!conn || conn.connectionState !== 'connected') return;
        let list: TopicInfo[];
        try {
            list = await conn.listTopics();
        } catch {
            return;
        }
        if (conn !== ros) return;
        const known = topicIndex(rootComponent, knownPortPaths());
        const seen = new Set<string>();
        for (const info of list) {
            if (info.topic === AUTOMATON_STATES || info.topic === '/clock' || info.topic.startsWith('/rosout') || info.topic.startsWith('/parameter_events')) continue;
            seen.add(info.topic);
            const port = topicToPort(rootComponent, info.topic, known);
            const existing = rows.get(info.topic);
            if (existing) {
                existing.info = info;
                if (port) existing.port = port;
                continue;
            }
            rows.set(info.topic, createRow(info, port));
        }
        for (const [topic, r] of rows) {
            if (!seen.has(topic)) {
                r.sub?.dispose();
                r.tr.remove();
                rows.delete(topic);
            }
        }
        renderRows();
        updateSubscriptions();
    }

    function createRow(info: TopicInfo, port: PortTopic | undefined): Row {
        const watch = el('input', { type: 'checkbox', title: 'Watch this port (plot)', 'data-topic': info.topic, class: 'maa-watch' });
        const valueCell = el('td', { class: 'maa-port-value', 'data-testid': 'port-value' }, '–');
        const svg = document.createElementNS(SVG_NS, 'svg');
        svg.setAttribute('width', '120');
        svg.setAttribute('height', '24');
        svg.setAttribute('class', 'maa-sparkline');
        const plotPath = document.createElementNS(SVG_NS, 'path');
        svg.appendChild(plotPath);
        const plotCell = el('div', { class: 'maa-port-plot' });
        plotCell.appendChild(svg);
        const valueText = el('div', { class: 'maa-port-value-text' }, '–');
        valueCell.replaceChildren(valueText, plotCell);
        const nameCell = el('td', { class: 'maa-port-name', title: `${info.topic}  (${info.type || 'type unknown'})` }, port ? port.portPath : info.topic);
        const injectCell = el('td', { class: 'maa-port-inject' });
        if (port?.rootPort) {
            const input = el('input', { type: 'text', placeholder: info.type.startsWith('std_msgs/') ? 'value' : 'JSON message', class: 'maa-inject-input', 'data-testid': 'inject-input', 'data-topic': info.topic });
            const send = el('button', { type: 'button', class: 'maa-sim-button', 'data-testid': 'inject-send', 'data-topic': info.topic }, 'Send');
            const doSend = (): void => void inject(info.topic, input.value);
            send.addEventListener('click', doSend);
            input.addEventListener('keydown', (e) => {
                if (e.key === 'Enter') doSend();
            });
            injectCell.append(input, send);
        }
        const tr = el(
            'tr',
            { class: port ? 'maa-port-row' : 'maa-platform-row', 'data-topic': info.topic, 'data-port-path': port?.portPath ?? '' },
            el('td', {}, watch),
            nameCell,
            valueCell,
            injectCell,
        );
        const row: Row = { info, port, tr, watch, valueCell: valueText, plotPath, plotCell, samples: new SampleWindow(200), dirty: false, numeric: false };
        watch.addEventListener('change', () => {
            tr.classList.toggle('maa-watched', watch.checked);
            if (!watch.checked) row.samples.clear();
            // resubscribe: watched topics arrive unthrottled
            row.sub?.dispose();
            row.sub = undefined;
            updateSubscriptions();
            pushToDiagram(true);
        });
        return row;
    }

    function rowVisible(r: Row): boolean {
        if (!r.port && !showPlatform.checked && !r.watch.checked) return false;
        const f = filterInput.value.trim().toLowerCase();
        return !f || r.info.topic.toLowerCase().includes(f) || (r.port?.portPath.toLowerCase().includes(f) ?? false);
    }

    function renderRows(): void {
        const sorted = [...rows.values()].sort((a, b) => Number(!a.port) - Number(!b.port) || (a.port?.portPath ?? a.info.topic).localeCompare(b.port?.portPath ?? b.info.topic));
        const visible = sorted.filter(rowVisible);
        tbody.replaceChildren(...visible.map((r) => r.tr));
        inspectorEmpty.hidden = visible.length > 0;
        inspectorEmpty.textContent = rows.size === 0 ? 'Port topics appear here during a run.' : 'No topic matches.';
    }
    filterInput.addEventListener('input', renderRows);
    showPlatform.addEventListener('change', () => {
        renderRows();
        updateSubscriptions();
    });
    allOnDiagram.addEventListener('change', () => {
        updateSubscriptions();
        pushToDiagram(true);
    });

    /** Subscribed: watched rows, port rows when all values go to the diagram, visible platform rows. */
    function updateSubscriptions(): void {
        const conn = ros;
        if (!conn) return;
        for (const r of rows.values()) {
            const want = r.watch.checked || (!!r.port && allOnDiagram.checked) || (!r.port && showPlatform.checked) || (!!r.port && rowVisible(r));
            if (want && !r.sub) {
                r.sub = conn.subscribe(r.info.topic, r.info.type || undefined, (m) => onMessage(r, m), r.watch.checked ? 0 : DIAGRAM_PERIOD_MS);
            } else if (!want && r.sub) {
                r.sub.dispose();
                r.sub = undefined;
            }
        }
    }

    function onMessage(r: Row, m: unknown): void {
        r.last = m;
        r.dirty = true;
        if (isEnumMessage(m)) lookUpEnum(r.info.type);
        const v = numericValue(m);
        if (v !== undefined) {
            r.numeric = true;
            if (r.watch.checked) r.samples.push(clock ?? performance.now() / 1000, v);
        }
    }

    /** Looks up the literals of an enum message type once (rosapi's message definition); rows of the type then show them. */
    function lookUpEnum(type: string): void {
        const conn = ros;
        if (!type || enumLiterals.has(type) || !conn) return;
        enumLiterals.set(type, null);
        conn.messageDetails(type)
            .then((typedefs) => {
                const literals = enumLiteralsOf(typedefs[0]);
                if (!literals) return;
                enumLiterals.set(type, literals);
                for (const r of rows.values()) if (r.info.type === type && r.last !== undefined) r.dirty = true;
            })
            .catch(() => {
                /* no rosapi details: ordinals stay */
            });
    }

    function formatOptions(r: Row): FormatOptions | undefined {
        const literals = enumLiterals.get(r.info.type);
        return literals ? { enumLiterals: literals } : undefined;
    }

    async function inject(topic: string, text: string): Promise<void> {
        const conn = ros;
        const r = rows.get(topic);
        if (!conn || !r) return;
        try {
            let type = r.info.type;
            try {
                type = (await conn.topicType(topic)) || type;
            } catch {
                /* keep the listed type */
            }
            if (!type) throw new Error(`the type of ${topic} is unknown`);
            const literals = enumLiterals.get(type);
            const ordinal = literals ? literals.indexOf(text.trim()) : -1;
            const msg = ordinal >= 0 ? { value: ordinal } : parseInjectedValue(type, text);
            conn.publish(topic, type, msg);
            host.notify('info', `Sent ${formatRosValue(msg, 60)} to ${r.port?.portPath ?? topic}`);
        } catch (e) {
            host.notify('error', `Inject on ${topic}: ${errorText(e)}`);
        }
    }

    /** Updates the inspector cells and hands values and states to the diagram (10 Hz). */
    function pushToDiagram(force = false): void {
        let valuesChanged = force;
        for (const r of rows.values()) {
            if (!r.dirty) continue;
            r.dirty = false;
            const text = formatRosValue(r.last, 120, formatOptions(r));
            if (text !== r.lastText) {
                r.lastText = text;
                r.valueCell.textContent = text;
                r.valueCell.title = text;
                if (r.port) valuesChanged = true;
            }
            if (r.watch.checked && r.numeric) r.plotPath.setAttribute('d', sparklinePath(r.samples.samples(), 120, 24));
        }
        for (const r of rows.values()) if (!r.watch.checked && r.plotPath.getAttribute('d')) r.plotPath.removeAttribute('d');
        if (valuesChanged) {
            const values = new Map<string, string>();
            for (const r of rows.values()) {
                if (!r.port || r.lastText === undefined) continue;
                if (!allOnDiagram.checked && !r.watch.checked) continue;
                values.set(r.port.portPath, formatRosValue(r.last, 28, formatOptions(r)));
            }
            host.diagram.setLiveValues(values);
        }
        if (statesDirty) {
            statesDirty = false;
            host.diagram.setActiveStates(activeStates);
        }
        if (clock !== undefined && running && ros?.connectionState === 'connected') statusText.textContent = statusLine(simStatus, clock);
    }

    // --- start-up: apps and a session that is already running ------------------------------------------
    updateButtons();
    void (async () => {
        await loadApps();
        try {
            let st = await simApi.status();
            const app = apps.find((a) => a.path === st.app);
            const adopt = (): void => {
                if (!app) return;
                appSelect.value = app.path;
                fillPlatforms();
                if (st.platform) platformSelect.value = st.platform;
            };
            if (st.preparing && !disposed) {
                // a start (from another window, or before a reload) still prepares its ROS 2 environment
                adopt();
                starting = true;
                busy = true;
                updateButtons();
                const stopPolling = pollWhileStarting(`${app?.name ?? st.app ?? 'the application'} on ${st.platform ?? '?'}`);
                try {
                    while (st.preparing && !disposed) {
                        await new Promise((r) => setTimeout(r, START_POLL_MS));
                        st = await simApi.status();
                    }
                } finally {
                    stopPolling();
                    starting = false;
                    busy = false;
                }
                if (!st.running && !disposed && !cancelled) {
                    statusText.textContent = 'Not running';
                    if (st.log?.length) showError('The simulation did not start', st.log);
                }
                cancelled = false;
                updateButtons();
            }
            if (st.running && !disposed) {
                running = true;
                adopt();
                rootComponent = app?.component ?? selectedApp()?.component ?? '';
                attach();
                updateButtons();
            }
        } catch {
            /* backend without a session API: nothing to attach */
        }
    })();

    return {
        dispose(): void {
            if (disposed) return;
            disposed = true;
            detach();
            container.replaceChildren();
            container.classList.remove('maa-simulate');
        },
    };
}

function errorText(e: unknown): string {
    return e instanceof Error ? e.message : String(e);
}
