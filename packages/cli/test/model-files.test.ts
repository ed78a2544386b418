// maa-gen's model files are the family's file languages (from the language facts): every
// language's extension is discovered, `.arcapp` included.
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import { isModelFile, MODEL_FILE_EXTENSIONS } from '../src/roots.js';
import { listModelFiles } from '../src/summary.js';
import { ModelDir, requireBuiltCli, runCliInProcess } from './helpers.js';

const APP = 'application App for Sys {\n  platform timesync {\n    timesync.Components;\n    timesync.DataTypes;\n  }\n}\n';
const SYS = 'component Sys {\n  port in int a;\n  port out int b;\n}\n';

let dirs: ModelDir[] = [];
const models = (): ModelDir => {
    const m = new ModelDir();
    dirs.push(m);
    return m;
};
afterEach(() => {
    for (const d of dirs) d.dispose();
    dirs = [];
});

describe('model file extensions from the language facts', () => {
    it('recognises the extensions of every file language of the family', () => {
        const expected = LANGUAGE_FACTS.languages.filter((l) => l.kind === 'file').flatMap((l) => l.fileExtensions);
        expect([...MODEL_FILE_EXTENSIONS].sort()).toEqual([...new Set(expected)].sort());
        expect(MODEL_FILE_EXTENSIONS).toEqual(expect.arrayContaining(['.arc', '.arcapp', '.cd', '.ra']));
        for (const ext of expected) expect(isModelFile(`models/x/Some${ext}`), ext).toBe(true);
        expect(isModelFile('toast/Controller.stream')).toBe(false);
    });

    it('counts .arcapp files of a folder as model files', () => {
        const m = models();
        m.write('Sys.arc', SYS);
        m.write('App.arcapp', APP);
        m.write('notes.txt', 'hello');
        expect(
            listModelFiles(m.dir)
                .map((f) => f.slice(m.dir.length + 1))
                .sort(),
        ).toEqual(['App.arcapp', 'Sys.arc']);
    });
});

describe('maa-gen check with .arcapp files', () => {
    beforeAll(() => requireBuiltCli());

    it('checks an .arcapp file argument in its folder (the default --root of generate)', async () => {
        const m = models();
        m.write('Sys.arc', SYS);
        m.write('App.arcapp', APP);
        const ok = await runCliInProcess(['check', '-f', 'json', 'App.arcapp'], m.dir);
        expect(ok.stderr).toBe('');
        expect(ok.code).toBe(0);
        expect(JSON.parse(ok.stdout)).toEqual({ diagnostics: [], summary: { errors: 0, warnings: 0, infos: 0, files: 1, roots: 1 } });

        m.write('Bad.arcapp', 'application Bad for NoSuchComponent {\n  platform timesync {\n    timesync.Components;\n  }\n}\n');
        const bad = await runCliInProcess(['check', '-f', 'json', 'Bad.arcapp'], m.dir);
        expect(bad.code).toBe(1);
        const report = JSON.parse(bad.stdout) as { diagnostics: Array<{ file: string; severity: string }> };
        expect(report.diagnostics.length).toBeGreaterThan(0);
        for (const d of report.diagnostics) expect(d.file).toBe(m.path('Bad.arcapp'));
    });

    it('counts the .arcapp files of a folder argument in the summary', async () => {
        const m = models();
        m.write('Sys.arc', SYS);
        m.write('App.arcapp', APP);
        const r = await runCliInProcess(['check', '-f', 'json', '.'], m.dir);
        expect(r.code).toBe(0);
        expect(JSON.parse(r.stdout)).toMatchObject({ summary: { files: 2, roots: 1 } });
    });
});
