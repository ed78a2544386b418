// GenerationService's runner (the lab server runs generator runs in worker threads): the job it
// hands over is plain data naming the app, its model root, the platform, the output folder and the
// discovery roots; runGenerateJob's result is plain data too (it survives structuredClone, as a
// message between threads must) and gives the same answer as the default in-process run; an input
// error of the run is a 400; runs of one service still take turns.
import { cpSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import { HttpError } from '../src/http-util.js';
import { type GenerateJob, GenerationService, packageDir, runGenerateJob, Workspace } from '../src/index.js';
import { repo } from './helpers.js';

const APP = 'toast-service/TR.arcapp';

describe('the runner of GenerationService', () => {
    let dir: string | undefined;
    afterEach(() => {
        if (dir) rmSync(dir, { recursive: true, force: true });
        dir = undefined;
    });

    function copyOfExamples(): { workspace: Workspace; out: string } {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-ide-runner-'));
        const root = path.join(dir, 'ws');
        cpSync(path.join(repo, 'examples', 'toast-service'), path.join(root, 'toast-service'), { recursive: true });
        return { workspace: new Workspace(root), out: path.join(dir, 'out') };
    }

    it('hands a plain job to the runner and answers what runGenerateJob gave, after a structured clone', async () => {
        const { workspace, out } = copyOfExamples();
        const jobs: GenerateJob[] = [];
        const viaClone = new GenerationService(workspace, out, [packageDir], async (job) => {
            jobs.push(structuredClone(job));
            return structuredClone(await runGenerateJob(structuredClone(job)));
        });
        const answer = await viaClone.generate(APP, 'timesync');
        expect(jobs).toEqual([
            {
                appFile: path.join(workspace.root, APP),
                modelRoot: path.join(workspace.root, 'toast-service'),
                platform: 'timesync',
                outDir: path.join(out, APP),
                discoveryRoots: [packageDir],
            },
        ]);
        expect(answer.ok).toBe(true);
        expect(answer.files.length).toBeGreaterThan(0);
        expect(answer.platformDir).toBe(path.join(out, APP, 'timesync'));
        // the default (in-process) run answers the same
        const inProcess = await new GenerationService(workspace, out, [packageDir]).generate(APP, 'timesync');
        expect(inProcess).toEqual(answer);
    });

    it('makes an input error of the run a 400 and keeps the runs of one service in turn', async () => {
        const { workspace, out } = copyOfExamples();
        const events: string[] = [];
        let release: () => void = () => undefined;
        const gate = new Promise<void>((resolve) => {
            release = resolve;
        });
        let started: () => void = () => undefined;
        const firstStarted = new Promise<void>((resolve) => {
            started = resolve;
        });
        const service = new GenerationService(workspace, out, [packageDir], async (job) => {
            events.push(`start ${job.platform}`);
            if (job.platform === 'timesync') {
                started();
                await gate;
            }
            events.push(`end ${job.platform}`);
            return { kind: 'input-error', message: `no generator for ${job.platform}` };
        });
        const first = service.generate(APP, 'timesync').catch((e: unknown) => e);
        const second = service.generate(APP, 'rospython').catch((e: unknown) => e);
        await firstStarted;
        expect(events).toEqual(['start timesync']); // the second waits for the first
        release();
        const [a, b] = await Promise.all([first, second]);
        expect(events).toEqual(['start timesync', 'end timesync', 'start rospython', 'end rospython']);
        expect(a).toBeInstanceOf(HttpError);
        expect(a).toMatchObject({ status: 400, message: 'no generator for timesync' });
        expect(b).toMatchObject({ status: 400, message: 'no generator for rospython' });
    });
});
