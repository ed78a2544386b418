import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { selectCases, type StreamTestAnswer } from '../src/stream-tests.js';
import { authFetch, json, rawRequest, repo, startSite, type TestSite } from './helpers.js';

const APP = 'toast-service/TR.arcapp';
const CONTROLLER = 'toast-service/toast/Controller.stream';
const python = path.join(repo, 'packages', 'generators-python', '.venv', 'bin', 'python');

/** POST /api/test on a real backend over a copy of examples/ (the Python of the generators-python venv). */
describe('POST /api/test (stream tests, as maa-gen test --format json)', () => {
    let site: TestSite;
    beforeAll(async () => {
        vi.stubEnv('MAA_PYTHON', python);
        site = await startSite();
    });
    afterAll(async () => {
        await site.dispose();
        vi.unstubAllEnvs();
    });

    const post = (body: unknown) =>
        authFetch(site.url('/api/test'), { method: 'POST', body: JSON.stringify(body), headers: { 'Content-Type': 'application/json' } });

    it('refuses a request without the token: nothing generated', async () => {
        const res = await rawRequest(site.server.url, '/api/test', {
            method: 'POST',
            headers: { Authorization: null, 'Content-Type': 'text/plain' },
            body: JSON.stringify({ app: APP }),
        });
        expect(res.status).toBe(401);
        expect(existsSync(path.join(site.dir, '.maa-ide-out', APP))).toBe(false);
    });

    it('runs every stream file of the model root, and one file or named cases on request', async () => {
        const all = await post({ app: APP });
        expect(all.status).toBe(200);
        const answer = await json<StreamTestAnswer>(all);
        expect(answer.ok).toBe(true);
        expect([...new Set(answer.results.map((r) => r.file))]).toEqual([
            'toast-service/toast/ArmController.stream',
            'toast-service/toast/Controller.stream',
            'toast-service/toast/ToasterController.stream',
        ]);
        expect(answer.summary).toEqual({ passed: answer.results.length, failed: 0 });

        const named = await json<StreamTestAnswer>(
            await post({ app: APP, files: [CONTROLLER], cases: ['a burnt toast is not served', 'a plate starts loading the bread'] }),
        );
        expect(named.results.map((r) => [r.file, r.test, r.line, r.passed])).toEqual([
            [CONTROLLER, 'a plate starts loading the bread', 15, true],
            [CONTROLLER, 'a burnt toast is not served', 33, true],
        ]);
    }, 300_000);

    it('reports a wrong expected stream as a failed test with the differing streams', async () => {
        const file = path.join(site.workspace, CONTROLLER);
        const text = readFileSync(file, 'utf8');
        writeFileSync(file, text.replace('arm      == NONE Tk Tk LOAD_BREAD Tk;', 'arm      == NONE Tk LOAD_BREAD Tk;'));
        try {
            const answer = await json<StreamTestAnswer>(await post({ app: APP, files: [CONTROLLER] }));
            expect(answer.summary).toEqual({ passed: 4, failed: 1 });
            const failed = answer.results.filter((r) => !r.passed);
            expect(failed).toEqual([
                {
                    file: CONTROLLER,
                    test: 'a plate starts loading the bread',
                    line: 15,
                    passed: false,
                    problems: ['arm: expected NONE Tk LOAD_BREAD Tk; got NONE Tk Tk LOAD_BREAD Tk'],
                },
            ]);
        } finally {
            writeFileSync(file, text);
        }
    }, 300_000);

    it('answers generation errors with ok false and no results; bad requests with 400/404', async () => {
        const app = path.join(site.workspace, APP);
        const text = readFileSync(app, 'utf8');
        writeFileSync(app, text.replace('for toast.ToastServiceRobot', 'for toast.NoSuchRobot'));
        try {
            const answer = await json<StreamTestAnswer>(await post({ app: APP }));
            expect(answer.ok).toBe(false);
            expect(answer.results).toEqual([]);
            expect(answer.diagnostics.some((d) => d.severity === 'error' && d.file === APP)).toBe(true);
        } finally {
            writeFileSync(app, text);
        }
        expect((await post({})).status).toBe(400);
        expect((await post({ app: APP, files: 'x.stream' })).status).toBe(400);
        expect((await post({ app: APP, files: ['toast-service/TR.arcapp'] })).status).toBe(400);
        expect((await post({ app: APP, files: ['toast-service/none.stream'] })).status).toBe(404);
        expect((await post({ app: APP, files: ['../outside.stream'] })).status).toBe(400);
        const unknown = await post({ app: APP, files: [CONTROLLER], cases: ['no such test'] });
        expect(unknown.status).toBe(400);
        expect((await json<{ error: string }>(unknown)).error).toContain('no stream test named "no such test"');
    }, 300_000);
});

describe('selectCases', () => {
    const r = (file: string, test: string | null) => ({ file, test, line: 1, passed: true, problems: [] });
    it('keeps the named tests and the errors of files that did not run', () => {
        const results = [r('a', 'x'), r('a', 'y'), r('b', null)];
        expect(selectCases(results, undefined)).toEqual(results);
        expect(selectCases(results, ['y'])).toEqual([r('a', 'y'), r('b', null)]);
        expect(selectCases(results, ['z'])).toEqual([r('b', null)]);
        expect(() => selectCases([r('a', 'x')], ['z'])).toThrow('no stream test named "z"');
    });
});
