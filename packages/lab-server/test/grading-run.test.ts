// One real grading run through the lab's service (docs/lab.md "Grading"): toast-controller
// released with its grading/ folder, ada's workspace with the reference solution and bob's with
// the starter's stub, both submitted, graded by @maa/grading with the real Python driver (Ray,
// the sandbox, maa-sim) on the standard scenario; the results and the recording are in the lab.
// Skipped, saying why, when the sim-server venv is absent. Run it alone: it starts Ray.
import { existsSync, readFileSync, rmSync } from 'node:fs';
import { mkdtemp } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { loadExercise } from '../src/exercises/load.js';
import { releaseExercise } from '../src/exercises/release.js';
import { openExerciseWorkspace } from '../src/exercises/workspace.js';
import { GradingService } from '../src/grading/index.js';
import { type LabStore, openLabStore } from '../src/storage/index.js';
import { copyPgliteTemplate } from './backends.js';
import { repo } from './workspace-setup.js';

const VENV_PYTHON = path.join(repo, 'sim-server', '.venv', 'bin', 'python');
const HAS_VENV = existsSync(VENV_PYTHON);
if (!HAS_VENV)
    console.warn(`grading-run.test.ts skipped: the sim-server venv is absent (${VENV_PYTHON}); run sim-server/scripts/setup_env.sh`);

describe.skipIf(!HAS_VENV)('a real grading run through the lab', () => {
    let dir: string;
    let store: LabStore;

    beforeAll(async () => {
        dir = await mkdtemp(path.join(tmpdir(), 'maa-lab-grading-run-'));
        await copyPgliteTemplate(path.join(dir, 'lab-data'));
        store = await openLabStore({ dataDir: path.join(dir, 'lab-data') });
    });
    afterAll(async () => {
        await store?.close();
        if (dir) rmSync(dir, { recursive: true, force: true });
    });

    it('grades the reference solution and the stub, stores the results and keeps the recording', async () => {
        const teacher = await store.createUser({ login: 'teacher', name: 'Teacher', role: 'instructor' });
        const course = await store.createCourse({ name: 'robotics', title: 'Robotics' });
        const folder = path.join(repo, 'examples', 'lab', 'toast-controller');
        const loaded = await loadExercise(folder);
        expect(loaded.grading, 'examples/lab/toast-controller has a grading/ folder').toBeDefined();
        const { exercise } = await releaseExercise(store, loaded, { course: course.name, authorId: teacher.id });
        // One scenario keeps the run short; the rest of the grading is the exercise's own.
        const spec = loaded.grading!.spec as { criteria: Array<{ kind: string; scenarios?: Array<{ id: string }> }> };
        const trimmed = {
            ...spec,
            criteria: spec.criteria.map((c) =>
                c.kind === 'scenarios' ? { ...c, scenarios: c.scenarios?.filter((s) => s.id === 'standard') } : c,
            ),
        };
        await store.setExerciseGrading(exercise.id, { spec: trimmed, files: loaded.grading!.files });
        const solution = readFileSync(path.join(folder, 'solution', 'toast', 'Controller.arc'), 'utf8');
        for (const login of ['ada', 'bob']) {
            const user = await store.createUser({ login, name: login, role: 'student' });
            await store.enroll(course.id, user.id);
            const ws = await openExerciseWorkspace(store, exercise, user.id, teacher.id);
            if (login === 'ada')
                await store.saveFile({ workspaceId: ws.id, path: 'toast/Controller.arc', content: solution, authorId: user.id });
            await store.submit(ws.id, user.id);
        }
        const dataDir = path.join(dir, 'lab-data');
        const progress: string[] = [];
        const service = new GradingService(store, { dataDir, onProgress: (_run, p) => progress.push(`${p.done}/${p.total}`) });
        const run = await service.gradeCourse(exercise, teacher);
        await service.settled();
        const ended = await store.findGradingRun(run.id);
        expect(ended?.error ?? null).toBeNull();
        expect(ended).toMatchObject({ status: 'done' });
        expect(progress.length).toBeGreaterThan(0);
        const results = await store.runResults(run.id);
        expect(results.length).toBe(2);
        const [adaResult, bobResult] = results; // by user id: ada, then bob
        const criterion = (r: typeof adaResult, id: string) =>
            ((r?.grade['criteria'] ?? []) as Array<{ id: string; score: number; max: number; feedback: unknown[] }>).find(
                (c) => c.id === id,
            );
        // The reference solution: every criterion in full.
        for (const id of ['architecture', 'no-errors', 'hidden-tests', 'scenarios'])
            expect(criterion(adaResult, id), `ada's ${id}`).toMatchObject({ score: criterion(adaResult, id)?.max });
        // The stub: the hidden tests and the scenario fail, with feedback saying so.
        expect(bobResult!.score).toBeLessThan(adaResult!.score);
        expect(criterion(bobResult, 'scenarios')?.score).toBe(0);
        expect(criterion(bobResult, 'scenarios')?.feedback.length).toBeGreaterThan(0);
        // ada's recording of the standard scenario is in the data directory, an MCAP file.
        const recording = adaResult!.recordings.find((r) => r.scenario === 'standard');
        expect(recording?.path).toBe(`recordings/${run.id}/${adaResult!.id}/standard.mcap`);
        const bytes = readFileSync(path.join(dataDir, ...recording!.path.split('/')));
        expect(bytes.subarray(1, 5).toString('latin1')).toBe('MCAP');
    }, 900_000);
});
