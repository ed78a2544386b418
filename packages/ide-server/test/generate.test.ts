import { appendFileSync, existsSync, readFileSync, symlinkSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import type { GenerateAnswer } from '../src/index.js';
import { authFetch, json, q, startSite, type TestSite } from './helpers.js';

const APP = 'toast-service/TR.arcapp';

describe('apps and generation (on a copy of examples/)', () => {
    let site: TestSite | undefined;
    afterEach(async () => {
        await site?.dispose();
        site = undefined;
    });

    const post = (s: TestSite, body: unknown) =>
        authFetch(s.url('/api/generate'), { method: 'POST', body: JSON.stringify(body), headers: { 'Content-Type': 'application/json' } });

    it('lists the application configurations with their platforms and kinds', async () => {
        site = await startSite();
        writeFileSync(path.join(site.workspace, 'empty.arcapp'), '// no application yet\n');
        const res = await authFetch(site.url('/api/apps'));
        expect(res.status).toBe(200);
        const { apps } = await json<{
            apps: Array<{ path: string; name: string; component: string; platforms: Array<{ name: string; kind: string }> }>;
        }>(res);
        // examples/lab/: the starters of the lab exercises are applications too (toast-controller's
        // starter holds only its Controller: the rest, TR.arcapp too, is its base examples/toast-service).
        expect(apps.map((a) => a.path).sort()).toEqual([
            'lab/line-follower/starter/LineFollowing.arcapp',
            'lab/pick-and-place/starter/Sorting.arcapp',
            APP,
        ]);
        expect(apps.find((a) => a.path === APP)).toMatchObject({
            path: APP,
            name: 'TR',
            component: 'toast.ToastServiceRobot',
            platforms: [
                { name: 'rospython', kind: 'ros2' },
                { name: 'timesync', kind: 'timesync' },
            ],
        });
    });

    it('generates timesync and rospython (concurrent requests queue), serves files and the trace', async () => {
        site = await startSite();
        const s = site;
        const [timesync, rospython] = await Promise.all([
            post(s, { app: APP, platform: 'timesync' }),
            post(s, { app: APP, platform: 'rospython' }),
        ]);
        for (const [res, platform, marker] of [
            [timesync, 'timesync', 'lockstep.json'],
            [rospython, 'rospython', 'toast_service_robot/deployment.json'],
        ] as const) {
            expect(res.status).toBe(200);
            const answer = await json<GenerateAnswer>(res);
            expect(answer.ok, JSON.stringify(answer.diagnostics)).toBe(true);
            expect(answer.platform).toBe(platform);
            expect(answer.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
            const files = answer.files.map((f) => f.path);
            expect(files).toContain(marker);
            expect(files).toEqual([...files].sort());
            // Output lies outside the workspace (docs/ide.md), the workspace is untouched.
            const onDisk = path.join(s.dir, '.maa-ide-out', APP, platform, marker);
            expect(answer.files.find((f) => f.path === marker)!.size).toBe(readFileSync(onDisk).length);

            const file = await authFetch(s.url(`/api/generated/file?${q({ app: APP, platform, path: marker })}`));
            expect(file.status).toBe(200);
            expect(await file.text()).toBe(readFileSync(onDisk, 'utf8'));

            const trace = await authFetch(s.url(`/api/generated/trace?${q({ app: APP, platform })}`));
            expect(trace.status).toBe(200);
            expect(trace.headers.get('content-type')).toContain('application/json');
            const body = await json<{ platform: string; rootComponent: string; files: Array<{ path: string }> }>(trace);
            expect(body.platform).toBe(platform);
            expect(body.rootComponent).toBe('toast.ToastServiceRobot');
            expect(body.files.map((f) => f.path)).toContain(marker);
        }
        const listing = await json<{ entries: Array<{ path: string }> }>(await authFetch(s.url('/api/files')));
        expect(listing.entries.some((e) => e.path.includes('lockstep'))).toBe(false);

        // The generated-file routes confine like the workspace routes.
        const outside = path.join(s.dir, 'outside.txt');
        writeFileSync(outside, 'outside');
        symlinkSync(outside, path.join(s.dir, '.maa-ide-out', APP, 'timesync', 'link.txt'));
        const cases: Array<[Record<string, string>, number]> = [
            [{ app: APP, platform: 'timesync', path: '../rospython/.maa-trace.json' }, 400],
            [{ app: APP, platform: 'timesync', path: '/etc/passwd' }, 400],
            [{ app: APP, platform: '../x', path: 'lockstep.json' }, 400],
            [{ app: '../x.arcapp', platform: 'timesync', path: 'lockstep.json' }, 400],
            [{ app: APP, platform: 'timesync', path: 'link.txt' }, 403],
            [{ app: APP, platform: 'timesync', path: 'nope.py' }, 404],
            [{ app: APP, platform: 'other', path: 'lockstep.json' }, 404],
        ];
        for (const [params, status] of cases) {
            const res = await authFetch(s.url(`/api/generated/file?${q(params)}`));
            expect(res.status, JSON.stringify(params)).toBe(status);
            expect(typeof (await json(res))['error']).toBe('string');
        }
        expect((await authFetch(s.url(`/api/generated/trace?${q({ app: APP, platform: 'other' })}`))).status).toBe(404);
    });

    it('reports a broken model as ok:false with LSP diagnostics and writes nothing', async () => {
        site = await startSite();
        appendFileSync(path.join(site.workspace, 'toast-service', 'toast', 'Controller.arc'), '\ncomponent Broken {\n');
        const res = await post(site, { app: APP, platform: 'timesync' });
        expect(res.status).toBe(200);
        const answer = await json<GenerateAnswer>(res);
        expect(answer.ok).toBe(false);
        expect(answer.files).toEqual([]);
        const error = answer.diagnostics.find((d) => d.severity === 'error');
        expect(error).toBeDefined();
        expect(error!.file).toBe('toast-service/toast/Controller.arc');
        expect(error!.range.start.line).toBeGreaterThanOrEqual(0);
        expect(typeof error!.code).toBe('string');
        expect(existsSync(path.join(site.dir, '.maa-ide-out', APP, 'timesync'))).toBe(false);
    });

    it('rejects unknown platforms, missing apps and bad paths with 4xx', async () => {
        site = await startSite();
        const cases: Array<[unknown, number]> = [
            [{ app: APP, platform: 'nosuch' }, 400],
            [{ app: 'toast-service/None.arcapp', platform: 'timesync' }, 404],
            [{ app: '../TR.arcapp', platform: 'timesync' }, 400],
            [{ app: 'toast-service/maa.json', platform: 'timesync' }, 400],
            [{ app: APP, platform: 'a/b' }, 400],
            [{ app: APP }, 400],
        ];
        for (const [body, status] of cases) {
            const res = await post(site, body);
            expect(res.status, JSON.stringify(body)).toBe(status);
            expect(typeof (await json(res))['error']).toBe('string');
        }
    });
});
