// `maa-gen new <exercise>`: every lab exercise of examples/lab/ is a template (its starter, its
// description as README.md, never its solution), and the project it makes is one `maa-gen check`
// reads: the starter's diagnostics, nothing else.
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import { ModelDir, requireBuiltCli, runCliInProcess } from './helpers.js';

const repoDir = fileURLToPath(new URL('../../../', import.meta.url));
const labDir = path.join(repoDir, 'examples', 'lab');
const manifest = JSON.parse(readFileSync(fileURLToPath(new URL('../templates/templates.json', import.meta.url)), 'utf8')) as {
    templates: Array<{ name: string; from: string; app: string; readme?: string }>;
};

/** The lab exercises: the folders of examples/lab/ with an exercise.json. */
const exercises = readdirSync(labDir, { withFileTypes: true })
    .filter((e) => e.isDirectory() && existsSync(path.join(labDir, e.name, 'exercise.json')))
    .map((e) => e.name)
    .sort();

/** The error codes `maa-gen check` reports on each starter (the student's task). */
const STARTER_ERRORS: Record<string, string[]> = {
    'line-follower': [],
    'pick-and-place': ['robotarm/command-without-program', 'robotarm/command-without-program'],
    'toast-controller': [],
};

/** The files below `dir` (relative, `/`, sorted). */
function filesOf(dir: string): string[] {
    return readdirSync(dir, { recursive: true, encoding: 'utf8' })
        .filter((f) => statSync(path.join(dir, f)).isFile())
        .map((f) => f.split(path.sep).join('/'))
        .sort();
}

let dirs: ModelDir[] = [];
beforeAll(() => requireBuiltCli());
afterEach(() => {
    for (const d of dirs) d.dispose();
    dirs = [];
});

describe('maa-gen new <lab exercise>', () => {
    it('offers every exercise of examples/lab/ with its starter, its description and its app', () => {
        expect(exercises).toEqual(Object.keys(STARTER_ERRORS));
        for (const name of exercises) {
            const template = manifest.templates.find((t) => t.name === name);
            const exercise = JSON.parse(readFileSync(path.join(labDir, name, 'exercise.json'), 'utf8')) as { app: string };
            expect(template, name).toEqual(
                expect.objectContaining({
                    from: `../../examples/lab/${name}/starter`,
                    readme: `../../examples/lab/${name}/description.md`,
                    app: exercise.app,
                }),
            );
        }
    });

    it.each(exercises)('new %s makes a project maa-gen check reads: the starter, its README, no solution', async (name) => {
        const work = new ModelDir();
        dirs.push(work);
        const made = await runCliInProcess(['new', name, 'demo'], work.dir);
        expect(made.code, made.stderr).toBe(0);
        const demo = work.path('demo');
        expect(readFileSync(path.join(demo, 'README.md'), 'utf8')).toBe(readFileSync(path.join(labDir, name, 'description.md'), 'utf8'));
        const solution = path.join(labDir, name, 'solution');
        for (const file of readdirSync(solution, { recursive: true, encoding: 'utf8' })) {
            if (!statSync(path.join(solution, file)).isFile()) continue;
            // The student gets the starter's version of each file the solution changes.
            expect(readFileSync(path.join(demo, file), 'utf8'), file).toBe(readFileSync(path.join(labDir, name, 'starter', file), 'utf8'));
        }
        const exercise = JSON.parse(readFileSync(path.join(labDir, name, 'exercise.json'), 'utf8')) as { base?: string; omit?: string[] };
        if (exercise.base) {
            // The base's files (without those omitted) with the starter's over them, byte for byte.
            const base = path.resolve(labDir, name, exercise.base);
            const omitted = (f: string) => (exercise.omit ?? []).some((o) => (o.endsWith('/') ? f.startsWith(o) : f === o));
            const expected = new Map<string, string>();
            for (const [dir, keep] of [
                [base, (f: string) => !omitted(f)],
                [path.join(labDir, name, 'starter'), () => true],
            ] as const)
                for (const f of filesOf(dir)) if (keep(f)) expected.set(f, path.join(dir, f));
            expect(filesOf(demo).filter((f) => f !== 'README.md')).toEqual([...expected.keys()].sort());
            for (const [f, source] of expected) expect(readFileSync(path.join(demo, f), 'utf8'), f).toBe(readFileSync(source, 'utf8'));
        }
        const check = await runCliInProcess(['check', '.', '--format', 'json'], demo);
        const diagnostics = (JSON.parse(check.stdout) as { diagnostics: Array<{ severity: string; code: string }> }).diagnostics;
        expect(diagnostics.filter((d) => d.severity === 'error').map((d) => d.code)).toEqual(STARTER_ERRORS[name]);
        expect(check.code).toBe(STARTER_ERRORS[name]?.length ? 1 : 0);
    });
});
