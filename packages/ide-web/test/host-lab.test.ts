import { describe, expect, it } from 'vitest';
import { exerciseItems } from '../src/host/exercise-items.js';
import { type ExerciseInfo, labMeta, parseExerciseInfo, withCsrfToken } from '../src/host/lab.js';

const INFO: ExerciseInfo = {
    course: 'robotics',
    exercise: 'toast-controller',
    owner: 'ada',
    writable: true,
    title: "The toast robot's controller",
    description: '# The controller\n\nWrite the automaton.',
    app: 'TR.arcapp',
    readOnly: ['TR.arcapp', 'toast/types/'],
    tests: ['toast/Controller.stream'],
    platforms: ['timesync'],
    latestTests: null,
};

/** A fetch that records what it was asked. */
function recorder() {
    const calls: { url: string; method: string; token: string | null }[] = [];
    const fetchFn = (async (input: RequestInfo | URL, init?: RequestInit) => {
        const headers = new Headers(init?.headers);
        calls.push({ url: String(input), method: init?.method ?? 'GET', token: headers.get('X-CSRF-Token') });
        return new Response('{}');
    }) as typeof fetch;
    return { calls, fetchFn };
}

describe('lab mode of the page', () => {
    it('finds the lab’s meta tags, and nothing on maa-ide’s page', () => {
        const doc = (tags: Record<string, string>) => ({
            querySelector: (selector: string) => {
                const name = /name="([^"]+)"/.exec(selector)?.[1] ?? '';
                return name in tags ? ({ getAttribute: () => tags[name] } as unknown as Element) : null;
            },
        });
        expect(labMeta(doc({ 'maa-csrf-token': 't0k', 'maa-lab-workspace': '/api/ws/r/e/ada' }))).toEqual({
            csrfToken: 't0k',
            workspace: '/api/ws/r/e/ada',
        });
        expect(labMeta(doc({}))).toBeUndefined();
        expect(labMeta(doc({ 'maa-csrf-token': '', 'maa-lab-workspace': '/x' }))).toBeUndefined();
    });

    it('puts the CSRF token on writes to its own origin only, never on reads or other sites', async () => {
        const { calls, fetchFn } = recorder();
        const wrapped = withCsrfToken(fetchFn, 't0k', 'http://lab.test', 'http://lab.test/ide/r/e/ada/');
        await wrapped('api/file?path=a', { method: 'PUT', body: 'x', headers: { 'Content-Type': 'text/plain' } });
        await wrapped('api/generate', { method: 'post' });
        await wrapped('api/files');
        await wrapped('http://lab.test/api/file', { method: 'HEAD' });
        await wrapped('https://elsewhere.example/api/file', { method: 'PUT' });
        expect(calls.map((c) => [c.method, c.token])).toEqual([
            ['PUT', 't0k'],
            ['post', 't0k'],
            ['GET', null],
            ['HEAD', null],
            ['PUT', null],
        ]);
    });

    it('accepts the lab’s answer about the exercise and refuses one without its fields', () => {
        expect(parseExerciseInfo({ ...INFO, extra: 1 })).toMatchObject({ exercise: 'toast-controller', writable: true });
        expect(() => parseExerciseInfo({ ...INFO, readOnly: 'TR.arcapp' })).toThrow(/readOnly/);
        expect(() => parseExerciseInfo(null)).toThrow(/exercise/);
        expect(() => parseExerciseInfo({ ...INFO, description: undefined })).toThrow(/description/);
    });
});

describe('the Exercise view', () => {
    it('shows the exercise, the owner’s workspace, the application, the tests and the read-only files', () => {
        const items = exerciseItems(INFO);
        expect(items.map((i) => i.label)).toEqual([
            "The toast robot's controller",
            'Your workspace (ada)',
            'Application',
            'Tests',
            'Read-only files',
        ]);
        expect(items[0]).toMatchObject({ markdown: '# The controller\n\nWrite the automaton.' });
        expect(items[2]).toMatchObject({ description: 'TR.arcapp', file: 'TR.arcapp' });
        expect(items[3]).toMatchObject({
            description: 'not run yet',
            children: [{ label: 'toast/Controller.stream', file: 'toast/Controller.stream' }],
        });
        // A folder entry opens nothing; a file entry opens the file.
        expect(items[4]?.children).toEqual([
            { label: 'TR.arcapp', file: 'TR.arcapp', icon: 'lock' },
            { label: 'toast/types/', icon: 'lock' },
        ]);
    });

    it('says when an instructor looks at a student’s workspace, and the last test run', () => {
        const items = exerciseItems({ ...INFO, writable: false, latestTests: { passed: 3, failed: 1, at: '2026-11-24T07:00:00Z' } });
        expect(items[1]).toMatchObject({ label: "ada's workspace", description: 'read-only (instructor view)' });
        expect(items[3]).toMatchObject({ description: 'last run: 3 passed, 1 failed', icon: 'error' });
    });
});
