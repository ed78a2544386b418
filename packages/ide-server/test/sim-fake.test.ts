import { chmodSync, writeFileSync } from 'node:fs';
import { createServer, type Server } from 'node:net';
import path from 'node:path';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { authFetch, json, startSite, TEST_TOKEN, type TestSite } from './helpers.js';

// Session supervision with stand-ins for maa-sim (shell scripts), so crashes and timeouts are
// tested without the simulator's start-up time.
describe('simulation sessions with a stand-in maa-sim', () => {
    let listener: Server;
    let port: number;
    let site: TestSite | undefined;

    beforeAll(async () => {
        // Something that accepts TCP connections, standing in for the rosbridge port.
        listener = createServer((socket) => socket.destroy());
        await new Promise<void>((resolve) => listener.listen(0, '127.0.0.1', resolve));
        port = (listener.address() as { port: number }).port;
    });
    afterAll(() => new Promise<void>((resolve) => listener.close(() => resolve())));
    afterEach(async () => {
        await site?.dispose();
        site = undefined;
    });

    async function siteWith(script: string, simReadyTimeoutMs?: number): Promise<TestSite> {
        const s = await startSite({ simReadyTimeoutMs });
        const fake = path.join(s.dir, 'fake-maa-sim');
        writeFileSync(fake, `#!/bin/bash\n${script}\n`);
        chmodSync(fake, 0o755);
        await s.server.close();
        const { startIdeServer } = await import('../src/index.js');
        s.server = await startIdeServer({ workspace: s.workspace, port: 0, token: TEST_TOKEN, maaSim: fake, simReadyTimeoutMs });
        return s;
    }

    const start = (s: TestSite) =>
        authFetch(s.url('/api/sim/start'), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' }),
        });

    it('reports a simulator that exits before it is ready, with the log tail', async () => {
        site = await siteWith('echo "loading $2" >&2; echo "boom: no scene" >&2; exit 3');
        const res = await start(site);
        expect(res.status).toBe(500);
        const body = await json<{ error: string; log: string[] }>(res);
        expect(body.error).toContain('exit code 3');
        expect(body.error).toContain('boom: no scene');
        expect(body.log).toContain('boom: no scene');
        const status = await json<{ running: boolean; exitCode: number; log: string[] }>(await authFetch(site.url('/api/sim/status')));
        expect(status.running).toBe(false);
        expect(status.exitCode).toBe(3);
        expect(status.log.join('\n')).toContain('boom: no scene');
    });

    it('times out a simulator that never gets ready and stops it', async () => {
        site = await siteWith('echo "still loading" >&2; exec sleep 30', 1500);
        const res = await start(site);
        expect(res.status).toBe(504);
        expect((await json(res))['error']).toContain('still loading');
        expect((await json(await authFetch(site.url('/api/sim/status'))))['running']).toBe(false);
    });

    it('reports a crash after the start and keeps serving', async () => {
        site = await siteWith(
            `echo '{"event": "ready", "rosbridge": "ws://127.0.0.1:${port}", "viser": null}'; sleep 0.5; echo "Traceback: oops" >&2; exit 1`,
        );
        const res = await start(site);
        expect(res.status, JSON.stringify(await res.clone().json())).toBe(200);
        let status = await json<{ running: boolean; exitCode?: number; log: string[] }>(await authFetch(site.url('/api/sim/status')));
        for (let i = 0; i < 50 && status.running; i++) {
            await new Promise((r) => setTimeout(r, 100));
            status = await json(await authFetch(site.url('/api/sim/status')));
        }
        expect(status.running).toBe(false);
        expect(status.exitCode).toBe(1);
        expect(status.log.join('\n')).toContain('Traceback: oops');
        expect((await authFetch(site.url('/sim/viser/'))).status).toBe(502);
        expect((await authFetch(site.url('/api/files'))).status).toBe(200);
    });
});
