// The web entry's Generate: the backend's answer as the CLI's report (positions, paths, counts),
// and the web GenerateRunner against a real maa-ide backend on a copy of examples/ (a good model,
// a broken one, a refused request, a cancelled one).
import { appendFileSync, cpSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { type IdeServer, startIdeServer } from '@maa/ide-server';
import type { GenerateAnswer } from '@maa/protocol';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { summaryMessage } from '../src/generate-report.js';
import { reportFromAnswer } from '../src/generate-runner.js';
import { backendBase, backendRunner } from '../src/web/backend.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const TOKEN = 'web-generate-test-token-0123456789';

describe('reportFromAnswer', () => {
    const answer: GenerateAnswer = {
        ok: false,
        platform: 'timesync',
        files: [],
        diagnostics: [
            {
                file: 'toast-service/toast/Controller.arc',
                range: { start: { line: 4, character: 2 }, end: { line: 4, character: 9 } },
                severity: 'error',
                code: 'maa.adl.unresolved',
                message: 'no port x',
            },
            {
                file: 'toast-service/toast/Controller.arc',
                range: { start: { line: 0, character: 0 }, end: { line: 1, character: 0 } },
                severity: 'warning',
                code: 'maa.adl.unused',
                message: 'unused',
            },
            {
                file: 'TR.arcapp',
                range: { start: { line: 2, character: 0 }, end: { line: 2, character: 3 } },
                severity: 'odd',
                code: '',
                message: 'm',
            },
        ],
    };

    it('turns 0-based ranges into 1-based positions below the workspace root, grouped by file', () => {
        const report = reportFromAnswer(answer, '/workspace/');
        expect([...report.byFile.keys()]).toEqual(['/workspace/toast-service/toast/Controller.arc', '/workspace/TR.arcapp']);
        expect(report.byFile.get('/workspace/toast-service/toast/Controller.arc')?.[0]).toEqual({
            file: '/workspace/toast-service/toast/Controller.arc',
            line: 5,
            column: 3,
            endLine: 5,
            endColumn: 10,
            severity: 'error',
            code: 'maa.adl.unresolved',
            message: 'no port x',
        });
        // An unknown severity counts as an error (the CLI report's reading does the same).
        expect(report.byFile.get('/workspace/TR.arcapp')?.[0]?.severity).toBe('error');
        expect({ ok: report.ok, errors: report.errors, warnings: report.warnings, files: report.files }).toEqual({
            ok: false,
            errors: 2,
            warnings: 1,
            files: 0,
        });
        expect(summaryMessage('timesync', report)).toBe('MontiArc: nothing generated for timesync (2 errors, 1 warning; see Problems)');
    });
});

describe('backendBase', () => {
    it('is the folder of the hosting page, without a trailing slash', () => {
        expect(backendBase({ href: 'http://127.0.0.1:3000/?open=x' })).toBe('http://127.0.0.1:3000');
        expect(backendBase({ href: 'https://lab.example/ide/robotics/toast-controller/ada/' })).toBe(
            'https://lab.example/ide/robotics/toast-controller/ada',
        );
    });
    it('refuses to guess without a page', () => {
        expect(() => backendBase(undefined)).toThrow(/browser IDE/);
    });
});

describe('the web GenerateRunner against maa-ide (a copy of examples/)', () => {
    let dir = '';
    let server: IdeServer;
    const authorized: typeof fetch = (input, init) => {
        const headers = new Headers(init?.headers);
        headers.set('authorization', `Bearer ${TOKEN}`);
        return fetch(input, { ...init, headers });
    };
    const runner = () =>
        backendRunner(server.url.replace(/\/$/, ''), '/workspace', (file) => path.posix.relative('/workspace', file), authorized);

    beforeAll(async () => {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-web-generate-'));
        cpSync(path.join(repo, 'examples'), path.join(dir, 'ws'), { recursive: true });
        server = await startIdeServer({ appDir: path.join(dir, 'no-app'), token: TOKEN, workspace: path.join(dir, 'ws'), port: 0 });
    });
    afterAll(async () => {
        await server?.close();
        rmSync(dir, { recursive: true, force: true });
    });

    it('generates timesync: ok, the files counted, no errors', async () => {
        const report = await runner().run(
            { appFile: '/workspace/toast-service/TR.arcapp', platform: 'timesync' },
            new AbortController().signal,
        );
        expect(report.ok).toBe(true);
        expect(report.errors).toBe(0);
        expect(report.files).toBeGreaterThan(3);
    });

    it('reports a broken model as errors at the model file below the workspace root', async () => {
        appendFileSync(path.join(dir, 'ws', 'toast-service', 'toast', 'Controller.arc'), '\ncomponent Broken {\n');
        const report = await runner().run(
            { appFile: '/workspace/toast-service/TR.arcapp', platform: 'timesync' },
            new AbortController().signal,
        );
        expect(report.ok).toBe(false);
        expect(report.errors).toBeGreaterThan(0);
        const controller = report.byFile.get('/workspace/toast-service/toast/Controller.arc') ?? [];
        expect(controller.some((d) => d.severity === 'error' && d.line >= 1 && d.column >= 1)).toBe(true);
    });

    it("rejects with the backend's message when it refuses the request", async () => {
        await expect(
            runner().run({ appFile: '/workspace/toast-service/TR.arcapp', platform: 'no-such-platform' }, new AbortController().signal),
        ).rejects.toThrow(/generating toast-service\/TR\.arcapp for no-such-platform: .*no-such-platform/);
    });

    it('rejects when cancelled', async () => {
        const abort = new AbortController();
        abort.abort();
        await expect(runner().run({ appFile: '/workspace/toast-service/TR.arcapp', platform: 'timesync' }, abort.signal)).rejects.toThrow(
            /abort/i,
        );
    });
});
