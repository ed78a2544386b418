// The web entry's Show Generated Code / Show Model Element without an editor: the `maa-generated:`
// URIs, the model root an app's trace is read against, the trace lookups with Windows paths (the
// lookups use no node:path since the web bundle has none), and both directions on a real trace that
// a maa-ide backend generated (a copy of examples/, rospython), its files read over the API.
import { cpSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { type IdeServer, startIdeServer } from '@maa/ide-server';
import { TRACE_FORMAT_VERSION, type TraceFile } from '@maa/protocol';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { generatedCodeAt, modelElementAt, platformDirOf } from '../src/trace.js';
import { backendRunner, type Generation, onGenerated } from '../src/web/backend.js';
import {
    appModelRoot,
    GENERATED_SCHEME,
    GeneratedOutput,
    generatedHits,
    generatedUriParts,
    markerFolders,
    modelElementOf,
    parseGeneratedUri,
    workspaceTrace,
} from '../src/web/generated-files.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const TOKEN = 'web-generated-code-test-token-0123456789';

describe('maa-generated URIs', () => {
    it('name the platform and the path in the URI path, the app in the query, and parse back', () => {
        const ref = { app: 'toast service/TR.arcapp', platform: 'rospython', path: 'toast_service_robot/toast/controller.py' };
        const parts = generatedUriParts(ref);
        expect(parts).toEqual({
            scheme: GENERATED_SCHEME,
            path: '/rospython/toast_service_robot/toast/controller.py',
            query: 'app=toast+service%2FTR.arcapp',
        });
        expect(parseGeneratedUri(parts)).toEqual(ref);
    });

    it('another scheme, a missing app or a path without a file is no generated file', () => {
        expect(parseGeneratedUri({ scheme: 'file', path: '/rospython/a.py', query: 'app=TR.arcapp' })).toBeUndefined();
        expect(parseGeneratedUri({ scheme: GENERATED_SCHEME, path: '/rospython/a.py', query: '' })).toBeUndefined();
        expect(parseGeneratedUri({ scheme: GENERATED_SCHEME, path: '/rospython', query: 'app=TR.arcapp' })).toBeUndefined();
    });
});

describe('the model root of an app in the workspace', () => {
    it('is the nearest folder up to the workspace root with maa.json, else the app folder', () => {
        const app = '/workspace/lab/starter/app/A.arcapp';
        expect(markerFolders(app, '/workspace')).toEqual([
            '/workspace/lab/starter/app',
            '/workspace/lab/starter',
            '/workspace/lab',
            '/workspace',
        ]);
        expect(markerFolders('/workspace/A.arcapp', '/workspace/')).toEqual(['/workspace']);
        expect(appModelRoot(app, '/workspace', new Set(['/workspace/lab/starter', '/workspace']))).toBe('/workspace/lab/starter');
        expect(appModelRoot(app, '/workspace', new Set())).toBe('/workspace/lab/starter/app');
        // A marker above the workspace root does not count.
        expect(appModelRoot(app, '/workspace', new Set(['/']))).toBe('/workspace/lab/starter/app');
    });
});

describe('trace lookups with Windows paths', () => {
    const trace: TraceFile = {
        version: TRACE_FORMAT_VERSION,
        application: 'A',
        platform: 'timesync',
        rootComponent: 'demo.Lamp',
        modelRoot: '..\\..\\models',
        generators: [],
        files: [
            {
                path: 'demo/lamp.py',
                generator: 'timesync.Components',
                userFile: false,
                sha256: '0'.repeat(64),
                lines: 10,
                traces: [
                    {
                        lines: { first: 2, last: 5 },
                        generator: 'timesync.Components',
                        element: {
                            file: 'demo/Lamp.arc',
                            range: { start: { line: 1, character: 0 }, end: { line: 6, character: 1 } },
                            path: '/component',
                            type: 'ComponentType',
                            name: 'Lamp',
                        },
                    },
                ],
            },
        ],
    };
    const platformDir = 'C:\\p\\gen\\timesync';

    it('read `\\` as `/` in both directions', () => {
        expect(generatedCodeAt(trace, platformDir, 'C:\\p\\models\\demo\\Lamp.arc', { line: 2, character: 0 })).toEqual([
            { file: 'C:/p/gen/timesync/demo/lamp.py', first: 2, last: 5, generator: 'timesync.Components' },
        ]);
        expect(modelElementAt(trace, platformDir, 'C:\\p\\gen\\timesync\\demo\\lamp.py', 3)).toMatchObject({
            file: 'C:/p/models/demo/Lamp.arc',
            name: 'Lamp',
        });
        expect(modelElementAt(trace, platformDir, 'C:\\p\\gen\\timesyncx\\demo\\lamp.py', 3)).toBeUndefined();
    });

    it('the platform folder of a generated file is one of the folders as given', () => {
        expect(platformDirOf('C:\\p\\gen\\timesync\\demo\\lamp.py', ['C:\\p\\gen', platformDir])).toBe(platformDir);
    });
});

describe('Show Generated Code and Show Model Element on a generation of maa-ide (a copy of examples/)', () => {
    let dir = '';
    let server: IdeServer;
    let base = '';
    const authorized: typeof fetch = (input, init) => {
        const headers = new Headers(init?.headers);
        headers.set('authorization', `Bearer ${TOKEN}`);
        return fetch(input, { ...init, headers });
    };
    const generation: Generation = { app: 'toast-service/TR.arcapp', platform: 'rospython' };
    const controller = '/workspace/toast-service/toast/Controller.arc';

    beforeAll(async () => {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-web-generated-'));
        cpSync(path.join(repo, 'examples'), path.join(dir, 'ws'), { recursive: true });
        server = await startIdeServer({ appDir: path.join(dir, 'no-app'), token: TOKEN, workspace: path.join(dir, 'ws'), port: 0 });
        base = server.url.replace(/\/$/, '');
    });
    afterAll(async () => {
        await server?.close();
        rmSync(dir, { recursive: true, force: true });
    });

    it('no trace before the app was generated for the platform; Generate reports the generation', async () => {
        const output = new GeneratedOutput(base, authorized);
        expect(await output.trace(generation)).toBeUndefined();
        const seen: Generation[] = [];
        const stop = onGenerated((g) => seen.push(g));
        const runner = backendRunner(base, '/workspace', (file) => path.posix.relative('/workspace', file), authorized);
        const report = await runner.run({ appFile: `/workspace/${generation.app}`, platform: 'rospython' }, new AbortController().signal);
        stop();
        expect(report.ok).toBe(true);
        expect(seen).toEqual([generation]);
    }, 120_000);

    it('the automaton at the cursor leads to its generated behavior, and its lines back to the model', async () => {
        const output = new GeneratedOutput(base, authorized);
        const trace = await output.trace(generation);
        expect(trace?.platform).toBe('rospython');
        if (!trace) return;
        // examples/toast-service has maa.json in its folder: that is the model root.
        const w = workspaceTrace(
            generation,
            trace,
            appModelRoot(`/workspace/${generation.app}`, '/workspace', new Set(['/workspace/toast-service'])),
        );
        const text = readFileSync(path.join(dir, 'ws', 'toast-service', 'toast', 'Controller.arc'), 'utf8').split('\n');
        // rospython traces Controller's automaton (the component's node is generated from the whole app).
        const line = text.findIndex((l) => l.includes('automaton {'));
        const hits = generatedHits(w, controller, { line: line + 1, character: 4 });
        expect(hits.length).toBeGreaterThan(0);
        const hit = hits[0];
        if (!hit) return;
        expect(hit.ref).toMatchObject(generation);
        const generated = (await output.file(hit.ref)).split('\n');
        expect(generated.slice(hit.first, hit.last + 1).join('\n')).toMatch(/class Controller/);
        expect(hit.ref.path).toMatch(/controller_behavior\.py$/);
        // Back: a line of that span is the automaton of Controller.arc.
        const back = modelElementOf(w, hit.ref.path, hit.first);
        expect(back).toMatchObject({ file: controller, type: 'Automaton' });
        expect(back?.range.start.line).toBe(line);
        // A line of a file the trace does not know, and a file that was not generated.
        expect(modelElementOf(w, 'no/such.py', 0)).toBeUndefined();
        await expect(output.file({ ...generation, path: 'no/such.py' })).rejects.toThrow(
            /reading no\/such\.py generated from .*not generated/,
        );
    }, 60_000);
});
