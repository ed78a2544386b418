import { describe, expect, test } from 'vitest';
import { exerciseIssues, exerciseManifestContract, isReadOnly, layerStarter, releasedExerciseContract } from '../dist/exercise/index.js';

const valid = {
    format: 'maa-exercise/1',
    title: 'The toast controller',
    description: 'description.md',
    app: 'TR.arcapp',
    readOnly: ['toast/types/', 'toast/Robot.arc'],
    tests: ['toast/Controller.stream'],
    platforms: ['timesync'],
};
const files = ['TR.arcapp', 'maa.json', 'toast/Controller.arc', 'toast/Controller.stream', 'toast/Robot.arc', 'toast/types/Types.cd'];

describe('exercise.json (the lab exercise format)', () => {
    test('a valid exercise has no issues, with and without its starter files', () => {
        expect(exerciseIssues(valid)).toEqual([]);
        expect(exerciseIssues(valid, files)).toEqual([]);
        expect(exerciseManifestContract.check({ ...valid, starter: 'files' })).toBe(true);
        expect(exerciseIssues({ ...valid, base: '../../toast-service', omit: ['README.md', 'toast/tests/'] })).toEqual([]);
    });

    test.each([
        ['wrong format', { ...valid, format: 'maa-exercise/2' }, '/format', "format must be 'maa-exercise/1'"],
        ['empty title', { ...valid, title: '' }, '/title', 'title must be a non-empty string'],
        ['description not Markdown', { ...valid, description: 'description.txt' }, '/description', 'ending in .md'],
        ['app not an .arcapp', { ...valid, app: 'TR.arc' }, '/app', 'ending in .arcapp'],
        ['absolute read-only path', { ...valid, readOnly: ['/etc/passwd'] }, '/readOnly/0', 'relative path'],
        ['.. in a test path', { ...valid, tests: ['../x.stream'] }, '/tests/0', 'relative path'],
        ['a test that is no .stream', { ...valid, tests: ['toast/Controller.arc'] }, '/tests/0', 'ending in .stream'],
        ['no platform', { ...valid, platforms: [] }, '/platforms', 'non-empty list'],
        ['unknown field', { ...valid, solution: 'solution' }, '/solution', ''],
        ['absolute base', { ...valid, base: '/srv/examples/toast' }, '/base', 'relative folder path'],
        ['a . segment in the base', { ...valid, base: '../../toast/./x' }, '/base', 'relative folder path'],
        ['a backslash in the base', { ...valid, base: '..\\toast' }, '/base', 'relative folder path'],
        ['.. in an omit entry', { ...valid, base: '../x', omit: ['../README.md'] }, '/omit/0', 'relative path'],
        ['omit twice the same', { ...valid, base: '../x', omit: ['a', 'a'] }, '/omit', 'distinct'],
    ])('%s: an issue at the field', (_what, value, pointer, message) => {
        const issues = exerciseIssues(value);
        expect(issues.length).toBeGreaterThan(0);
        expect(issues.some((i) => i.pointer === pointer && i.message.includes(message))).toBe(true);
    });

    test('missing fields are named', () => {
        const { title: _t, platforms: _p, ...rest } = valid;
        const pointers = exerciseIssues(rest).map((i) => i.pointer);
        expect(pointers).toEqual(expect.arrayContaining(['/title', '/platforms']));
    });

    test('against the starter files: the app, every test and every read-only entry must exist', () => {
        const issues = exerciseIssues(
            {
                ...valid,
                app: 'Other.arcapp',
                tests: ['toast/Controller.stream', 'toast/Gone.stream'],
                readOnly: ['toast/lib/', 'maa.json'],
            },
            files,
        );
        expect(issues).toEqual([
            { pointer: '/app', message: 'starter/Other.arcapp does not exist' },
            { pointer: '/tests/1', message: 'starter/toast/Gone.stream does not exist' },
            { pointer: '/readOnly/0', message: 'starter/toast/lib/ holds no file' },
        ]);
    });

    test('parse names the file and the JSON path', () => {
        expect(() => exerciseManifestContract.parse({ ...valid, tests: 'x' }, 'examples/lab/x/exercise.json')).toThrow(
            /examples\/lab\/x\/exercise\.json: not a valid exercise\.json: \/tests: /,
        );
    });

    test('isReadOnly: exact paths and folders ending in /', () => {
        expect(isReadOnly(valid, 'toast/Robot.arc')).toBe(true);
        expect(isReadOnly(valid, 'toast/types/Types.cd')).toBe(true);
        expect(isReadOnly(valid, 'toast/Controller.arc')).toBe(false);
        expect(isReadOnly(valid, 'toast/types')).toBe(false);
    });

    test('a released exercise: valid and invalid', () => {
        const released = {
            format: 'maa-exercise/1',
            name: 'toast-controller',
            title: 'The toast controller',
            description: '# Toast\n',
            app: 'TR.arcapp',
            readOnly: [],
            tests: ['toast/Controller.stream'],
            platforms: ['timesync'],
            files,
            starterVersion: 1,
        };
        expect(releasedExerciseContract.issues(released)).toEqual([]);
        expect(releasedExerciseContract.issues({ ...released, starterVersion: 0 }).map((i) => i.pointer)).toContain('/starterVersion');
        expect(releasedExerciseContract.issues({ ...released, name: 'Toast Controller' }).map((i) => i.pointer)).toContain('/name');
    });

    test('layerStarter: the base without what omit names, the starter over it, sorted; where each file comes from', () => {
        const base = [
            'README.md',
            'TR.arcapp',
            'toast/Controller.arc',
            'toast/Robot.stream',
            'toast/tests/A.stream',
            'toast/tests/B.stream',
        ];
        const manifest = { base: '../../toast-service', omit: ['README.md', 'toast/tests/'] };
        expect(layerStarter(manifest, base, ['toast/Controller.arc', 'toast/New.arc'])).toEqual({
            files: [
                { path: 'TR.arcapp', from: 'base' },
                { path: 'toast/Controller.arc', from: 'starter' },
                { path: 'toast/New.arc', from: 'starter' },
                { path: 'toast/Robot.stream', from: 'base' },
            ],
            issues: [],
        });
        // No base: the starter folder alone.
        expect(layerStarter({}, [], ['b', 'a']).files).toEqual([
            { path: 'a', from: 'starter' },
            { path: 'b', from: 'starter' },
        ]);
    });

    test('layerStarter: omit without a base, naming no file of the base, or one the starter replaces', () => {
        expect(layerStarter({ omit: ['README.md'] }, [], ['a']).issues).toEqual([
            { pointer: '/omit', message: 'omit drops files of the base: it needs a base' },
        ]);
        expect(layerStarter({ base: '../b', omit: ['Gone.md', 'none/', 'a'], starter: 'files' }, ['a', 'c'], ['a']).issues).toEqual([
            { pointer: '/omit/0', message: '../b/Gone.md does not exist (omit names files of the base)' },
            { pointer: '/omit/1', message: '../b/none/ holds no file (omit names files of the base)' },
            { pointer: '/omit/2', message: "files/a replaces the base's file already: omit only what the starter leaves out" },
        ]);
    });
});
