import { describe, expect, test } from 'vitest';
import { exerciseIssues, exerciseManifestContract, isReadOnly, releasedExerciseContract } from '../dist/exercise/index.js';

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
});
