// The browser IDE's StreamTestRunner against a real maa-ide backend (POST /api/test) on a copy of
// the toast example: the same report as the CLI runner, its files the request's URIs; a wrong
// expected stream fails at its port, a model that does not generate rejects with its errors.
import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { type IdeServer, startIdeServer } from '@maa/ide-server';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { caseOutcome, resultOfCase } from '../src/testing/report.js';
import type { FileRef } from '../src/testing/runner.js';
import { outlineStreamFile } from '../src/testing/stream-file.js';
import { WebStreamTestRunner } from '../src/testing/web-runner.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const python = path.join(repo, 'packages', 'generators-python', '.venv', 'bin', 'python');
const TOKEN = 'stream-tests-web-token-0123456789';

/** A file of the browser IDE's workspace (`/workspace/…`, the URI scheme the web host gives it). */
const ref = (rel: string): FileRef => ({ uri: `maa-ws:/workspace/${rel}`, path: `/workspace/${rel}`, fsPath: `/workspace/${rel}` });

describe('WebStreamTestRunner on a real maa-ide', () => {
    let dir = '';
    let server: IdeServer;
    const authorized: typeof fetch = (input, init) => {
        const headers = new Headers(init?.headers);
        headers.set('authorization', `Bearer ${TOKEN}`);
        return fetch(input, { ...init, headers });
    };
    const runner = () => new WebStreamTestRunner(server.url.replace(/\/$/, ''), '/workspace', authorized);
    const controller = 'toast-service/toast/Controller.stream';
    const request = (cases: string[] = []) => ({ app: ref('toast-service/TR.arcapp'), files: [ref(controller)], cases });

    beforeAll(async () => {
        vi.stubEnv('MAA_PYTHON', python);
        dir = mkdtempSync(path.join(tmpdir(), 'maa-web-streams-'));
        cpSync(path.join(repo, 'examples', 'toast-service'), path.join(dir, 'ws', 'toast-service'), { recursive: true });
        server = await startIdeServer({ appDir: path.join(dir, 'no-app'), token: TOKEN, workspace: path.join(dir, 'ws'), port: 0 });
    });
    afterAll(async () => {
        await server?.close();
        rmSync(dir, { recursive: true, force: true });
        vi.unstubAllEnvs();
    });

    it('runs a file and one case; results name the request files by URI', async () => {
        const all = await runner().run(request(), new AbortController().signal);
        expect(all.summary).toEqual({ passed: 5, failed: 0 });
        expect(all.results.every((r) => r.file === ref(controller).uri)).toBe(true);
        const one = await runner().run(request(['a burnt toast is not served']), new AbortController().signal);
        expect(one.results.map((r) => [r.test, r.line, r.passed])).toEqual([['a burnt toast is not served', 33, true]]);
    }, 300_000);

    it('a wrong expected stream is a failed case with a diff at its port statement', async () => {
        const file = path.join(dir, 'ws', controller);
        const text = readFileSync(file, 'utf8');
        const wrong = text.replace('toaster  ~= STOP START;', 'toaster  ~= STOP STOP;');
        expect(wrong).not.toBe(text);
        writeFileSync(file, wrong);
        try {
            const report = await runner().run(request(), new AbortController().signal);
            expect(report.summary).toEqual({ passed: 4, failed: 1 });
            const burnt = outlineStreamFile(wrong).cases[3]!;
            const outcome = caseOutcome(resultOfCase(report.results, burnt)!, burnt);
            expect(outcome).toEqual({
                state: 'failed',
                messages: [
                    {
                        text: 'toaster: expected STOP STOP; got STOP START',
                        expected: 'STOP STOP',
                        actual: 'STOP START',
                        span: burnt.expected['toaster'],
                    },
                ],
            });
        } finally {
            writeFileSync(file, text);
        }
    }, 300_000);

    it('rejects with the errors when the application does not generate, and with the reason of a refused request', async () => {
        const app = path.join(dir, 'ws', 'toast-service', 'TR.arcapp');
        const text = readFileSync(app, 'utf8');
        writeFileSync(app, text.replace('for toast.ToastServiceRobot', 'for toast.NoSuchRobot'));
        try {
            await expect(runner().run(request(), new AbortController().signal)).rejects.toThrow(
                /generation failed; no stream test was run\ntoast-service\/TR\.arcapp:\d+: /,
            );
        } finally {
            writeFileSync(app, text);
        }
        await expect(runner().run(request(['no such test']), new AbortController().signal)).rejects.toThrow(
            'testing toast-service/TR.arcapp: no stream test named "no such test"',
        );
        const anonymous = new WebStreamTestRunner(server.url.replace(/\/$/, ''), '/workspace');
        await expect(anonymous.run(request(), new AbortController().signal)).rejects.toThrow(/^testing toast-service\/TR\.arcapp: /);
    }, 300_000);

    it('an aborted run rejects', async () => {
        const abort = new AbortController();
        const pending = runner().run(request(), abort.signal);
        abort.abort();
        await expect(pending).rejects.toThrow();
    }, 60_000);
});
