// Record and replay in the browser IDE (issue 19, C6): a lock-step run of the example recorded from
// the simulate view (the Record toggle, the run at full speed until the toast lies on the plate),
// the recording replayed (the recordings list, Replay), the time slider scrubbed to the moment the
// toast reaches the plate (/sim/scene toast_on_plate first true, read from the file with the `mcap`
// reader libraries as Foxglove would): the status line, the diagram's values and active state and
// the replay server's 3D scene (the bread's pose) match what the file recorded at that time.
// Screenshots as artifacts. Each gets { page, url, workspace, shot(name) } (run.mjs).
import { execFileSync } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fail } from './host-kit.mjs';
import { repo, startLockstepRun, until } from './lib.mjs';

/** The slider goes this long after the moment the toast reaches the plate. */
const AFTER_GOAL = 0.01;

/**
 * What the recording holds when the toast first lies on the plate, read with the mcap libraries
 * (not maa-sim's code): that time, the bread's poses around it ([t, x, y, z]), the last message
 * of every topic then (`last`) and at AFTER_GOAL seconds later, where the slider goes (`at`), and
 * the time of the first message after that the view loads (`next`: not the scene poses, not /clock).
 */
function recordedAtGoal(file) {
    const script = `
import json, sys
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
def plain(v):
    if isinstance(v, (bool, int, float, str)) or v is None: return v
    if isinstance(v, (list, tuple)): return [plain(x) for x in v]
    return {k: plain(getattr(v, k)) for k in getattr(type(v), "__slots__", ()) if not k.startswith("_")}
AFTER = float(sys.argv[2])
goal, last, at, breads, after = None, {}, {}, [], None
with open(sys.argv[1], "rb") as f:
    for _s, ch, m, msg in make_reader(f, decoder_factories=[DecoderFactory()]).iter_decoded_messages(log_time_order=True):
        t = m.log_time / 1e9
        if goal is not None and t > goal + 0.2: break
        if goal is not None and after is None and t > goal + AFTER and ch.topic not in ("/sim/scene", "/clock"): after = t
        if ch.topic == "/sim/scene":
            if msg.toast_on_plate and goal is None: goal = t
            pose = msg.body_poses[list(msg.body_names).index("bread")]
            breads = (breads + [[t, pose.position.x, pose.position.y, pose.position.z]])[-40:]
            continue
        if not hasattr(msg, "data"): continue
        if goal is None: last[ch.topic] = plain(msg.data)
        if goal is None or t <= goal + AFTER: at[ch.topic] = plain(msg.data)
print(json.dumps({"goal": goal, "breads": breads, "last": last, "at": at, "next": after}))
`;
    const python = path.join(repo, 'sim-server', '.venv', 'bin', 'python');
    return JSON.parse(execFileSync(python, ['-c', script, file, String(AFTER_GOAL)], { encoding: 'utf8' }));
}

/** Calls a service of the running session's rosbridge (the replay server) from the page, as the view does. */
const callService = (page, service, args) =>
    page.evaluate(
        ({ service, args }) =>
            new Promise((resolve, reject) => {
                const ws = new WebSocket(new URL('sim/rosbridge', location.href.replace(/^http/, 'ws')));
                const timer = setTimeout(() => reject(new Error(`${service}: no answer`)), 20_000);
                ws.onopen = () => ws.send(JSON.stringify({ op: 'call_service', id: 'e2e', service, args }));
                ws.onmessage = (e) => {
                    const m = JSON.parse(e.data);
                    if (m.id !== 'e2e') return;
                    clearTimeout(timer);
                    ws.close();
                    resolve(m.values);
                };
                ws.onerror = () => reject(new Error(`${service}: WebSocket error`));
            }),
        { service, args },
    );

/** The backend's simulation status, asked from the page (its origin and token cookie). */
const simStatus = (page) => page.evaluate(async () => (await fetch('api/sim/status')).json());

/** Moves the replay's time slider to `t` as a person dragging it would (an input event). */
const scrub = (view, t) =>
    view.locator('[data-testid=replay-slider]').evaluate((slider, value) => {
        slider.value = String(value);
        slider.dispatchEvent(new Event('input', { bubbles: true }));
    }, t);

/** The tool bar's Start once the view is idle; Record ticked, full speed. */
async function startRecordedRun(view, page) {
    await until(page, 'Start is not enabled', () => view.locator('[data-testid=sim-start]').isEnabled(), 120_000);
    await view.locator('[data-testid=sim-speed]').selectOption('0');
    await view.locator('[data-testid=sim-record]').check();
    await view.locator('[data-testid=sim-start]').click();
}

/** How the port table shows a recorded `data` value of a std_msgs message (format.ts), `undefined` for values it rounds or cuts. */
function shownText(v) {
    if (typeof v === 'boolean') return v ? 'true' : 'false';
    if (Number.isInteger(v)) return String(v);
    if (typeof v === 'string' && v.length < 100) return v;
    return undefined;
}

/**
 * The port table follows the slider: each port row of the application's topics shows the value
 * the recording holds at the slider's time (at least two such rows, none showing another value).
 */
async function inspectorShowsRecorded(view, page, at) {
    const wanted = Object.entries(at)
        .filter(([topic]) => topic.startsWith('/toast_service_robot/'))
        .map(([topic, v]) => [topic, shownText(v)])
        .filter(([, text]) => text !== undefined);
    const rows = async () => {
        const found = [];
        for (const [topic, text] of wanted) {
            const value = view.locator(`[data-testid=port-inspector] tr[data-topic="${topic}"] .maa-port-value-text`);
            if ((await value.count()) === 0) continue;
            found.push({ topic, expected: text, shown: ((await value.textContent()) ?? '').trim() });
        }
        return found;
    };
    let last = [];
    await until(
        page,
        `the port table does not show the recorded values at the slider's time: ${JSON.stringify(last)}`,
        async () => {
            last = await rows();
            return last.length >= 2 && last.every((r) => r.shown === r.expected);
        },
        30_000,
    ).catch(async () => fail(`the port table does not show the recorded values: ${JSON.stringify(last)}`));
    const note = (await view.locator('[data-testid=port-stale]').textContent()) ?? '';
    if (!/Recorded values at/.test(note)) await fail(`the port table's note says "${note}"`);
}

export const replayScenarios = [
    {
        id: 'r1-replay',
        name: 'record a lock-step run, replay it, scrub to the toast reaching the plate: status, diagram values and state, 3D scene as recorded',
        async run({ page, url, workspace, shot }) {
            // The simulate view opens with a run (Start Simulation); it is stopped and started again recorded.
            const { view, diagram } = await startLockstepRun(page, url, { diagram: true });
            await view.locator('[data-testid=sim-stop]').click();
            await until(page, 'the first run did not stop', async () => !(await simStatus(page)).running, 60_000);

            await startRecordedRun(view, page);
            const status = view.locator('[data-testid=sim-status]');
            await until(
                page,
                'the recorded run did not get the toast onto the plate',
                async () => /on plate/.test((await status.textContent()) ?? ''),
                240_000,
            );
            const recording = (await simStatus(page)).recording;
            if (!recording) await fail("the backend does not name the run's recording");
            await shot('recorded-run');
            await view.locator('[data-testid=sim-stop]').click();
            const file = path.join(workspace, 'recordings', recording);
            await until(page, `the recording ${recording} was not completed`, async () => existsSync(file), 60_000);
            if (readdirSync(path.dirname(file)).some((n) => n.endsWith('.part'))) await fail('a .part file is left in recordings/');
            const expected = recordedAtGoal(file);
            if (expected.goal === null) await fail('the recording never has the toast on the plate');

            // The recordings list (refreshed when it gets the focus), Replay.
            const select = view.locator('[data-testid=sim-recordings]');
            await until(page, `the recordings list does not offer ${recording}`, async () => {
                await select.focus();
                return (await select.locator('option', { hasText: recording }).count()) > 0;
            });
            await select.selectOption(recording);
            await until(page, 'Replay is not enabled', () => view.locator('[data-testid=sim-replay]').isEnabled());
            await view.locator('[data-testid=sim-replay]').click();
            await view.locator('[data-testid=replay-bar]').waitFor({ state: 'visible', timeout: 120_000 });
            await until(page, 'the replay did not load', async () => /^replay /.test((await status.textContent()) ?? ''), 60_000);
            await shot('replay-opened');

            // Just before the moment: the toast is not on the plate yet.
            const goal = expected.goal;
            await scrub(view, goal - 0.03);
            await until(
                page,
                `the status line does not show t ${(goal - 0.03).toFixed(2)} s`,
                async () => /t \d+\.\d+ s/.test((await status.textContent()) ?? '') && !/on plate/.test((await status.textContent()) ?? ''),
            );
            // At the moment: on the plate, in the status line and in the replay server's scene.
            await scrub(view, goal + AFTER_GOAL);
            await until(page, `the status line does not say the toast is on the plate at ${goal} s`, async () =>
                /on plate/.test((await status.textContent()) ?? ''),
            );
            const server = await callService(page, '/sim/get_status', {});
            if (Math.abs(server.time - (goal + AFTER_GOAL)) > 0.011) await fail(`the replay server shows ${server.time} s, not ${goal} s`);
            const names = server.scene.body_names;
            const pose = server.scene.body_poses[names.indexOf('bread')].position;
            const shown = [pose.x, pose.y, pose.z];
            // the recorded pose of the last scene state at or before the time the server shows
            const recordedPose =
                expected.breads
                    .filter(([t]) => t <= server.time + 1e-9)
                    .pop()
                    ?.slice(1) ?? [];
            if (!server.scene.toast_on_plate || shown.some((v, i) => !(Math.abs(v - recordedPose[i]) <= 1e-9)))
                await fail(
                    `the 3D scene's bread is at ${JSON.stringify(shown)} at ${server.time} s, recorded ${JSON.stringify(recordedPose)}`,
                );

            // The diagram: the controller's recorded state and the recorded port values at that time.
            const states = JSON.parse(expected.last['/maa/automaton_states'] ?? '{}');
            const ctrlState = states['/toast_service_robot/ctrl'];
            if (!ctrlState) await fail(`no recorded state of ctrl: ${JSON.stringify(states)}`);
            await until(page, `the diagram does not show ctrl in ${ctrlState}`, async () =>
                (await diagram.locator('svg').first().textContent())?.includes(ctrlState),
            );
            const titles = await diagram.locator('.maa-value-label title').allTextContents();
            const recorded = new Set(
                Object.entries(expected.last)
                    .filter(([topic]) => topic.startsWith('/toast_service_robot/'))
                    .map(([topic, v]) => `${topic.split('/').pop()} = ${typeof v === 'string' ? v : JSON.stringify(v)}`),
            );
            const matching = titles.filter((t) => recorded.has(t));
            if (matching.length < 2)
                await fail(`the diagram's values ${JSON.stringify(titles)} do not show the recorded ${JSON.stringify([...recorded])}`);
            await inspectorShowsRecorded(view, page, expected.at);
            await shot('replay-on-plate');
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Diagram' }).first().click();
            await shot('replay-diagram');
            await page.locator('.tabs-container .tab', { hasText: 'MontiArc Simulation' }).first().click();

            // → on the focused slider steps to the next recorded message: later, but not past the file's next one.
            const slider = view.locator('[data-testid=replay-slider]');
            const from = Number(await slider.inputValue());
            await slider.focus();
            await page.keyboard.press('ArrowRight');
            let to = from;
            await until(page, '→ on the slider did not step', async () => {
                to = Number(await slider.inputValue());
                return to > from;
            }).catch(() => fail(`→ on the slider did not move it from ${from} s`));
            if (expected.next !== null && to > expected.next + 1e-6)
                await fail(`→ stepped from ${from} s to ${to} s, past the next recorded message at ${expected.next} s`);

            // Close: the replay session ends.
            await view.locator('[data-testid=replay-close]').click();
            await until(page, 'the replay session still runs after Close', async () => !(await simStatus(page)).running, 60_000);
        },
    },
];
