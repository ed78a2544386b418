// The lab bench's simulations: how many lock-step simulations of the released exercise this
// machine holds at real-time speed. Each runs in a student's workspace (started through the
// lab's /sim/start); its real-time factor is read from the simulator's status service
// (`/sim/get_status` over the workspace's proxied rosbridge WebSocket, which also keeps the
// simulation from ending for want of a connection).
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { BenchClient } from './http.mjs';
import { median } from './stats.mjs';
import { COURSE, EXERCISE, EXERCISE_DIR, PASSWORD, REPO, studentLogin } from './setup.mjs';

// `ws` is the WebSocket client of @maa/ide-server (a dependency of the lab server); Node 20 has
// no WebSocket client without a flag.
const WebSocket = createRequire(path.join(REPO, 'packages', 'ide-server', 'package.json'))('ws');

const CONTROLLER = 'toast/Controller.arc';
// The starter's Controller never serves the toast, so no run ends at the goal while it is measured.
const STARTER = readFileSync(path.join(EXERCISE_DIR, 'starter', CONTROLLER), 'utf8');
const START = { app: 'TR.arcapp', platform: 'timesync', mode: 'lockstep', speed: 1 };
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** A running simulation of one student: its client, its rosbridge socket, status calls. */
class BenchSimulation {
    constructor(url, login) {
        this.url = url;
        this.login = login;
        this.prefix = `/api/ws/${COURSE}/${EXERCISE}/${login}`;
        this.client = new BenchClient(url);
        this.socket = undefined;
        this.pending = new Map();
        this.nextId = 1;
    }

    async start() {
        await this.client.login(this.login, PASSWORD);
        const saved = await this.client.send(undefined, 'PUT', `${this.prefix}/file?path=${encodeURIComponent(CONTROLLER)}`, STARTER);
        if (saved.status !== 200) throw new Error(`${this.login}: saving the starter failed: ${saved.status} ${saved.text}`);
        const started = await this.client.send(undefined, 'POST', `${this.prefix}/sim/start`, START);
        if (started.status !== 200 || started.json?.ok !== true)
            throw new Error(`${this.login}: /sim/start failed: ${started.status} ${started.text.slice(0, 500)}`);
        const wsUrl = new URL(started.json.rosbridge, this.url.replace(/^http/, 'ws'));
        this.socket = new WebSocket(wsUrl, { headers: { Cookie: this.client.cookie } });
        await new Promise((resolve, reject) => {
            this.socket.once('open', resolve);
            this.socket.once('error', reject);
        });
        this.socket.on('message', (data) => {
            let m;
            try {
                m = JSON.parse(String(data));
            } catch {
                return;
            }
            const waiter = m?.op === 'service_response' ? this.pending.get(m.id) : undefined;
            if (waiter) {
                this.pending.delete(m.id);
                waiter(m);
            }
        });
        this.socket.on('error', () => undefined);
    }

    /** The simulator's status (real_time_factor, time, finished, ...). */
    status(timeoutMs = 10_000) {
        const id = `bench-${this.nextId++}`;
        return new Promise((resolve, reject) => {
            const timer = setTimeout(() => {
                this.pending.delete(id);
                reject(new Error(`${this.login}: /sim/get_status got no answer in ${timeoutMs} ms`));
            }, timeoutMs);
            this.pending.set(id, (m) => {
                clearTimeout(timer);
                if (m.result === false) reject(new Error(`${this.login}: /sim/get_status: ${JSON.stringify(m.values)}`));
                else resolve(m.values);
            });
            this.socket.send(JSON.stringify({ op: 'call_service', service: '/sim/get_status', id }));
        });
    }

    async stop() {
        this.socket?.close();
        await this.client.send(undefined, 'POST', `${this.prefix}/sim/stop`, {});
        this.client.close();
    }
}

/**
 * Starts 1, 2, 3, ... simulations (one more each step, the earlier ones keep running); after
 * each start waits `settleMs` and reads every running simulation's real-time factor `samples`
 * times a second apart (each simulation's median of them). Stops at the first count whose median
 * over the simulations is below `threshold`, or at `maxSims`. Every simulation is stopped after.
 * @returns {rows: [{count, median, min, max, factors}], held} held: the largest count at real time
 */
export async function measureSimulations({
    url,
    maxSims,
    students,
    settleMs = 5000,
    samples = 5,
    threshold = 0.95,
    log = () => undefined,
}) {
    const running = [];
    const rows = [];
    let held = 0;
    try {
        for (let count = 1; count <= Math.min(maxSims, students); count++) {
            const sim = new BenchSimulation(url, studentLogin(count - 1));
            running.push(sim);
            await sim.start();
            await sleep(settleMs);
            const perSim = running.map(() => []);
            for (let s = 0; s < samples; s++) {
                const statuses = await Promise.all(running.map((r) => r.status()));
                statuses.forEach((st, i) => {
                    if (st.finished) throw new Error(`${running[i].login}: the simulation finished (${st.finished}) while measured`);
                    perSim[i].push(Number(st.real_time_factor));
                });
                await sleep(1000);
            }
            const factors = perSim.map(median);
            const row = { count, median: median(factors), min: Math.min(...factors), max: Math.max(...factors), factors };
            rows.push(row);
            log(row);
            if (row.median < threshold) break;
            held = count;
        }
    } finally {
        for (const sim of running) await sim.stop().catch(() => undefined);
    }
    return { rows, held, threshold };
}
