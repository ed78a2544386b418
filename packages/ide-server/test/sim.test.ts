import { existsSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import WebSocket from 'ws';
import { authFetch, BEARER, json, repo, startSite, type TestSite } from './helpers.js';

const MAA_SIM = path.join(repo, 'sim-server', '.venv', 'bin', 'maa-sim');
const haveSim = existsSync(MAA_SIM);
const APP = 'toast-service/TR.arcapp';

interface RosbridgeMessage {
    op: string;
    id?: string;
    topic?: string;
    service?: string;
    result?: boolean;
    values?: { topics?: string[] };
    msg?: { clock?: { sec: number; nanosec: number } };
}

/** A rosbridge v2 client over the backend's proxy that waits for the first message matching a predicate. */
function rosbridge(url: string): Promise<{ ws: WebSocket; next(match: (m: RosbridgeMessage) => boolean): Promise<RosbridgeMessage> }> {
    return new Promise((resolve, reject) => {
        const ws = new WebSocket(url, { headers: BEARER });
        const waiting: Array<{ match: (m: RosbridgeMessage) => boolean; done: (m: RosbridgeMessage) => void }> = [];
        ws.on('message', (data) => {
            const m = JSON.parse(String(data)) as RosbridgeMessage;
            for (const w of [...waiting]) {
                if (w.match(m)) {
                    waiting.splice(waiting.indexOf(w), 1);
                    w.done(m);
                }
            }
        });
        ws.once('error', reject);
        ws.once('open', () =>
            resolve({
                ws,
                next: (match) =>
                    new Promise((done, fail) => {
                        const timer = setTimeout(() => fail(new Error('no matching rosbridge message within 15 s')), 15_000);
                        waiting.push({
                            match,
                            done: (m) => {
                                clearTimeout(timer);
                                done(m);
                            },
                        });
                    }),
            }),
        );
    });
}

describe.skipIf(!haveSim)(
    `simulation session${haveSim ? '' : ` (skipped: ${MAA_SIM} is missing; run bash sim-server/scripts/setup_env.sh)`}`,
    () => {
        let site: TestSite;
        beforeAll(async () => {
            site = await startSite({ maaSim: MAA_SIM });
        });
        afterAll(() => site?.dispose());

        const start = (body: unknown) => authFetch(site.url('/api/sim/start'), { method: 'POST', body: JSON.stringify(body) });

        it('refuses a platform of the wrong kind for the mode', async () => {
            const res = await start({ app: APP, platform: 'rospython', mode: 'lockstep', speed: 1 });
            expect(res.status).toBe(400);
            expect((await json(res))['error']).toContain('lockstep mode needs a timesync platform');
            expect((await start({ app: APP, platform: 'timesync', mode: 'fast' })).status).toBe(400);
            expect((await start({ app: APP, platform: 'timesync', mode: 'lockstep', speed: -1 })).status).toBe(400);
        });

        it('runs lockstep (timesync): rosbridge and viser through the proxy, status, stop', async () => {
            const res = await start({ app: APP, platform: 'timesync', mode: 'lockstep', speed: 1 });
            const answer = await json(res);
            expect(res.status, JSON.stringify(answer)).toBe(200);
            expect(answer).toMatchObject({ ok: true, mode: 'lockstep', rosbridge: '/sim/rosbridge', viser: '/sim/viser/' });

            const status = await json(await authFetch(site.url('/api/sim/status')));
            expect(status).toMatchObject({ running: true, session: answer['session'], mode: 'lockstep', app: APP, platform: 'timesync' });

            const client = await rosbridge(site.url('/sim/rosbridge').replace(/^http/, 'ws'));
            try {
                client.ws.send(JSON.stringify({ op: 'call_service', id: 'topics', service: '/rosapi/topics', args: {} }));
                const topics = await client.next((m) => m.op === 'service_response' && m.id === 'topics');
                expect(topics.result).toBe(true);
                expect(topics.values?.topics).toContain('/clock');
                client.ws.send(JSON.stringify({ op: 'subscribe', id: 'clock', topic: '/clock' }));
                const clock = await client.next((m) => m.op === 'publish' && m.topic === '/clock');
                expect(typeof clock.msg?.clock?.sec).toBe('number');
            } finally {
                client.ws.close();
            }

            const viser = await authFetch(site.url('/sim/viser/'));
            expect(viser.status).toBe(200);
            expect(viser.headers.get('content-type')).toContain('text/html');
            expect(await viser.text()).toContain('<title>Viser</title>');
            const redirect = await authFetch(site.url('/sim/viser'), { redirect: 'manual' });
            expect(redirect.status).toBe(301);
            expect(redirect.headers.get('location')).toBe('/sim/viser/');
            // viser's client opens its WebSocket at the page URL without the trailing slash.
            const viserWs = new WebSocket(site.url('/sim/viser').replace(/^http/, 'ws'), ['viser-v1'], { headers: BEARER });
            await new Promise<void>((resolve, reject) => {
                viserWs.once('open', () => resolve());
                viserWs.once('error', reject);
            });
            viserWs.close();

            const stopped = await authFetch(site.url('/api/sim/stop'), { method: 'POST' });
            expect(await json(stopped)).toEqual({ ok: true });
            const after = await json<{ running: boolean; exitCode: number; log: string[] }>(await authFetch(site.url('/api/sim/status')));
            expect(after.running).toBe(false);
            expect(after.exitCode).toBe(0);
            expect(after.log.some((l) => l.includes('"event": "finished"'))).toBe(true);
            expect((await authFetch(site.url('/sim/viser/'))).status).toBe(502);
        });
    },
);

/** The pid and process group of the maa-sim whose command line names a folder below `dir` (from /proc). */
function simBelow(dir: string): { pid: number; pgid: number } | undefined {
    for (const name of readdirSync('/proc').filter((n) => /^\d+$/.test(n))) {
        try {
            const cmdline = readFileSync(`/proc/${name}/cmdline`, 'utf8').split('\0');
            if (!cmdline.some((a) => a.endsWith('maa-sim')) || !cmdline.some((a) => a.startsWith(dir))) continue;
            const stat = readFileSync(`/proc/${name}/stat`, 'utf8');
            return { pid: Number(name), pgid: Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[2]) };
        } catch {
            // gone meanwhile
        }
    }
    return undefined;
}

function groupAlive(pgid: number): boolean {
    try {
        process.kill(-pgid, 0);
        return true;
    } catch (e) {
        return (e as NodeJS.ErrnoException).code !== 'ESRCH';
    }
}

describe.skipIf(!haveSim || !existsSync('/proc'))('simulation session lifetime (real lockstep maa-sim)', () => {
    let site: TestSite;
    beforeAll(async () => {
        site = await startSite({ maaSim: MAA_SIM, sessionIdleSeconds: 2 });
    });
    afterAll(() => site?.dispose());

    it('ends when its last rosbridge client has been gone for the idle time, leaving no process of its group', async () => {
        const res = await authFetch(site.url('/api/sim/start'), {
            method: 'POST',
            body: JSON.stringify({ app: APP, platform: 'timesync', mode: 'lockstep', speed: 1 }),
        });
        expect(res.status, await res.clone().text()).toBe(200);
        const sim = simBelow(site.dir);
        expect(sim, 'maa-sim runs').toBeDefined();
        const pgid = sim!.pgid;
        expect(pgid, 'maa-sim leads a process group of its own').toBe(sim!.pid);
        const client = await rosbridge(site.url('/sim/rosbridge').replace(/^http/, 'ws'));
        client.ws.send(JSON.stringify({ op: 'call_service', id: 'topics', service: '/rosapi/topics', args: {} }));
        expect((await client.next((m) => m.id === 'topics')).result).toBe(true);
        const closed = new Promise((r) => client.ws.once('close', r));
        client.ws.close();
        await closed;
        // Not polling the status meanwhile: that would count as a sign of life.
        const deadline = Date.now() + 60_000;
        while (groupAlive(pgid) && Date.now() < deadline) await new Promise((r) => setTimeout(r, 200));
        expect(groupAlive(pgid), `process group ${pgid} still has processes 60 s after the client left`).toBe(false);
        const status = await json<{ running: boolean; log: string[] }>(await authFetch(site.url('/api/sim/status')));
        expect(status.running).toBe(false);
        expect(status.log.join('\n')).toContain('no client for 2 s');
    });
});
