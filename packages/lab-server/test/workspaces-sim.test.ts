// Students' simulations in the lab with the real simulator (sim-server's maa-sim): the proxied
// rosbridge and viser endpoints only for the workspace's owner (another student's session cookie
// gets 403, as do no session, an instructor and a foreign Origin), the concurrent-simulation and
// simulated-time quotas (429 naming the limit), and every way a simulation ends when its student
// leaves — their last connection gone for the grace time, logout, session expiry, the server's
// stop — with no process of it left (its process group and its descendants' groups) and its
// result recorded.
import { randomBytes } from 'node:crypto';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { type IncomingMessage, request } from 'node:http';
import type { Duplex } from 'node:stream';
import { descendantGroups, groupAlive } from '@maa/ide-server';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { LabServer } from '../src/http/server.js';
import { startBackend } from './backends.js';
import type { Client } from './http-client.js';
import { EXERCISE, type Lab, MAA_SIM, startLab, until } from './workspace-setup.js';

const haveSim = existsSync(MAA_SIM);
const START = { app: 'TR.arcapp', platform: 'timesync', mode: 'lockstep' };

/** A WebSocket handshake (node:http): 101 with the socket, or the refusal's status. */
function upgrade(url: string, headers: Record<string, string>): Promise<{ status: number; socket?: Duplex; body?: string }> {
    return new Promise((resolve, reject) => {
        const req = request(url.replace(/^ws/, 'http'), {
            headers: {
                Connection: 'Upgrade',
                Upgrade: 'websocket',
                'Sec-WebSocket-Version': '13',
                'Sec-WebSocket-Key': randomBytes(16).toString('base64'),
                ...headers,
            },
        });
        req.on('upgrade', (_res, socket) => resolve({ status: 101, socket }));
        req.on('response', (res: IncomingMessage) => {
            let body = '';
            res.on('data', (c: Buffer) => (body += c.toString()));
            res.on('end', () => resolve({ status: res.statusCode ?? 0, body }));
        });
        req.on('error', reject);
        req.end();
    });
}

/** The processes whose command line names a path below `dir` (maa-sim runs `--package <dir>/...`). */
function processesUnder(dir: string): string[] {
    return readdirSync('/proc')
        .filter((n) => /^\d+$/.test(n))
        .filter((pid) => {
            try {
                return readFileSync(`/proc/${pid}/cmdline`, 'utf8').includes(dir);
            } catch {
                return false; // ended meanwhile
            }
        });
}

const cookieOf = (c: Client) => [...c.cookies].map(([k, v]) => `${k}=${v}`).join('; ');

describe.skipIf(!haveSim)(`students’ simulations${haveSim ? '' : ` (skipped: ${MAA_SIM} is missing)`}`, () => {
    let lab: Lab;
    let dispose: () => Promise<void>;

    beforeAll(async () => {
        const backend = await startBackend('pglite');
        lab = await startLab(await backend.freshStorage(), {
            workspaces: { simIdleSeconds: 3, sweepMs: 200, simStopGraceMs: 4000 },
        });
        dispose = async () => {
            await lab.dispose();
            await backend.dispose();
        };
    }, 120_000);
    afterAll(async () => dispose?.());

    const wsId = async (login: string, exercise = EXERCISE) => {
        const course = await lab.store.findCourse('robotics');
        const found = await lab.store.findExercise(course!.id, exercise);
        return (await lab.store.workspace((await lab.store.findUserByLogin(login))!.id, found!.id)).id;
    };

    /** Starts the owner's simulation; returns its process groups (maa-sim's and its descendants'). */
    async function start(c: Client, owner: string, server: LabServer = lab.server): Promise<number[]> {
        const answer = await c.post(`${lab.ws(owner)}/sim/start`, START);
        expect(answer.status, answer.text).toBe(200);
        expect(answer.json).toMatchObject({ ok: true, rosbridge: `${lab.ws(owner)}/sim/rosbridge`, viser: `${lab.ws(owner)}/sim/viser/` });
        const pid = server.workspaces.pool.find(await wsId(owner))?.sims.processGroup();
        expect(pid).toBeTypeOf('number');
        expect(processesUnder(lab.dataDir)).toContain(String(pid));
        return [pid!, ...descendantGroups(pid!)];
    }

    /** An open rosbridge connection of the owner (it keeps the simulation from idling out). */
    async function connect(c: Client, owner: string, server: LabServer = lab.server): Promise<Duplex> {
        const own = await upgrade(`${server.url}${lab.ws(owner)}/sim/rosbridge`, { Cookie: cookieOf(c) });
        expect(own.status).toBe(101);
        return own.socket!;
    }

    const latestDetails = async (owner: string) => JSON.stringify((await lab.store.latestSimulationResult(await wsId(owner)))?.details);

    /** Every group of the simulation ended (no orphan process). */
    const gone = (groups: number[]) => groups.every((g) => !groupAlive(g));

    it('proxies rosbridge and viser only for the workspace’s owner, and ends the simulation when their last connection left', async () => {
        const [ada, bob, teacher] = await Promise.all(['ada', 'bob', 'teacher'].map((l) => lab.as(l)));
        const groups = await start(ada, 'ada');
        const rosbridge = `${lab.server.url}${lab.ws('ada')}/sim/rosbridge`;
        const viser = `${lab.server.url}${lab.ws('ada')}/sim/viser/`;
        // Another student's cookie, an instructor's, none, or a foreign origin: refused.
        expect((await upgrade(rosbridge, { Cookie: cookieOf(bob) })).status).toBe(403);
        expect((await upgrade(`${lab.server.url}${lab.ws('ada')}/sim/viser`, { Cookie: cookieOf(bob) })).status).toBe(403);
        expect((await upgrade(rosbridge, { Cookie: cookieOf(teacher) })).status).toBe(403);
        expect((await upgrade(rosbridge, {})).status).toBe(401);
        expect((await upgrade(rosbridge, { Cookie: cookieOf(ada), Origin: 'http://evil.example' })).status).toBe(403);
        expect((await upgrade(`${lab.server.url}/api/elsewhere`, { Cookie: cookieOf(ada) })).status).toBe(404);
        expect((await bob.send(viser)).status).toBe(403);
        expect((await teacher.send(viser)).status).toBe(403);
        // Its owner gets through to the simulator.
        const own = await upgrade(rosbridge, { Cookie: cookieOf(ada) });
        expect(own.status).toBe(101);
        const page = await ada.send(viser);
        expect(page.status, page.text).toBe(200);
        // One simulation at a time: a second one (another exercise) is refused with when it frees.
        const second = await ada.post(`${lab.ws('ada', 'toast-copy')}/sim/start`, START);
        expect(second.status, second.text).toBe(429);
        expect(second.json).toMatchObject({ limit: 'concurrentSimulations', value: 1 });
        expect(second.headers['retry-after']).toMatch(/^\d+$/);
        expect(second.json.error).toMatch(/at most 1 at a time/);
        // The connection goes; after the grace time (3 s) the simulation ends with all its processes.
        expect(gone(groups)).toBe(false);
        own.socket?.destroy();
        await until(() => gone(groups), 'the simulation to end after its last connection left');
        await until(async () => (await lab.store.latestSimulationResult(await wsId('ada'))) !== undefined, 'the recorded result');
        const result = await lab.store.latestSimulationResult(await wsId('ada'));
        expect(result?.simulatedSeconds).toBeGreaterThan(0);
        expect(result?.goalReached).toBe(false);
        expect(lab.server.workspaces.simulations.slots.count((await lab.store.findUserByLogin('ada'))!.id)).toBe(0);
    }, 300_000);

    it('ends the simulation when its student logs out', async () => {
        const ada = await lab.as('ada');
        const groups = await start(ada, 'ada');
        const socket = await connect(ada, 'ada');
        const before = (await lab.store.latestSimulationResult(await wsId('ada')))?.id ?? 0;
        expect((await ada.post('/api/logout')).status).toBe(200);
        await until(() => gone(groups), 'the simulation to end after the logout');
        await until(async () => ((await lab.store.latestSimulationResult(await wsId('ada')))?.id ?? 0) > before, 'the recorded result');
        expect(await latestDetails('ada')).toMatch(/logged out/);
        socket.destroy();
    }, 300_000);

    it('ends the simulation when its student’s session expires', async () => {
        // The server's clock is moved past the session's end once the simulation runs and its
        // student is connected: no race with a short session (a fresh-clone run with 20 s saw the
        // connection refused, the session already over) and no simulation held for a minute.
        let ahead = 0;
        const clocked = await lab.serverWith({ now: () => Date.now() + ahead, workspaces: { sweepMs: 200 } });
        const bob = await lab.as('bob', clocked);
        const groups = await start(bob, 'bob', clocked);
        const socket = await connect(bob, 'bob', clocked);
        expect((await bob.send(`${lab.ws('bob')}/sim/status`)).status).toBe(200);
        expect(gone(groups)).toBe(false);
        ahead = 13 * 3600_000; // past the session's 12 hours
        await until(() => gone(groups), 'the simulation to end after the session expired');
        expect((await bob.send(`${lab.ws('bob')}/sim/status`)).status).toBe(401);
        await until(async () => /session expired/.test(await latestDetails('bob')), 'the recorded result');
        socket.destroy();
        await clocked.close();
    }, 300_000);

    it('ends every simulation when the server stops', async () => {
        const other = await lab.serverWith({});
        const bob = await lab.as('bob', other);
        const groups = await start(bob, 'bob', other);
        await other.close();
        expect(gone(groups)).toBe(true);
        expect(await latestDetails('bob')).toMatch(/the server stops/);
    }, 300_000);

    it('stops a simulation that used up the hour’s simulated time and refuses the next start (429)', async () => {
        const strict = await lab.serverWith({ workspaces: { sweepMs: 200, quotas: { simulatedSecondsPerHour: 2 } } });
        const bob = await lab.as('bob', strict);
        const groups = await start(bob, 'bob', strict);
        const socket = await connect(bob, 'bob', strict);
        await until(() => gone(groups), 'the simulation to end at the quota');
        await until(async () => /quota of the hour is used up/.test(await latestDetails('bob')), 'the end recorded');
        socket.destroy();
        const again = await bob.post(`${lab.ws('bob')}/sim/start`, START);
        expect(again.status, again.text).toBe(429);
        expect(again.json).toMatchObject({ limit: 'simulatedSecondsPerHour', value: 2 });
        expect(again.json.error).toMatch(/of the 2 simulated seconds allowed per hour; more frees at/);
        expect(Number(again.headers['retry-after'])).toBeGreaterThan(3000);
        await strict.close();
    }, 300_000);

    it('leaves no process behind that runs from a workspace folder', async () => {
        await lab.server.close();
        expect(processesUnder(lab.dataDir)).toEqual([]);
    });
});
