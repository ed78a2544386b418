// An exercise's grading folder at release and update (docs/lab.md "Grading"): grading.json checked
// with @maa/protocol/grading and every problem named by file and JSON pointer, the hidden files
// it names stored beside the exercise and never part of the starter; an update replaces the
// grading or removes it with the folder. And `maa-lab grade` (in-process, with the test engine).
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { Command } from 'commander';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import type { LabIo } from '../src/cli/io.js';
import { loadExercise } from '../src/exercises/load.js';
import { releaseExercise } from '../src/exercises/release.js';
import { updateExercise } from '../src/exercises/update.js';
import { gradeCommand, scoreTable } from '../src/grading/command.js';
import { openLabStore } from '../src/storage/index.js';
import { copyPgliteTemplate } from './backends.js';
import { MANIFEST, STARTER, writeExercise, writeFiles } from './exercise-folder.js';
import { engine } from './grading-engine.js';
import { repo } from './workspace-setup.js';

const SPEC = {
    format: 'maa-grading/1',
    criteria: [
        { id: 'no-errors', title: 'No errors', kind: 'diagnostics', weight: 10 },
        { id: 'hidden', title: 'Hidden tests', kind: 'tests', weight: 20, files: ['Lamp.hidden.stream', 'more/Lamp.edge.stream'] },
    ],
};
const HIDDEN = { 'Lamp.hidden.stream': 'component hello.Lamp;\n', 'more/Lamp.edge.stream': 'component hello.Lamp;\n' };

describe('an exercise’s grading folder', () => {
    let dir: string;

    beforeAll(() => {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-grading-'));
    });
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    const exerciseWith = (name: string, grading: Record<string, string>) => {
        const folder = writeExercise(dir, name, STARTER, MANIFEST);
        writeFiles(path.join(folder, 'grading'), grading);
        return folder;
    };

    it('is loaded with its hidden files, none of them in the starter, and stored at release and update', async () => {
        const folder = exerciseWith('lamp', { 'grading.json': JSON.stringify(SPEC), ...HIDDEN, 'notes.txt': 'not named: not read' });
        const loaded = await loadExercise(folder);
        expect(loaded.grading).toEqual({ spec: SPEC, files: HIDDEN });
        expect(Object.keys(loaded.files).some((f) => f.includes('hidden') || f.startsWith('grading'))).toBe(false);
        await copyPgliteTemplate(path.join(dir, 'db'));
        const store = await openLabStore({ dataDir: path.join(dir, 'db') });
        try {
            const teacher = await store.createUser({ login: 't', name: 'T', role: 'instructor' });
            await store.createCourse({ name: 'c', title: 'C' });
            const released = await releaseExercise(store, loaded, { course: 'c', authorId: teacher.id });
            expect(await store.exerciseGrading(released.exercise.id)).toMatchObject({ spec: SPEC, files: HIDDEN });
            expect(JSON.stringify(released.exercise.spec)).not.toContain('hidden');
            const changed = { ...SPEC, criteria: [SPEC.criteria[0]] };
            writeFileSync(path.join(folder, 'grading', 'grading.json'), JSON.stringify(changed));
            await updateExercise(store, await loadExercise(folder), { course: 'c', authorId: teacher.id });
            expect(await store.exerciseGrading(released.exercise.id)).toMatchObject({ spec: changed, files: {} });
            rmSync(path.join(folder, 'grading'), { recursive: true });
            await updateExercise(store, await loadExercise(folder), { course: 'c', authorId: teacher.id });
            expect(await store.exerciseGrading(released.exercise.id)).toBeUndefined();
        } finally {
            await store.close();
        }
    });

    it('loads the grading of every exercise of examples/lab', async () => {
        for (const name of ['toast-controller', 'pick-and-place', 'line-follower']) {
            const loaded = await loadExercise(path.join(repo, 'examples', 'lab', name));
            expect(loaded.grading?.spec['format'], name).toBe('maa-grading/1');
            expect(Object.keys(loaded.grading?.files ?? {}).length, name).toBeGreaterThan(0);
        }
    });

    it.each([
        ['no grading.json', { 'Lamp.hidden.stream': '' }, [/grading\/grading\.json: not found \(a grading folder holds grading\.json\)$/]],
        ['not JSON', { 'grading.json': '{ criteria: ' }, [/grading\/grading\.json: not JSON: /]],
        ['a wrong format', { 'grading.json': JSON.stringify({ ...SPEC, format: 'maa-grading/9' }) }, [/grading\.json: \/format: /]],
        [
            'an unknown criterion kind and a negative weight',
            {
                'grading.json': JSON.stringify({
                    format: 'maa-grading/1',
                    criteria: [
                        { id: 'a', title: 'A', kind: 'magic', weight: 1 },
                        { id: 'b', title: 'B', kind: 'diagnostics', weight: -1 },
                    ],
                }),
            },
            [
                /grading\.json: \/criteria\/0\/kind: kind must be one of/,
                /grading\.json: \/criteria\/1\/weight: weight must be a number from 0/,
            ],
        ],
        [
            'a hidden file that is not there',
            { 'grading.json': JSON.stringify(SPEC), 'Lamp.hidden.stream': '' },
            [/grading\.json: \/criteria\/1\/files\/1: grading\/more\/Lamp\.edge\.stream does not exist$/],
        ],
        [
            'a hidden file outside the grading folder',
            {
                'grading.json': JSON.stringify({
                    ...SPEC,
                    criteria: [{ id: 'h', title: 'H', kind: 'tests', weight: 1, files: ['../starter/hello/Lamp.stream'] }],
                }),
            },
            [/grading\.json: \/criteria\/0\/files\/0: /],
        ],
    ])('is refused with %s, every problem by file and pointer', async (name, files, problems) => {
        const folder = exerciseWith(`bad-${name.replace(/[^a-z]+/g, '-')}`.replace(/-+$/, ''), files);
        const error = await loadExercise(folder).then(
            () => undefined,
            (e: unknown) => e as Error & { problems: string[] },
        );
        expect(error, name).toBeDefined();
        for (const problem of problems)
            expect(
                error?.problems.some((p) => problem.test(p)),
                `${problem} in ${error?.message}`,
            ).toBe(true);
    });
});

describe('maa-lab grade', () => {
    let dir: string;

    beforeAll(async () => {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-grade-'));
        await copyPgliteTemplate(path.join(dir, 'lab-data'));
        const store = await openLabStore({ dataDir: path.join(dir, 'lab-data') });
        try {
            const teacher = await store.createUser({ login: 'teacher', name: 'Teacher', role: 'instructor' });
            const course = await store.createCourse({ name: 'robotics', title: 'Robotics' });
            // cyd never submits: only ada's and bob's latest submissions are graded.
            for (const login of ['ada', 'bob', 'cyd']) {
                const user = await store.createUser({ login, name: `${login}, student`, role: 'student' });
                await store.enroll(course.id, user.id);
            }
            const loaded = await loadExercise(path.join(repo, 'examples', 'lab', 'toast-controller'));
            const released = await releaseExercise(store, loaded, { course: 'robotics', authorId: teacher.id });
            for (const [login, note] of [
                ['ada', '// correct // tested'],
                ['bob', '// tested'],
            ] as const) {
                const user = await store.findUserByLogin(login);
                const ws = await store.workspace(user!.id, released.exercise.id);
                await store.saveFile({
                    workspaceId: ws.id,
                    path: 'toast/Controller.arc',
                    content: `package toast;\n${note}\n`,
                    authorId: user!.id,
                });
                await store.submit(ws.id, user!.id);
            }
            await releaseExercise(store, { ...loaded, name: 'ungraded', grading: undefined }, { course: 'robotics', authorId: teacher.id });
        } finally {
            await store.close();
        }
    });
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    async function grade(args: string[], withEngine = engine) {
        let out = '';
        let err = '';
        const io: LabIo = { cwd: dir, env: {}, out: (t) => void (out += t), err: (t) => void (err += t), readSecret: async () => '' };
        const program = new Command('maa-lab').exitOverride().addCommand(gradeCommand(io, withEngine));
        const error = await program.parseAsync(['node', 'maa-lab', 'grade', ...args]).then(
            () => undefined,
            (e: unknown) => e as Error,
        );
        return { out, err, error };
    }

    it("grades every student's latest submission: progress on stderr, a table on stdout", async () => {
        const run = await grade(['--course', 'robotics', '--exercise', 'toast-controller']);
        expect(run.error).toBeUndefined();
        expect(run.err).toContain('maa-lab: grading 2 submissions of toast-controller (run 1)');
        expect(run.err).toContain('maa-lab: grading toast-controller: 2/2 tasks done');
        expect(run.out).toBe(
            [
                'student  no-errors  hidden-tests  total',
                'ada      10/10      30/30         40/40',
                'bob      0/10       30/30         30/40',
                'graded 2 submissions of toast-controller in robotics (run 1)',
                '',
            ].join('\n'),
        );
    });

    it('fails with the reason: no grading, an unknown exercise, a failing engine', async () => {
        const ungraded = await grade(['--course', 'robotics', '--exercise', 'ungraded']);
        expect(ungraded.error?.message).toMatch(/the exercise ungraded has no grading: add a grading\/ folder/);
        const unknown = await grade(['--course', 'robotics', '--exercise', 'nope']);
        expect(unknown.error?.message).toBe('the course robotics has no released exercise "nope"');
        const failing = await grade(['--course', 'robotics', '--exercise', 'toast-controller'], async () => {
            throw new Error('Ray is not there');
        });
        expect(failing.error?.message).toMatch(/^the grading run \d+ failed: Ray is not there$/);
    });

    it('prints a table with a column per criterion and a dash where one is missing', () => {
        const row = (login: string, ids: string[]) => ({
            id: 1,
            run: 1,
            submission: 1,
            student: { login, name: login },
            score: ids.length,
            maxScore: 2,
            criteria: ids.map((id) => ({ id, title: id, kind: 'tests', score: 1, max: 1, feedback: [] })),
            tasks: [],
            recordings: [],
            gradedAt: '',
        });
        expect(scoreTable(['a', 'b'], [row('ada', ['a', 'b']), row('bo', ['a'])])).toBe(
            ['student  a    b    total', 'ada      1/1  1/1  2/2', 'bo       1/1  -    1/2'].join('\n'),
        );
    });
});
