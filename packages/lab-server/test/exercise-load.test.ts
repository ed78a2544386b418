// Loading exercise folders: the examples under examples/lab/ and invalid folders (every problem
// named by file and JSON path).
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { releasedExerciseContract } from '@maa/protocol/exercise';
import { afterAll, describe, expect, it } from 'vitest';
import { ExerciseError, loadExercise, releasedSpec } from '../src/exercises/index.js';
import { MANIFEST, STARTER, writeExercise } from './exercise-folder.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const dir = mkdtempSync(path.join(tmpdir(), 'maa-lab-load-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

async function problems(folder: string): Promise<readonly string[]> {
    const error = await loadExercise(folder).then(
        () => undefined,
        (e: unknown) => e,
    );
    expect(error).toBeInstanceOf(ExerciseError);
    return (error as ExerciseError).problems;
}

describe('loadExercise', () => {
    it.each(['toast-controller', 'pick-and-place', 'line-follower'])(
        'loads examples/lab/%s: starter only, released spec valid',
        async (name) => {
            const loaded = await loadExercise(path.join(repo, 'examples/lab', name));
            expect(loaded.name).toBe(name);
            expect(Object.keys(loaded.files).length).toBeGreaterThan(3);
            expect(Object.keys(loaded.files).some((f) => f.startsWith('solution'))).toBe(false);
            expect(loaded.description.startsWith('# ')).toBe(true);
            expect(releasedExerciseContract.issues(releasedSpec(loaded, 1))).toEqual([]);
        },
    );

    it('reads a valid folder without its solution/', async () => {
        const loaded = await loadExercise(writeExercise(dir, 'valid', STARTER));
        expect(loaded.files).toEqual(STARTER);
        expect(loaded.manifest).toEqual(MANIFEST);
    });

    it('names the file and the JSON path of every problem of exercise.json', async () => {
        const folder = writeExercise(dir, 'bad-fields', STARTER, { ...MANIFEST, title: '', platforms: [] });
        const where = path.join(folder, 'exercise.json');
        expect(await problems(folder)).toEqual(
            expect.arrayContaining([
                expect.stringMatching(new RegExp(`^${where.replace(/[.]/g, '\\.')}: /title: title must be a non-empty string`)),
                `${where}: /platforms: platforms must be a non-empty list of distinct names`,
            ]),
        );
    });

    it('checks the paths against the starter folder', async () => {
        const folder = writeExercise(dir, 'bad-paths', STARTER, { ...MANIFEST, tests: ['hello/Gone.stream'], readOnly: ['nothing/'] });
        const where = path.join(folder, 'exercise.json');
        expect(await problems(folder)).toEqual([
            `${where}: /tests/0: starter/hello/Gone.stream does not exist`,
            `${where}: /readOnly/0: starter/nothing/ holds no file`,
        ]);
    });

    it('refuses a folder without exercise.json, bad JSON, a missing description, a bad name', async () => {
        expect((await problems(path.join(dir, 'nothing-here')))[0]).toMatch(/exercise\.json: not found/);
        const badJson = writeExercise(dir, 'bad-json', STARTER);
        writeFileSync(path.join(badJson, 'exercise.json'), '{ "format": ');
        expect((await problems(badJson))[0]).toMatch(/exercise\.json: not JSON/);
        const noDescription = writeExercise(dir, 'no-description', STARTER, { ...MANIFEST, description: 'gone.md' });
        expect((await problems(noDescription))[0]).toMatch(/exercise\.json: \/description: gone\.md does not exist/);
        const badName = writeExercise(dir, 'Bad_Name', STARTER);
        expect((await problems(badName))[0]).toMatch(/lower case letters, digits and -/);
    });
});
