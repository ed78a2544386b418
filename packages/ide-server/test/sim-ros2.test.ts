import { chmodSync, existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { request } from 'node:http';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import WebSocket from 'ws';
import { HttpError } from '../src/http-util.js';
import { findInterfacePackages, Ros2Environment } from '../src/ros2-environment.js';
import { SimSessions } from '../src/sim-session.js';
import { authFetch, BEARER, json, repo, startSite, type TestSite } from './helpers.js';

const ROS2_VENV = path.join(repo, 'packages', 'generators-python', '.venv-ros2');
const SCRIPTS = path.join(repo, 'packages', 'generators-python', 'scripts');
const haveVenv = existsSync(path.join(ROS2_VENV, 'bin', 'maa-sim'));
const switchedOff = process.env['MAA_TEST_ROS2'] === '0';
const skipReason = switchedOff
    ? ' (skipped: MAA_TEST_ROS2=0)'
    : haveVenv
      ? ''
      : ` (skipped: ${ROS2_VENV}/bin/maa-sim is missing; run bash packages/generators-python/scripts/setup_ros2_venv.sh)`;
const APP = 'toast-service/TR.arcapp';
const LONG = 180_000;

/** A POST without fetch's 300 s header timeout: a cold start sets up the venv first (minutes). */
function post(url: string, body: unknown): Promise<{ status: number; body: Record<string, unknown> }> {
    return new Promise((resolve, reject) => {
        const req = request(url, { method: 'POST', headers: { 'Content-Type': 'application/json', ...BEARER } }, (res) => {
            let text = '';
            res.setEncoding('utf8');
            res.on('data', (c: string) => (text += c));
            res.on('end', () => resolve({ status: res.statusCode ?? 0, body: JSON.parse(text) as Record<string, unknown> }));
        });
        req.on('error', reject);
        req.end(JSON.stringify(body));
    });
}

interface RosbridgeMessage {
    op: string;
    id?: string;
    result?: boolean;
    values?: { topics?: string[]; nodes?: Array<{ name: string; state: string }> };
}

/** A rosbridge v2 client with request/answer calls. */
async function rosbridge(url: string): Promise<{ ws: WebSocket; call(service: string): Promise<RosbridgeMessage> }> {
    const ws = new WebSocket(url, { headers: BEARER });
    const waiting = new Map<string, (m: RosbridgeMessage) => void>();
    ws.on('message', (data) => {
        const m = JSON.parse(String(data)) as RosbridgeMessage;
        if (m.op === 'service_response' && m.id) waiting.get(m.id)?.(m);
    });
    await new Promise<void>((resolve, reject) => {
        ws.once('open', () => resolve());
        ws.once('error', reject);
    });
    let n = 0;
    return {
        ws,
        call: (service) =>
            new Promise((resolve, reject) => {
                const id = `call-${++n}`;
                const timer = setTimeout(() => reject(new Error(`no answer of ${service} within 30 s`)), 30_000);
                waiting.set(id, (m) => {
                    clearTimeout(timer);
                    waiting.delete(id);
                    resolve(m);
                });
                ws.send(JSON.stringify({ op: 'call_service', id, service, args: {} }));
            }),
    };
}

describe.skipIf(!haveVenv || switchedOff)(`ROS 2 simulation session (rospython in ${path.basename(ROS2_VENV)})${skipReason}`, () => {
    let site: TestSite;
    beforeAll(async () => {
        site = await startSite({ ros2Venv: ROS2_VENV });
    });
    afterAll(() => site?.dispose());

    it(
        'installs the interface package, runs every node, port topics over the proxied rosbridge, stops',
        async () => {
            const t0 = Date.now();
            const started = await post(site.url('/api/sim/start'), { app: APP, platform: 'rospython', speed: 1 });
            const startSeconds = (Date.now() - t0) / 1000;
            const status = await json<{ running: boolean; mode: string; log: string[] }>(await authFetch(site.url('/api/sim/status')));
            expect(started.status, `${JSON.stringify(started.body)}\n${status.log.join('\n')}`).toBe(200);
            expect(started.body).toMatchObject({ ok: true, mode: 'ros2', rosbridge: '/sim/rosbridge' });
            expect(status).toMatchObject({ running: true, mode: 'ros2', platform: 'rospython' });
            expect(status.log.join('\n')).toContain('maa-ide: toast_service_robot_interfaces is installed');

            const deployment = JSON.parse(
                await (
                    await authFetch(
                        site.url(
                            `/api/generated/file?app=${encodeURIComponent(APP)}&platform=rospython&path=toast_service_robot/deployment.json`,
                        ),
                    )
                ).text(),
            ) as { nodes: Array<{ name: string; namespace: string }> };
            const expected = deployment.nodes.map((n) => `${n.namespace}/${n.name}`).sort();
            expect(expected.length).toBeGreaterThan(1);

            const client = await rosbridge(site.url('/sim/rosbridge').replace(/^http/, 'ws'));
            try {
                // Port topics appear once the nodes' publishers are discovered.
                let topics: string[] = [];
                for (let i = 0; i < 60 && !topics.includes('/toast_service_robot/ctrl/arm'); i++) {
                    if (i > 0) await new Promise((r) => setTimeout(r, 500));
                    const answer = await client.call('/rosapi/topics');
                    expect(answer.result).toBe(true);
                    topics = answer.values?.topics ?? [];
                }
                expect(topics).toContain('/toast_service_robot/ctrl/arm');
                expect(topics).toContain('/clock');

                const sim = await client.call('/sim/get_status');
                expect(sim.result).toBe(true);
                const nodes = sim.values?.nodes ?? [];
                expect(nodes.map((n) => n.name).sort()).toEqual(expected);
                expect(
                    nodes.filter((n) => n.state !== 'running'),
                    JSON.stringify(nodes),
                ).toEqual([]);
            } finally {
                client.ws.close();
            }
            console.log(
                `ROS 2 session: start answered after ${startSeconds.toFixed(1)} s (generation, interface install, ${expected.length} nodes up)`,
            );

            const stopped = await post(site.url('/api/sim/stop'), {});
            expect(stopped.body).toEqual({ ok: true });
            const after = await json<{ running: boolean; exitCode: number; log: string[] }>(await authFetch(site.url('/api/sim/status')));
            expect(after.running).toBe(false);
            expect(after.exitCode, after.log.join('\n')).toBe(0);
            expect((await authFetch(site.url('/sim/viser/'))).status).toBe(502);
        },
        LONG,
    );
});

describe('ROS 2 environment preparation with stand-in scripts', () => {
    let dir: string;
    beforeAll(() => {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-ide-ros2-'));
    });
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    function script(name: string, body: string): string {
        const file = path.join(dir, name);
        writeFileSync(file, `#!/bin/bash\n${body}\n`);
        chmodSync(file, 0o755);
        return file;
    }

    /** A platform folder like rospython's: the ament_python package and an interface package. */
    function platform(name: string): string {
        const root = path.join(dir, name);
        mkdirSync(path.join(root, 'robot', 'robot'), { recursive: true });
        writeFileSync(path.join(root, 'robot', 'package.xml'), '<package/>');
        const iface = path.join(root, 'robot_interfaces');
        mkdirSync(path.join(iface, 'msg'), { recursive: true });
        writeFileSync(path.join(iface, 'package.xml'), '<package/>');
        writeFileSync(path.join(iface, 'CMakeLists.txt'), 'rosidl_generate_interfaces(robot_interfaces\n  "msg/A.msg"\n)\n');
        return root;
    }

    it('finds the interface packages of a generated platform', () => {
        const root = platform('find');
        expect(findInterfacePackages(root)).toEqual([path.join(root, 'robot_interfaces')]);
        expect(findInterfacePackages(path.join(dir, 'missing'))).toEqual([]);
    });

    it('sets up a missing venv, installs the interface package, and reports progress', async () => {
        const venv = path.join(dir, 'venv-a');
        const setup = script(
            'setup.sh',
            `echo "setup: creating"; sleep 1.2; mkdir -p ${venv}/bin; touch ${venv}/bin/python ${venv}/bin/maa-sim; echo "setup: ready"`,
        );
        const install = script('install.sh', 'echo "install: $(basename "$2") into $1"');
        const env = new Ros2Environment({ venv, setupScript: setup, installScript: install, heartbeatSeconds: 0.5 });
        const log: string[] = [];
        const maaSim = await env.prepare(platform('a'), (l) => log.push(l), new AbortController().signal);
        expect(maaSim).toBe(path.join(venv, 'bin', 'maa-sim'));
        expect(log).toContain('setup: ready');
        expect(log.some((l) => l.startsWith('maa-ide: still setting up the ROS 2 environment'))).toBe(true);
        expect(log).toContain(`install: robot_interfaces into ${venv}`);
        expect(log.some((l) => l.startsWith('maa-ide: robot_interfaces is installed'))).toBe(true);
    });

    it('fails with the output tail when the build fails, and when the venv is missing without a setup script', async () => {
        const venv = path.join(dir, 'venv-b');
        mkdirSync(path.join(venv, 'bin'), { recursive: true });
        writeFileSync(path.join(venv, 'bin', 'python'), '');
        writeFileSync(path.join(venv, 'bin', 'maa-sim'), '');
        const install = script('install-fails.sh', 'echo "CMake Error: msg/A.msg: unknown type" >&2; exit 1');
        const env = new Ros2Environment({ venv, installScript: install });
        const error = await env.prepare(platform('b'), () => undefined, new AbortController().signal).catch((e: unknown) => e);
        expect(error).toBeInstanceOf(HttpError);
        expect((error as HttpError).status).toBe(500);
        expect((error as HttpError).message).toContain('building the interface package robot_interfaces failed (exit code 1)');
        expect((error as HttpError).message).toContain('CMake Error: msg/A.msg: unknown type');

        const missing = new Ros2Environment({ venv: path.join(dir, 'nothing'), installScript: install });
        const error2 = await missing.prepare(platform('c'), () => undefined, new AbortController().signal).catch((e: unknown) => e);
        expect((error2 as HttpError).status).toBe(500);
        expect((error2 as HttpError).message).toContain('setup_ros2_venv.sh');
    });

    it('cancels a running step at once', async () => {
        const venv = path.join(dir, 'venv-d');
        const env = new Ros2Environment({
            venv,
            setupScript: script('slow-setup.sh', 'echo "setup: slow"; sleep 60'),
            installScript: script('noop.sh', 'true'),
        });
        const abort = new AbortController();
        const t0 = Date.now();
        const pending = env.prepare(platform('d'), () => undefined, abort.signal).catch((e: unknown) => e);
        await new Promise((r) => setTimeout(r, 500));
        abort.abort();
        const error = await pending;
        expect((error as HttpError).status).toBe(409);
        expect(Date.now() - t0).toBeLessThan(5_000);
    });

    it('shows a preparing session in the status, and a stop cancels it', async () => {
        const root = platform('e');
        writeFileSync(path.join(root, 'robot', 'deployment.json'), '{"nodes": []}');
        const env = new Ros2Environment({
            venv: path.join(dir, 'venv-f'),
            setupScript: script('slow-setup-2.sh', 'echo "setup: downloading"; sleep 60'),
            installScript: script('noop-2.sh', 'true'),
        });
        const sims = new SimSessions(path.join(dir, 'no-lockstep-maa-sim'), { readyTimeoutMs: 90_000 }, env);
        const t0 = Date.now();
        const starting = sims.start({ app: 'a/A.arcapp', platform: 'rospython', mode: 'ros2', platformDir: root }).catch((e: unknown) => e);
        for (let i = 0; i < 50 && !sims.status().log.includes('setup: downloading'); i++) await new Promise((r) => setTimeout(r, 100));
        expect(sims.status()).toMatchObject({ running: false, preparing: true, mode: 'ros2', platform: 'rospython' });
        expect(sims.target()).toBeUndefined();
        await sims.stop();
        expect(((await starting) as HttpError).status).toBe(409);
        expect(Date.now() - t0).toBeLessThan(10_000);
        const status = sims.status();
        expect(status.running).toBe(false);
        expect(status.preparing).toBeUndefined();
        expect(status.log.at(-1)).toContain('cancelled');
        sims.dispose();
    });

    it('answers a 500 with the log tail through the API when installing the interfaces fails, and keeps serving', async () => {
        // A venv whose python has no rclpy: the real install script refuses it.
        const venv = path.join(dir, 'venv-e');
        mkdirSync(path.join(venv, 'bin'), { recursive: true });
        writeFileSync(path.join(venv, 'bin', 'python'), '#!/bin/bash\nexit 1\n');
        writeFileSync(path.join(venv, 'bin', 'maa-sim'), '#!/bin/bash\nexit 1\n');
        chmodSync(path.join(venv, 'bin', 'python'), 0o755);
        chmodSync(path.join(venv, 'bin', 'maa-sim'), 0o755);
        expect(existsSync(path.join(SCRIPTS, 'install_ros2_interfaces.sh'))).toBe(true);
        const site = await startSite({ ros2Venv: venv });
        try {
            const res = await post(site.url('/api/sim/start'), { app: APP, platform: 'rospython' });
            expect(res.status).toBe(500);
            expect(String(res.body['error'])).toContain('building the interface package toast_service_robot_interfaces failed');
            expect(String(res.body['error'])).toContain('has no rclpy');
            expect((res.body['log'] as string[]).join('\n')).toContain('has no rclpy');
            const status = await json<{ running: boolean; preparing?: boolean; log: string[] }>(
                await authFetch(site.url('/api/sim/status')),
            );
            expect(status.running).toBe(false);
            expect(status.preparing).toBeUndefined();
            expect(status.log.join('\n')).toContain('has no rclpy');
            expect((await authFetch(site.url('/api/files'))).status).toBe(200);
        } finally {
            await site.dispose();
        }
    });
});
