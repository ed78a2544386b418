import { existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { maaGen, type StreamResult } from './maa-gen.js';
import { ensureVenv, repoDir, run, venvPython } from './python-env.js';

// The stream tests next to the example's models (examples/toast-service/toast/*.stream), run on
// the timesync build of its application configuration by `maa-gen test`.
describe('stream tests of the example (maa-gen test)', () => {
    it('every stream test of examples/toast-service passes', async () => {
        await ensureVenv();
        const r = await run(
            process.execPath,
            [maaGen, 'test', 'examples/toast-service/TR.arcapp', '--format', 'json', '--python', venvPython],
            repoDir,
        );
        const out = JSON.parse(r.stdout) as { results: StreamResult[]; summary: { passed: number; failed: number } };
        expect(out.results.filter((x) => !x.passed)).toEqual([]);
        expect(out.summary.passed).toBeGreaterThanOrEqual(11);
        for (const component of ['Controller', 'ToasterController', 'ArmController']) {
            expect(
                out.results.some((x) => x.file.endsWith(`${component}.stream`)),
                component,
            ).toBe(true);
        }
        expect(r.status).toBe(0);
    }, 180_000);

    it('a failing stream test fails the command with a readable difference', async () => {
        await ensureVenv();
        const r = await run(
            process.execPath,
            [
                maaGen,
                'test',
                'examples/toast-service/TR.arcapp',
                'packages/generators-python/test/fixtures/failing/Controller.stream',
                '--python',
                venvPython,
            ],
            repoDir,
        );
        expect(r.status).toBe(1);
        expect(r.stdout).toContain('FAIL');
        expect(r.stdout).toContain('arm: expected NONE Tk LOAD_BREAD Tk; got NONE Tk Tk');
    }, 180_000);

    it('an output that cannot be written exits 2 (an I/O problem, as for generate) and runs no test', async () => {
        const out = mkdtempSync(path.join(tmpdir(), 'maa-streams-out-'));
        try {
            writeFileSync(path.join(out, 'timesync'), 'a file where the platform folder belongs\n');
            const r = await run(
                process.execPath,
                [maaGen, 'test', 'examples/toast-service/TR.arcapp', '--out', out, '--python', venvPython],
                repoDir,
            );
            expect(r.stdout).toContain('gen/write-failed');
            expect(r.stderr).toContain('no stream test was run');
            expect(r.status).toBe(2);
        } finally {
            rmSync(out, { recursive: true, force: true });
        }
    }, 180_000);
});

// The timesync build of the example in the simulator's lock-step mode (sim-server, MuJoCo): the
// whole service runs until the toast lies on the plate. Needs sim-server/.venv (its setup script).
const maaSim = path.join(repoDir, 'sim-server', '.venv', 'bin', 'maa-sim');
describe.skipIf(!existsSync(maaSim))('the example on the simulator (lock-step, timesync build)', () => {
    it('serves a toast: the toast ends up on the plate', async () => {
        const out = mkdtempSync(path.join(tmpdir(), 'maa-timesync-sim-'));
        try {
            const gen = await run(
                process.execPath,
                [maaGen, 'generate', 'examples/toast-service/TR.arcapp', '--platform', 'timesync', '--out', out],
                repoDir,
            );
            expect(gen.status, gen.stderr).toBe(0);
            const sim = await run(
                maaSim,
                [
                    'run',
                    '--package',
                    path.join(out, 'timesync'),
                    '--mode',
                    'lockstep',
                    '--until-goal',
                    '--viser-port',
                    'off',
                    '--rosbridge-port',
                    'off',
                    '--max-time',
                    '60',
                ],
                repoDir,
            );
            expect(`${sim.stdout}${sim.stderr}`).toContain('toast on the plate: True');
        } finally {
            rmSync(out, { recursive: true, force: true });
        }
    }, 300_000);
});
