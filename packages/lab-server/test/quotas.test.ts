// The quotas on their own (a clock the test moves: the hour's window frees simulated time; slots
// per student; the options' checks) and through `maa-lab serve`'s options: a bad value is refused
// by name, a given one is the limit a save meets (413 naming it).
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { HttpError } from '@maa/ide-server/http';
import { afterAll, describe, expect, it } from 'vitest';
import { type LabIo, runLab } from '../src/cli/main.js';
import { DEFAULT_QUOTAS, HOUR_MS, quotaOptions, SimulatedTimeLedger, SimulationSlots } from '../src/quotas/index.js';
import { copyPgliteTemplate } from './backends.js';
import { Client } from './http-client.js';
import { PASSWORD, startLab } from './workspace-setup.js';

function refusal(body: () => void): HttpError {
    try {
        body();
    } catch (e) {
        if (e instanceof HttpError) return e;
        throw e;
    }
    throw new Error('expected a refusal');
}

describe('quotas', () => {
    it('counts simulated seconds within the last hour and frees them when they leave it', () => {
        let now = 1_000_000;
        const ledger = new SimulatedTimeLedger(100, () => now);
        ledger.add(1, 60);
        now += 10 * 60_000;
        ledger.add(1, 30);
        expect(ledger.remaining(1)).toBe(10);
        ledger.checkStart(1);
        ledger.checkStart(2, 99); // another student, with 99 s running
        const full = refusal(() => ledger.checkStart(1, 10)); // 10 s of a running simulation count too
        expect(full.status).toBe(429);
        expect(full.extra).toMatchObject({
            limit: 'simulatedSecondsPerHour',
            value: 100,
            freesAt: new Date(1_000_000 + HOUR_MS).toISOString(),
        });
        expect(full.message).toMatch(/you simulated 100 of the 100 simulated seconds allowed per hour/);
        now = 1_000_000 + HOUR_MS + 1; // the first run left the window
        expect(ledger.used(1)).toBe(30);
        ledger.checkStart(1, 10);
    });

    it('holds one slot per workspace and student', () => {
        const slots = new SimulationSlots(2);
        slots.take(1, 10);
        slots.take(1, 11);
        slots.take(1, 11); // a restart in the same workspace
        slots.take(2, 12);
        const third = refusal(() => slots.take(1, 13));
        expect(third.status).toBe(429);
        expect(third.extra).toMatchObject({ limit: 'concurrentSimulations', value: 2 });
        slots.release(1, 10);
        slots.take(1, 13);
        expect(slots.count(1)).toBe(2);
    });

    it('takes the defaults and refuses limits that are no positive whole numbers', () => {
        expect(quotaOptions()).toEqual(DEFAULT_QUOTAS);
        expect(quotaOptions({ workspaceFiles: 3 }).workspaceFiles).toBe(3);
        expect(() => quotaOptions({ concurrentSimulations: 0 })).toThrow(/concurrentSimulations must be a positive whole number, not 0/);
        expect(() => quotaOptions({ workspaceBytes: 1.5 })).toThrow(/workspaceBytes/);
    });
});

describe('maa-lab serve’s quota options', () => {
    const dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-quota-cli-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    async function serve(args: string[], onServing?: (stop: () => Promise<void>, url: string) => void) {
        let out = '';
        let err = '';
        const io: LabIo = { cwd: dir, env: {}, out: (t) => void (out += t), err: (t) => void (err += t), readSecret: async () => '' };
        const code = await runLab(['node', 'maa-lab', 'serve', '--port', '0', '--data-dir', path.join(dir, 'data'), ...args], io, {
            ...(onServing ? { onServing } : {}),
        });
        return { code, out, err };
    }

    it('lists them in --help and refuses a bad value by name', async () => {
        const help = await serve(['--help']);
        for (const flag of ['--max-simulations', '--max-sim-seconds-per-hour', '--max-workspace-bytes', '--max-workspace-files'])
            expect(help.out).toContain(flag);
        expect(await serve(['--max-simulations', '0'])).toMatchObject({
            code: 1,
            err: 'maa-lab: error: --max-simulations must be a positive whole number, not 0\n',
        });
        expect((await serve(['--max-workspace-bytes', '1e6'])).err).toContain('--max-workspace-bytes must be a positive whole number');
    });

    it('serves with the given limits', async () => {
        // The lab's users and exercise, written to the data directory before the command opens it.
        await copyPgliteTemplate(path.join(dir, 'data'));
        const seeded = await startLab({ dataDir: path.join(dir, 'data') });
        await seeded.dispose();
        let stop: (() => Promise<void>) | undefined;
        let url = '';
        const run = await serve(['--max-workspace-files', '20'], (s, u) => {
            stop = s;
            url = u;
        });
        expect(run.code, run.err).toBe(0);
        try {
            const ada = new Client(url);
            expect((await ada.login('ada', PASSWORD)).status).toBe(200);
            const answer = await ada.send('/api/ws/robotics/toast-controller/ada/file?path=one-more.txt', {
                method: 'PUT',
                raw: 'x',
                headers: { 'X-CSRF-Token': ada.csrf! },
            });
            expect(answer.status, answer.text).toBe(413);
            expect(answer.json).toMatchObject({ limit: 'workspaceFiles', value: 20 });
        } finally {
            await stop?.();
        }
    });
});
