// Students' live simulations run in sim-server's sandbox (src/workspaces/sim-sandbox.ts,
// `python -m maa_sim.sandbox`): maa-sim (and with it the student's components) runs in a pid
// namespace of its own, as a uid of its own (the lab runs as root here), with a ROS 2 domain of
// its workspace, and sees of the lab's data folder only its workspace's generated and simulation
// folders: neither another student's workspace nor the database beside them.
import { existsSync, readdirSync, readFileSync, readlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { startBackend } from './backends.js';
import { EXERCISE, type Lab, MAA_SIM, repo, startLab } from './workspace-setup.js';

const haveSim = existsSync(MAA_SIM);
const haveBwrap = existsSync('/usr/bin/bwrap') || (process.env.PATH ?? '').split(':').some((d) => existsSync(path.join(d, 'bwrap')));
const root = process.getuid?.() === 0;
const START = { app: 'TR.arcapp', platform: 'timesync', mode: 'lockstep' };

/** The process's children (Linux /proc). */
function children(pid: number): number[] {
    try {
        return readFileSync(`/proc/${pid}/task/${pid}/children`, 'utf8').split(/\s+/).filter(Boolean).map(Number);
    } catch {
        return [];
    }
}

/** maa-sim itself below the session's process (the sandbox CLI → bwrap → the sandbox's pid 1 → maa-sim). */
function maaSimBelow(pid: number): number | undefined {
    const queue = [pid];
    while (queue.length > 0) {
        const p = queue.shift()!;
        const cmdline = readFileSync(`/proc/${p}/cmdline`, 'utf8').split('\0');
        if (
            cmdline.some((a) => a.endsWith('maa-sim')) &&
            cmdline.includes('--package') &&
            !cmdline.includes('maa_sim.sandbox') &&
            !cmdline[0]!.endsWith('bwrap')
        )
            return p;
        queue.push(...children(p));
    }
    return undefined;
}

const statusField = (pid: number, field: string) =>
    readFileSync(`/proc/${pid}/status`, 'utf8')
        .split('\n')
        .find((l) => l.startsWith(`${field}:`))!
        .slice(field.length + 1)
        .trim()
        .split(/\s+/);

const environ = (pid: number) =>
    Object.fromEntries(
        readFileSync(`/proc/${pid}/environ`, 'utf8')
            .split('\0')
            .filter(Boolean)
            .map((kv) => [kv.slice(0, kv.indexOf('=')), kv.slice(kv.indexOf('=') + 1)]),
    );

describe.skipIf(!haveSim || !haveBwrap)(
    `sandboxed simulations${haveSim && haveBwrap ? '' : ' (skipped: maa-sim or bwrap is missing)'}`,
    () => {
        let lab: Lab;
        let dispose: () => Promise<void>;

        beforeAll(async () => {
            const backend = await startBackend('pglite');
            lab = await startLab(await backend.freshStorage(), { workspaces: { simIdleSeconds: 60, sweepMs: 200 } });
            dispose = async () => {
                await lab.dispose();
                await backend.dispose();
            };
        }, 120_000);
        afterAll(async () => dispose?.());

        const wsId = async (login: string) => {
            const course = await lab.store.findCourse('robotics');
            const found = await lab.store.findExercise(course!.id, EXERCISE);
            return (await lab.store.workspace((await lab.store.findUserByLogin(login))!.id, found!.id)).id;
        };

        it('runs maa-sim in its own pid namespace and uid, with its own ROS 2 domain, seeing only its workspace’s generated folder', async () => {
            // a stand-in for the lab's database file beside the workspaces
            writeFileSync(path.join(lab.dataDir, 'lab.sqlite'), 'password hashes');
            const [ada, bob] = await Promise.all(['ada', 'bob'].map((l) => lab.as(l)));
            const sims: Record<string, number> = {};
            for (const [login, client] of [
                ['ada', ada],
                ['bob', bob],
            ] as const) {
                const answer = await client.post(`${lab.ws(login)}/sim/start`, START);
                expect(answer.status, answer.text).toBe(200);
                const group = lab.server.workspaces.pool.find(await wsId(login))?.sims.processGroup();
                expect(group).toBeTypeOf('number');
                const pid = maaSimBelow(group!);
                expect(pid, `maa-sim below ${group}`).toBeTypeOf('number');
                sims[login] = pid!;
            }
            const [adaPid, bobPid] = [sims['ada']!, sims['bob']!];
            for (const pid of [adaPid, bobPid]) {
                // NSpid: its pid on the host and in its own pid namespace
                expect(statusField(pid, 'NSpid')).toHaveLength(2);
                expect(readlinkSync(`/proc/${pid}/ns/pid`)).not.toBe(readlinkSync('/proc/self/ns/pid'));
                // the host's network (the lab proxies to its ports on 127.0.0.1), see docs/lab.md "Sandbox"
                expect(readlinkSync(`/proc/${pid}/ns/net`)).toBe(readlinkSync('/proc/self/ns/net'));
            }
            if (root) {
                const uids = [adaPid, bobPid].map((pid) => Number(statusField(pid, 'Uid')[0]));
                for (const uid of uids) expect(uid).toBeGreaterThanOrEqual(61000);
                expect(uids[0]).not.toBe(uids[1]);
            }
            const [adaEnv, bobEnv] = [environ(adaPid), environ(bobPid)];
            expect(adaEnv['ROS_DOMAIN_ID']).toMatch(/^\d+$/);
            expect(adaEnv['ROS_DOMAIN_ID']).not.toBe(bobEnv['ROS_DOMAIN_ID']);
            expect(adaEnv['MAA_SIM_ROS_DOMAIN']).toBe(adaEnv['ROS_DOMAIN_ID']); // maa-sim's own nodes use it
            expect(adaEnv['HOME']).toBe('/tmp');
            expect(adaEnv['MAA_SIM_TOKEN']).toBeTruthy();
            // Its view of the lab's data folder: its own workspace's generated and simulation folders only.
            const baseOf = async (login: string) => path.dirname(lab.server.workspaces.pool.find(await wsId(login))!.folder.root);
            const [adaBase, bobBase] = [await baseOf('ada'), await baseOf('bob')];
            const view = (p: string) => `/proc/${adaPid}/root${p}`;
            expect(existsSync(bobBase)).toBe(true);
            expect(existsSync(view(bobBase))).toBe(false);
            expect(readdirSync(view(path.dirname(adaBase)))).toEqual([path.basename(adaBase)]);
            expect(readdirSync(view(adaBase)).sort()).toEqual(['generated', 'sim']);
            expect(existsSync(path.join(lab.dataDir, 'lab.sqlite'))).toBe(true);
            expect(existsSync(view(path.join(lab.dataDir, 'lab.sqlite')))).toBe(false);
            // of the repository only what maa-sim needs (its venv, sim-server/src), not the rest
            expect(existsSync(`/proc/${adaPid}/root${MAA_SIM}`)).toBe(true);
            expect(existsSync(`/proc/${adaPid}/root${path.join(repo, 'package.json')}`)).toBe(false);
            expect(existsSync(`/proc/${adaPid}/root${path.join(repo, 'examples')}`)).toBe(false);
            for (const c of [ada, bob]) expect((await c.post(`${lab.ws(c === ada ? 'ada' : 'bob')}/sim/stop`, {})).status).toBe(200);
        }, 300_000);
    },
);
