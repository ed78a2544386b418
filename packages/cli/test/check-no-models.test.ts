// `maa-gen check` on a folder without a model file: a wrong path said plainly, exit 2.
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import { ModelDir, requireBuiltCli, runCliInProcess } from './helpers.js';

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

describe('maa-gen check on a folder without models', () => {
    it('says "no models found in <dir>" and exits 2', async () => {
        const d = tempDir();
        d.write('empty/README.md', '# not a model\n');
        d.write('empty/.hidden/A.arc', 'package x; component A {}\n');
        const r = await runCliInProcess(['check', 'empty'], d.dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('maa-gen: error: no models found in empty (no .arc, .arcapp, .cd, .ra files below it)');
        expect(r.stdout).toBe('');
    });

    it('names the current folder "."', async () => {
        const d = tempDir();
        const r = await runCliInProcess(['check', '.'], d.dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('no models found in . (');
    });

    it('names each empty folder among several, and checks nothing', async () => {
        const d = tempDir();
        d.write('models/a/A.arc', 'package a;\ncomponent A {}\n');
        d.write('none/notes.txt', 'nothing\n');
        d.write('other/x/y.txt', 'nothing\n');
        const r = await runCliInProcess(['check', 'models/a', 'none', 'other'], d.dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('no models found in none');
        expect(r.stderr).toContain('no models found in other');
        expect(r.stderr).not.toContain('models/a');
    });

    it('a folder with a model below it is checked as before', async () => {
        const d = tempDir();
        d.write('models/a/A.arc', 'package a;\ncomponent A {}\n');
        const r = await runCliInProcess(['check', 'models'], d.dir);
        expect(r.code).toBe(0);
        expect(r.stderr).toContain('0 errors, 0 warnings in 1 file');
    });
});
