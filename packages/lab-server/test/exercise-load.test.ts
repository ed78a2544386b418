// Loading exercise folders: the examples under examples/lab/ and invalid folders (every problem
// named by file and JSON path).
import { mkdtempSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { releasedExerciseContract } from '@maa/protocol/exercise';
import { afterAll, describe, expect, it } from 'vitest';
import { ExerciseError, loadExercise, releasedSpec } from '../src/exercises/index.js';
import { MANIFEST, STARTER, writeExercise, writeFiles } from './exercise-folder.js';

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

/** A folder of files (the base of an exercise) at `dir/rel`. */
const writeFolder = (rel: string, files: Record<string, string>) => writeFiles(path.join(dir, rel), files);

describe('loadExercise with a base (the starter is a folder beside the exercises, with files replaced and omitted)', () => {
    // dir/lab/<exercise> and dir/lamp-example: the base lies beside the exercises, as examples/toast-service does.
    const lab = path.join(dir, 'lab');
    const EXAMPLE = {
        ...STARTER,
        'hello/Lamp.arc': 'package hello;\ncomponent Lamp {\n  port in boolean button;\n  // the full solution\n}\n',
        'hello/Other.stream': 'component hello.Other;\n',
        'README.md': '# the lamp example\n',
        'extra/Notes.md': 'notes\n',
        'extra/more/Deep.md': 'deep\n',
    };
    writeFolder('lamp-example', EXAMPLE);
    writeFileSync(path.join(dir, 'a-file'), 'not a folder\n');
    const STUB = { 'hello/Lamp.arc': STARTER['hello/Lamp.arc'] as string };
    const BASED = { ...MANIFEST, base: '../../lamp-example', omit: ['README.md', 'hello/Other.stream', 'extra/'] };

    it("gives the base's files without the omitted ones, with the starter's over them", async () => {
        const loaded = await loadExercise(writeExercise(lab, 'based', { ...STUB, 'hello/New.arc': 'package hello;\n' }, BASED));
        expect(loaded.files).toEqual({ ...STARTER, 'hello/New.arc': 'package hello;\n' });
        expect(Object.keys(loaded.files)).toEqual(Object.keys(loaded.files).sort());
        expect(releasedSpec(loaded, 1).files).toEqual(Object.keys(loaded.files));
        expect(releasedExerciseContract.issues(releasedSpec(loaded, 1))).toEqual([]);
    });

    it("without omit the base's files all stay; a trailing / on the base is fine", async () => {
        const { omit: _o, ...noOmit } = BASED;
        const loaded = await loadExercise(writeExercise(lab, 'no-omit', STUB, { ...noOmit, base: '../../lamp-example/' }));
        expect(loaded.files).toEqual({ ...EXAMPLE, ...STUB });
    });

    it('checks app, tests and readOnly against the merged starter', async () => {
        const folder = writeExercise(lab, 'omitted-test', STUB, { ...BASED, omit: ['hello/Lamp.stream'] });
        expect(await problems(folder)).toEqual([
            `${path.join(folder, 'exercise.json')}: /tests/0: starter/hello/Lamp.stream does not exist`,
        ]);
    });

    it.each([
        ['a base that does not exist', { base: '../../gone' }, '/base: the folder ../../gone does not exist'],
        ['a base that is a file', { base: '../../a-file' }, '/base: ../../a-file is not a folder'],
        ["a base outside the exercises' grandparent", { base: '../../..' }, '/base: ../../.. lies outside'],
        ['a base holding the exercise folder', { base: '..' }, '/base: .. holds the exercise folder or lies in it'],
        [
            'a base inside the exercise folder (its solution)',
            { base: 'solution' },
            '/base: solution holds the exercise folder or lies in it',
        ],
        ['an absolute base', { base: '/etc' }, '/base: base must be a relative folder path'],
        ['omit without a base', { base: undefined }, '/omit: omit drops files of the base: it needs a base'],
        ['omit naming no file of the base', { omit: ['hello/Gone.arc'] }, '/omit/0: ../../lamp-example/hello/Gone.arc does not exist'],
        ['omit naming an empty folder', { omit: ['none/'] }, '/omit/0: ../../lamp-example/none/ holds no file'],
        [
            'omit of a file the starter replaces',
            { omit: ['hello/Lamp.arc'] },
            "/omit/0: starter/hello/Lamp.arc replaces the base's file already",
        ],
    ])('refuses %s', async (_what, change, message) => {
        const name = `bad-${_what.replace(/[^a-z]+/g, '-')}`.replace(/-$/, '');
        const folder = writeExercise(lab, name, STUB, { ...BASED, ...change });
        const found = await problems(folder);
        expect(
            found.some((p) => p.startsWith(`${path.join(folder, 'exercise.json')}: `) && p.includes(message)),
            found.join('\n'),
        ).toBe(true);
    });

    it('follows links before confining the base: a link out of the tree is refused', async () => {
        const outside = mkdtempSync(path.join(tmpdir(), 'maa-lab-outside-'));
        try {
            writeFileSync(path.join(outside, 'App.arcapp'), STARTER['App.arcapp'] as string);
            symlinkSync(outside, path.join(dir, 'linked-example'));
            const folder = writeExercise(lab, 'linked', STUB, { ...BASED, base: '../../linked-example', omit: undefined });
            expect((await problems(folder))[0]).toMatch(/\/base: \.\.\/\.\.\/linked-example lies outside/);
        } finally {
            rmSync(outside, { recursive: true, force: true });
        }
    });
});
