import { readFileSync } from 'node:fs';
import path from 'node:path';
import { afterEach, describe, expect, test } from 'vitest';
import { GradingSpecError, loadGradingSpec } from '../src/index.js';
import { fixtures, repoDir, tempDir, writeFiles } from './exercise.js';

const valid = JSON.parse(readFileSync(path.join(fixtures, 'toast-controller', 'grading.json'), 'utf8')) as {
    criteria: Array<Record<string, unknown>>;
};

describe('loadGradingSpec', () => {
    const dirs: Array<() => void> = [];
    afterEach(() => {
        for (const remove of dirs.splice(0)) remove();
    });
    const folder = (files: Record<string, string>): string => {
        const t = tempDir('spec');
        dirs.push(t.remove);
        writeFiles(t.dir, files);
        return t.dir;
    };

    test('loads a valid grading folder', async () => {
        const spec = await loadGradingSpec(path.join(fixtures, 'toast-controller'));
        expect(spec.criteria.map((c) => c.kind)).toEqual(['structure', 'diagnostics', 'tests', 'scenarios', 'coverage']);
    });

    test.each(['toast-controller', 'pick-and-place', 'line-follower'])('the grading folder of the lab exercise %s loads', async (name) => {
        const dir = path.join(repoDir, 'examples', 'lab', name, 'grading');
        let exists = true;
        try {
            readFileSync(path.join(dir, 'grading.json'));
        } catch {
            exists = false;
        }
        if (!exists) return; // the exercise has no grading folder (yet)
        await expect(loadGradingSpec(dir)).resolves.toMatchObject({ format: 'maa-grading/1' });
    });

    test('a missing grading.json names the file', async () => {
        const dir = folder({ 'README.md': 'x' });
        await expect(loadGradingSpec(dir)).rejects.toThrow(
            new RegExp(`${dir}/grading.json: cannot read the grading specification \\(ENOENT\\)`),
        );
    });

    test('a file that is no JSON names the file and the parser error', async () => {
        const dir = folder({ 'grading.json': '{ "format": ' });
        await expect(loadGradingSpec(dir)).rejects.toThrow(/grading\.json: not JSON: /);
    });

    test('a bad field is named by its JSON pointer', async () => {
        const criteria = valid.criteria.map((c) => (c['kind'] === 'coverage' ? { ...c, states: 2 } : c));
        const dir = folder({ 'grading.json': JSON.stringify({ ...valid, criteria }), 'Controller.hidden.stream': '' });
        const error = await loadGradingSpec(dir).catch((e: unknown) => e);
        expect(error).toBeInstanceOf(GradingSpecError);
        expect((error as GradingSpecError).issues).toEqual([
            { pointer: '/criteria/4/states', message: 'states must be a share from 0 to 1' },
        ]);
        expect((error as Error).message).toMatch(
            /grading\.json: not a valid grading specification: \/criteria\/4\/states: states must be a share from 0 to 1$/,
        );
    });

    test('a hidden test file the spec names must exist in the folder', async () => {
        const dir = folder({ 'grading.json': JSON.stringify(valid) });
        await expect(loadGradingSpec(dir)).rejects.toThrow(
            /\/criteria\/2\/files\/0: Controller\.hidden\.stream does not exist in the grading folder/,
        );
    });
});
