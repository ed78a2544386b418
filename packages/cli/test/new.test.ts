// `maa-gen new <template> [dir]`: the templates of the built CLI (dist/templates, copied by
// scripts/copy-templates.mjs), each made into a project on which check, generate and test run
// as the printed next steps say; refusals (existing files, unknown template) with exit 2.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
// @ts-expect-error: a plain ES module of the build step, without type declarations
import { adaptReadme, templateFiles } from '../scripts/copy-templates.mjs';
import { ModelDir, requireBuiltCli, runCli, runCliInProcess } from './helpers.js';

const repoDir = fileURLToPath(new URL('../../../', import.meta.url));
const distTemplates = fileURLToPath(new URL('../dist/templates/', import.meta.url));

let dirs: ModelDir[] = [];
function tempDir(): ModelDir {
    const d = new ModelDir();
    dirs.push(d);
    return d;
}

beforeAll(() => requireBuiltCli());
afterEach(() => {
    for (const d of dirs) d.dispose();
    dirs = [];
});

describe('maa-gen new --list', () => {
    it('lists every template with a one-line description', async () => {
        const r = await runCliInProcess(['new', '--list'], tempDir().dir);
        expect(r.code).toBe(0);
        const lines = r.stdout.trimEnd().split('\n');
        expect(lines.map((l) => l.trim().split(/\s+/)[0])).toEqual([
            'minimal',
            'toast-service',
            'toast-controller',
            'pick-and-place',
            'line-follower',
        ]);
        for (const line of lines) expect(line.trim().split(/\s{2,}/)[1]?.length ?? 0).toBeGreaterThan(20);
    });
});

describe('maa-gen new minimal', () => {
    it('creates a project on which check is clean and every stream test passes', async () => {
        const work = tempDir();
        const made = await runCliInProcess(['new', 'minimal', 'proj'], work.dir);
        expect(made.code, made.stderr).toBe(0);
        expect(made.stdout).toContain('Created proj from the template minimal (7 files).');
        for (const step of [
            'cd proj',
            'npx maa-gen check .',
            'npx maa-gen test App.arcapp',
            'npx maa-gen generate App.arcapp --platform timesync',
        ]) {
            expect(made.stdout).toContain(step);
        }
        const proj = work.path('proj');
        const check = await runCliInProcess(['check', '.'], proj);
        expect(check.code, check.stdout + check.stderr).toBe(0);
        expect(check.stdout).toBe('');
        expect(check.stderr).toContain('0 errors, 0 warnings in 3 files (1 root)');

        const test = await runCliInProcess(['test', 'App.arcapp', '--format', 'json'], proj);
        expect(test.code, test.stdout + test.stderr).toBe(0);
        const report = JSON.parse(test.stdout) as {
            results: Array<{ file: string; passed: boolean }>;
            summary: { passed: number; failed: number };
        };
        expect(report.summary).toEqual({ generated: true, passed: 4, failed: 0 });
        expect(new Set(report.results.map((r) => path.basename(r.file)))).toEqual(new Set(['Lamp.stream', 'Toggle.stream']));
    }, 180_000);

    it('writes into the current folder with "." and then prints no cd step', async () => {
        const work = tempDir();
        const r = await runCliInProcess(['new', 'minimal', '.'], work.dir);
        expect(r.code, r.stderr).toBe(0);
        expect(r.stdout).toContain('Created . from the template minimal');
        expect(r.stdout).not.toContain('cd ');
        expect(existsSync(work.path('hello/Toggle.arc'))).toBe(true);
    });

    it('defaults the folder to the template name and accepts an existing folder without collisions', async () => {
        const work = tempDir();
        work.write('minimal/notes.txt', 'mine\n');
        const r = await runCliInProcess(['new', 'minimal'], work.dir);
        expect(r.code, r.stderr).toBe(0);
        expect(readFileSync(work.path('minimal/notes.txt'), 'utf8')).toBe('mine\n');
        expect(existsSync(work.path('minimal/App.arcapp'))).toBe(true);
    });
});

describe('maa-gen new toast-service', () => {
    it('creates the example as a project: check is clean, the timesync platform generates', async () => {
        const work = tempDir();
        const made = await runCliInProcess(['new', 'toast-service', 'demo'], work.dir);
        expect(made.code, made.stderr).toBe(0);
        expect(made.stdout).toContain('npx maa-gen test TR.arcapp');
        const demo = work.path('demo');
        const check = await runCliInProcess(['check', '.'], demo);
        expect(check.code, check.stdout + check.stderr).toBe(0);
        expect(check.stderr).toMatch(/^0 errors, /);

        const gen = await runCliInProcess(['generate', 'TR.arcapp', '--platform', 'timesync', '--out', 'out'], demo);
        expect(gen.code, gen.stdout + gen.stderr).toBe(0);
        expect(existsSync(path.join(demo, 'out', 'timesync', 'maa_app.py'))).toBe(true);
        // The handwritten platform components of the example (toast/*.timesync.py) are part of the build.
        expect(existsSync(path.join(demo, 'out', 'timesync', 'toast', 'color_sensor_impl.py'))).toBe(true);
    }, 180_000);

    it('is the repository example itself (copied at build time): same files, same bytes, the README adapted', () => {
        const example = path.join(repoDir, 'examples', 'toast-service');
        const template = path.join(distTemplates, 'toast-service');
        const files = templateFiles(example) as string[];
        expect(templateFiles(template)).toEqual(files);
        for (const rel of files.filter((f) => f !== 'README.md')) {
            expect(readFileSync(path.join(template, rel)).equals(readFileSync(path.join(example, rel))), rel).toBe(true);
        }
        const readme = readFileSync(path.join(template, 'README.md'), 'utf8');
        // Only the note names the example's folder; every command works in the project.
        expect(readme.match(/examples\/toast-service/g)).toHaveLength(1);
        expect(readme).toContain('from `examples/toast-service` of the MontiArcAutomaton for the web repository');
        expect(readme).not.toContain('](../../');
        expect(readme).toContain('npx maa-gen check .');
    });
});

describe('adaptReadme (build step)', () => {
    it('makes paths relative to the project and repository links plain text, after a note', () => {
        const text =
            '# T\n\nIntro.\n\nRun `maa-gen check examples/t` and `maa-gen test examples/t/A.arcapp`; see [docs/x.md](../../docs/x.md#y) and [the guide](../../docs/g.md).\n';
        const out = adaptReadme(text, 'examples/t', 't') as string;
        expect(out).toBe(
            '# T\n\n> Created by `maa-gen new t` from `examples/t` of the MontiArcAutomaton for the web repository; files named "of the ' +
                'repository" are in that repository, not in this project.\n\nIntro.\n\nRun `maa-gen check .` and `maa-gen test A.arcapp`; ' +
                'see `docs/x.md` of the repository and the guide (`docs/g.md` of the repository).\n',
        );
    });
});

describe('maa-gen new refusals', () => {
    it('refuses to overwrite: names the existing file, exits 2 and writes nothing', async () => {
        const work = tempDir();
        work.write('proj/maa.json', '{"keep": true}\n');
        const r = await runCliInProcess(['new', 'minimal', 'proj'], work.dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('maa-gen: error: refusing to overwrite proj/maa.json');
        expect(r.stderr).toContain('nothing was written');
        expect(r.stdout).toBe('');
        expect(readFileSync(work.path('proj/maa.json'), 'utf8')).toBe('{"keep": true}\n');
        expect(readdirSync(work.path('proj'))).toEqual(['maa.json']);
    });

    it('refuses a file where the template needs a folder', async () => {
        const work = tempDir();
        work.write('proj/hello', 'a file, not a folder\n');
        const r = await runCliInProcess(['new', 'minimal', 'proj'], work.dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('refusing to overwrite proj/hello');
        expect(readdirSync(work.path('proj'))).toEqual(['hello']);
    });

    it('names at most five files and counts the rest', async () => {
        const work = tempDir();
        const first = await runCliInProcess(['new', 'toast-service', 'demo'], work.dir);
        expect(first.code).toBe(0);
        const again = await runCliInProcess(['new', 'toast-service', 'demo'], work.dir);
        expect(again.code).toBe(2);
        expect(again.stderr.match(/refusing to overwrite/g)).toHaveLength(5);
        expect(again.stderr).toContain('... and 19 more files of the template that exist');
    });

    it('an unknown template exits 2 and lists the templates', async () => {
        const r = await runCli(['new', 'toast', 'x'], tempDir().dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('maa-gen: error: unknown template: toast');
        expect(r.stderr).toMatch(/^ {2}minimal {2,}\S/m);
        expect(r.stderr).toMatch(/^ {2}toast-service {2,}\S/m);
        expect(r.stdout).toBe('');
    });

    it('no template exits 2 and lists the templates', async () => {
        const r = await runCliInProcess(['new'], tempDir().dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('no template given');
        expect(r.stderr).toContain('toast-service');
    });
});
