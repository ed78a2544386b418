import { readdirSync, readFileSync, rmSync, statSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
// @ts-expect-error: a plain ESM script shared with scripts/update-golden.mjs
import { RTE_FOLDERS, freshBase, rteCopy, generateCase, goldenCases, goldenDir, listFiles, packageDir } from '../scripts/golden-lib.mjs';
import { ensureVenv, lintPython, run, venvPython } from './python-env.js';

interface GoldenCase {
    name: string;
    app: string;
    platform: string;
}
interface Generated {
    result: {
        ok: boolean;
        diagnostics: Array<{ code?: string; message: string }>;
        platforms: Array<{ files: string[]; unchanged: string[]; kept: string[] }>;
    };
    dir: string;
}

// Golden files of the Python generators: regenerate with `npm run golden:update -w @maa/generators-python`.
describe.each(goldenCases() as GoldenCase[])('golden files: $name', (c) => {
    let first: Generated;
    let base: string;
    beforeAll(async () => {
        base = freshBase() as string;
        first = (await generateCase(c, base)) as Generated;
    });
    afterAll(() => rmSync(base, { recursive: true, force: true }));

    it('generates without errors', () => {
        expect(first.result.diagnostics.filter((d) => (d as { severity?: string }).severity === 'error')).toEqual([]);
        expect(first.result.ok).toBe(true);
    });

    it('matches the golden files byte for byte', () => {
        const golden = path.join(goldenDir, c.name);
        const generated = listFiles(first.dir) as string[];
        expect(generated).toEqual(listFiles(golden));
        for (const file of generated) {
            expect(readFileSync(path.join(first.dir, file), 'utf8'), file).toBe(readFileSync(path.join(golden, file), 'utf8'));
        }
    });

    it('copies the run-time environments verbatim', () => {
        for (const rte of RTE_FOLDERS as string[]) {
            const source = path.join(packageDir, 'rte', rte);
            const copy = rteCopy(first.dir, rte) as string | undefined;
            if (!copy) continue; // this platform does not use it
            for (const file of (listFiles(source, false) as string[]).filter((f) => f.endsWith('.py'))) {
                expect(readFileSync(path.join(copy, file), 'utf8'), `${rte}/${file}`).toBe(readFileSync(path.join(source, file), 'utf8'));
            }
        }
    });

    it('re-generation is byte-identical', async () => {
        const before = new Map((listFiles(first.dir, false) as string[]).map((f) => [f, readFileSync(path.join(first.dir, f))]));
        const second = (await generateCase(c, base)) as Generated;
        expect(second.result.ok).toBe(true);
        const p = second.result.platforms[0];
        expect(p.unchanged.length + p.kept.length).toBe(p.files.length);
        for (const [file, bytes] of before) expect(readFileSync(path.join(second.dir, file)).equals(bytes), file).toBe(true);
    });

    it('passes ruff check and py_compile', async () => {
        await ensureVenv();
        if (c.platform === 'rospython') {
            // ROS 2 packages: the settings of test/ros2 (the packages and run-time environments are third-party imports there)
            const pkgs = readdirSync(first.dir).filter((d) => statSync(path.join(first.dir, d)).isDirectory());
            const r = await run(
                venvPython,
                [
                    '-m',
                    'ruff',
                    'check',
                    '--no-cache',
                    '--output-format',
                    'concise',
                    '--config',
                    path.join(packageDir, 'test', 'ros2', 'ruff-generated.toml'),
                    '--config',
                    `lint.isort.known-third-party=[${[...pkgs, 'maa_behavior', 'maa_ros2'].map((x) => `'${x}'`).join(',')}]`,
                    '--extend-exclude',
                    'maa_behavior',
                    '.',
                ],
                first.dir,
            );
            expect(r.status, r.stdout + r.stderr).toBe(0);
            return;
        }
        expect(await lintPython(first.dir)).toEqual([]);
    });
});
