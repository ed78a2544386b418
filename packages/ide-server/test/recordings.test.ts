import { chmodSync, existsSync, mkdirSync, readFileSync, symlinkSync, writeFileSync } from 'node:fs';
import { createServer, type Server } from 'node:net';
import path from 'node:path';
import { afterAll, afterEach, beforeAll, describe, expect, it } from 'vitest';
import { recordingName } from '../src/recordings.js';
import { authFetch, json, rawRequest, startSite, TEST_TOKEN, type TestSite } from './helpers.js';

// Record and replay (docs/ide.md "Record and replay"): the routes with a stand-in maa-sim that
// writes its command line to a file and announces a ready line, so what the backend asks of
// maa-sim is checked without the simulator's start-up time (the e2e replay scenario runs the real one).
describe('recordings and replay sessions', () => {
    let listener: Server;
    let port: number;
    let site: TestSite | undefined;

    beforeAll(async () => {
        listener = createServer((socket) => socket.destroy()); // stands in for the rosbridge port
        await new Promise<void>((resolve) => listener.listen(0, '127.0.0.1', resolve));
        port = (listener.address() as { port: number }).port;
    });
    afterAll(() => new Promise<void>((resolve) => listener.close(() => resolve())));
    afterEach(async () => {
        await site?.dispose();
        site = undefined;
    });

    /** A site whose maa-sim writes its arguments (one per line) to `<dir>/args` and then serves until stopped. */
    async function siteWithFake(): Promise<{ site: TestSite; args: () => string[] }> {
        const s = await startSite();
        const fake = path.join(s.dir, 'fake-maa-sim');
        const argsFile = path.join(s.dir, 'args');
        writeFileSync(
            fake,
            `#!/bin/bash\nprintf '%s\\n' "$@" > '${argsFile}'\necho '{"event": "ready", "rosbridge": "ws://127.0.0.1:${port}", "viser": null}'\nexec sleep 60\n`,
        );
        chmodSync(fake, 0o755);
        await s.server.close();
        const { startIdeServer } = await import('../src/index.js');
        s.server = await startIdeServer({ workspace: s.workspace, port: 0, token: TEST_TOKEN, maaSim: fake, simStopGraceMs: 2000 });
        return { site: s, args: () => readFileSync(argsFile, 'utf8').trim().split('\n') };
    }

    function addRecording(s: TestSite, name: string, meta?: object): string {
        const dir = path.join(s.workspace, 'recordings');
        mkdirSync(dir, { recursive: true });
        const file = path.join(dir, name);
        writeFileSync(file, 'MCAP stand-in');
        if (meta) writeFileSync(file.replace(/\.mcap$/, '.json'), JSON.stringify(meta));
        return file;
    }

    const replay = (s: TestSite, recording: unknown) =>
        authFetch(s.url('/api/sim/replay'), { method: 'POST', body: JSON.stringify({ recording }) });

    it('records a run when asked: maa-sim gets --record <workspace>/recordings/<App>-<time>.mcap, the app and platform beside it', async () => {
        const fake = await siteWithFake();
        site = fake.site;
        const res = await authFetch(site.url('/api/sim/start'), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', record: true }),
        });
        expect(res.status, await res.clone().text()).toBe(200);
        const args = fake.args();
        expect(args[0]).toBe('run');
        const target = args[args.indexOf('--record') + 1]!;
        expect(path.dirname(target)).toBe(path.join(site.workspace, 'recordings'));
        expect(path.basename(target)).toMatch(/^TR-\d{8}-\d{6}\.mcap$/);
        expect(JSON.parse(readFileSync(target.replace(/\.mcap$/, '.json'), 'utf8'))).toEqual({
            app: 'toast-service/TR.arcapp',
            platform: 'timesync',
            mode: 'lockstep',
        });
        const status = await json<{ recording?: string }>(await authFetch(site.url('/api/sim/status')));
        expect(status.recording).toBe(path.basename(target));
    });

    it('does not record unless asked, and refuses a record flag that is no boolean', async () => {
        const fake = await siteWithFake();
        site = fake.site;
        const bad = await authFetch(site.url('/api/sim/start'), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', record: 'yes' }),
        });
        expect(bad.status).toBe(400);
        expect((await json(bad))['error']).toContain('record must be true or false');
        const res = await authFetch(site.url('/api/sim/start'), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync' }),
        });
        expect(res.status).toBe(200);
        expect(fake.args()).not.toContain('--record');
        expect(existsSync(path.join(site.workspace, 'recordings'))).toBe(false);
    });

    it('lists the complete recordings, newest first, with what the IDE knows of them', async () => {
        site = await startSite();
        expect(await json(await authFetch(site.url('/api/sim/recordings')))).toEqual({ recordings: [] });
        addRecording(site, 'TR-20260101-100000.mcap', { app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' });
        addRecording(site, 'other.mcap'); // from elsewhere: no JSON beside it
        addRecording(site, 'running.mcap.part');
        addRecording(site, 'notes.txt');
        addRecording(site, '.hidden.mcap');
        const { recordings } = await json<{ recordings: { name: string; app?: string; size: number }[] }>(
            await authFetch(site.url('/api/sim/recordings')),
        );
        expect(recordings.map((r) => r.name).sort()).toEqual(['TR-20260101-100000.mcap', 'other.mcap']);
        const tr = recordings.find((r) => r.name.startsWith('TR-'))!;
        expect(tr).toMatchObject({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep', size: 13 });
        expect(recordings.find((r) => r.name === 'other.mcap')).not.toHaveProperty('app');
    });

    it('replays a recording: maa-sim replay <file> with the ports it picks; the status names the recording', async () => {
        const fake = await siteWithFake();
        site = fake.site;
        const file = addRecording(site, 'TR-20260101-100000.mcap', {
            app: 'toast-service/TR.arcapp',
            platform: 'timesync',
            mode: 'lockstep',
        });
        const res = await replay(site, 'TR-20260101-100000.mcap');
        expect(res.status, await res.clone().text()).toBe(200);
        const answer = await json<{ ok: boolean; recording: { app: string }; rosbridge: string; viser: string }>(res);
        expect(answer).toMatchObject({ ok: true, recording: { app: 'toast-service/TR.arcapp' }, rosbridge: '/sim/rosbridge' });
        expect(fake.args()).toEqual(['replay', file, '--rosbridge-port', '0', '--viser-port', '0', '--host', '127.0.0.1', '--status-json']);
        const status = await json<{ running: boolean; replay?: string; app?: string }>(await authFetch(site.url('/api/sim/status')));
        expect(status).toMatchObject({ running: true, replay: 'TR-20260101-100000.mcap', app: 'toast-service/TR.arcapp' });
        expect((await authFetch(site.url('/api/sim/stop'), { method: 'POST', body: '{}' })).status).toBe(200);
        expect((await json(await authFetch(site.url('/api/sim/status'))))['running']).toBe(false);
    });

    it('refuses names that leave recordings/, names no recording, and a symlink out of the workspace', async () => {
        const fake = await siteWithFake();
        site = fake.site;
        addRecording(site, 'ok.mcap');
        symlinkSync('/etc/passwd', path.join(site.workspace, 'recordings', 'evil.mcap'));
        writeFileSync(path.join(site.workspace, 'secret.mcap'), 'x');
        for (const name of ['../secret.mcap', 'recordings/ok.mcap', '/etc/passwd', '..%2fsecret.mcap', 'ok.txt', '.ok.mcap', '', 3, null]) {
            const res = await replay(site, name);
            expect(res.status, JSON.stringify(name)).toBe(400);
        }
        expect((await replay(site, 'missing.mcap')).status).toBe(404);
        const evil = await replay(site, 'evil.mcap');
        expect(evil.status).toBe(403);
        expect((await json(evil))['error']).not.toContain('/etc');
        // nothing was started by any of them
        expect(existsSync(path.join(site.dir, 'args'))).toBe(false);
        const listed = await json<{ recordings: { name: string }[] }>(await authFetch(site.url('/api/sim/recordings')));
        expect(listed.recordings.map((r) => r.name)).toEqual(['ok.mcap']);
    });

    it('guards the routes like every other: no token 401, a foreign Origin or Host 403', async () => {
        site = await startSite();
        addRecording(site, 'ok.mcap');
        const base = site.server.url;
        const own = new URL(base).host;
        const body = JSON.stringify({ recording: 'ok.mcap' });
        const post = { method: 'POST', body, headers: { 'Content-Type': 'application/json' } };
        expect((await rawRequest(base, '/api/sim/recordings', { headers: { Authorization: null } })).status).toBe(401);
        expect((await rawRequest(base, '/api/sim/replay', { ...post, headers: { ...post.headers, Authorization: null } })).status).toBe(
            401,
        );
        expect(
            (await rawRequest(base, '/api/sim/replay', { ...post, headers: { ...post.headers, Origin: 'http://evil.example' } })).status,
        ).toBe(403);
        expect((await rawRequest(base, '/api/sim/recordings', { headers: { Origin: 'http://evil.example' } })).status).toBe(403);
        expect((await rawRequest(base, '/api/sim/recordings', { headers: { Host: 'evil.example' } })).status).toBe(403);
        expect((await rawRequest(base, '/api/sim/recordings', { headers: { Origin: `http://${own}` } })).status).toBe(200);
        expect((await rawRequest(base, '/api/sim/recordings', { method: 'DELETE' })).status).toBe(405);
    });

    it('names recordings after the application and the UTC time, never twice', () => {
        const now = new Date('2026-01-24T17:03:02.123Z');
        expect(recordingName('examples/toast-service/TR.arcapp', now)).toBe('TR-20260124-170302.mcap');
        expect(recordingName('a b/Ström.arcapp', now)).toBe('Str_m-20260124-170302.mcap');
        expect(recordingName('_x.arcapp', now)).toBe('run_x-20260124-170302.mcap');
        expect(recordingName('TR.arcapp', now, new Set(['TR-20260124-170302.mcap', 'TR-20260124-170302-2.mcap']))).toBe(
            'TR-20260124-170302-3.mcap',
        );
    });
});
