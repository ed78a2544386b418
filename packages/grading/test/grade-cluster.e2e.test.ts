/**
 * A grading run on a real local Ray cluster (a head and a second worker node on 127.0.0.1, started
 * and stopped here with `python -m maa_sim.grading cluster`) gives the same grades as local mode.
 * Skips without the sim-server venv (with Ray) or bubblewrap.
 */
import { execFile } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { promisify } from 'node:util';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import type { SubmissionGrade } from '@maa/protocol/grading';
import { defaultPython, type GradeProgress, gradeSubmissions } from '../src/index.js';
import { repoDir, tempDir, toastController } from './exercise.js';

const run = promisify(execFile);
const gradingDir = path.join(repoDir, 'examples', 'lab', 'toast-controller', 'grading');
const python = defaultPython();
const missing = [
    existsSync(python) ? undefined : `the sim-server venv (${python}; run sim-server/scripts/setup_env.sh)`,
    existsSync('/usr/bin/bwrap') ? undefined : 'bubblewrap (/usr/bin/bwrap)',
    existsSync(path.join(gradingDir, 'grading.json')) ? undefined : `the exercise's grading folder ${gradingDir}`,
].filter(Boolean);
if (missing.length > 0) console.warn(`grade-cluster.e2e.test.ts skipped: missing ${missing.join(', ')}`);

/** The reference solution with Toasting -> Serving on white toast: it serves too early. */
const SERVES_WHITE = (solution: string) => solution.replace('color == ToastColor.GOLDEN', 'color == ToastColor.WHITE');

/** What must agree between two runs: everything but the task times and the recordings' paths. */
function comparable(grades: readonly SubmissionGrade[]) {
    return grades.map((g) => ({
        submission: g.submission,
        score: g.score,
        criteria: g.criteria.map((c) => ({ id: c.id, score: c.score, feedback: c.feedback })),
        recordings: g.recordings.map((r) => r.scenario).sort(),
        tasks: g.tasks.map((t) => ({ id: t.id, status: t.status })).sort((a, b) => a.id.localeCompare(b.id)),
    }));
}

describe.skipIf(missing.length > 0)('a grading run on a 2-node local Ray cluster', () => {
    const work = tempDir('cluster');
    const clusterDir = path.join(work.dir, 'ray');
    const submissions: { id: string; root: string; appFile: string }[] = [];
    let clusterEnv: Record<string, string> = {};
    let local: SubmissionGrade[];
    let cluster: SubmissionGrade[];
    const clusterEvents: GradeProgress[] = [];

    beforeAll(async () => {
        const reference = toastController(path.join(work.dir, 'reference'), { solution: true });
        const solution = readFileSync(path.join(reference, 'toast', 'Controller.arc'), 'utf8');
        const white = toastController(path.join(work.dir, 'white'), {
            solution: true,
            overlay: { 'toast/Controller.arc': SERVES_WHITE(solution) },
        });
        submissions.push({ id: 'reference', root: reference, appFile: 'TR.arcapp' }, { id: 'white', root: white, appFile: 'TR.arcapp' });
        const started = await run(python, ['-m', 'maa_sim.grading', 'cluster', 'start', '--dir', clusterDir, '--nodes', '2'], {
            cwd: repoDir,
        });
        clusterEnv = Object.fromEntries(
            started.stdout
                .split('\n')
                .map((line) => /^(RAY_[A-Z_]+)=(.*)$/.exec(line.trim()))
                .filter((m): m is RegExpExecArray => m !== null)
                .map((m) => [m[1]!, m[2]!]),
        );
        local = await gradeSubmissions({ gradingDir, submissions, workDir: path.join(work.dir, 'local') });
        cluster = await gradeSubmissions({
            gradingDir,
            submissions,
            workDir: path.join(work.dir, 'on-cluster'),
            rayAddress: clusterEnv.RAY_ADDRESS,
            env: clusterEnv,
            onProgress: (e) => clusterEvents.push(e),
        });
    }, 1_200_000);

    afterAll(async () => {
        if (existsSync(path.join(clusterDir, 'cluster.json'))) {
            await run(python, ['-m', 'maa_sim.grading', 'cluster', 'stop', '--dir', clusterDir], { cwd: repoDir });
        }
        work.remove();
    }, 120_000);

    test('the driver ran on the cluster: mode cluster with both nodes', () => {
        expect(clusterEnv.RAY_ADDRESS).toMatch(/^127\.0\.0\.1:\d+$/);
        const started = clusterEvents.flatMap((e) => (e.kind === 'driver' && e.line.event === 'started' ? [e.line] : []));
        expect(started).toHaveLength(1);
        expect(started[0]).toMatchObject({ mode: 'cluster', nodes: 2 });
    });

    test('the grades equal those of local mode (scores, feedback, task statuses)', () => {
        expect(local.map((g) => g.submission)).toEqual(['reference', 'white']);
        expect(local[0]!.score).toBe(local[0]!.maxScore);
        expect(local[1]!.score).toBeLessThan(local[1]!.maxScore);
        expect(comparable(cluster)).toEqual(comparable(local));
    });
});
