// maa-gen decides model roots by the one rule of resolveModelRoot (docs/user-guide.md "Model
// roots"): the default --root of generate and test is the nearest folder with a maa.json above the
// .arcapp, as in the IDE (packages/ide-server/test/model-root.test.ts has the same layout).
import { existsSync } from 'node:fs';
import path from 'node:path';
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import { modelRootOfFile, modelRootOfApp } from '../src/roots.js';
import { ModelDir, requireBuiltCli, runCliInProcess } from './helpers.js';

const APP = 'application A for robot.Ctrl {\n  platform timesync {\n    timesync.Components;\n    timesync.DataTypes;\n  }\n}\n';
const CTRL = 'package robot;\n\ncomponent Ctrl {\n  port in int a;\n  port out int b;\n}\n';

let dirs: ModelDir[] = [];
afterEach(() => {
    for (const d of dirs) d.dispose();
    dirs = [];
});
/** proj/maa.json, proj/apps/A.arcapp, proj/robot/Ctrl.arc. */
const project = (): ModelDir => {
    const m = new ModelDir();
    dirs.push(m);
    m.write('proj/maa.json', '{}\n');
    m.write('proj/apps/A.arcapp', APP);
    m.write('proj/robot/Ctrl.arc', CTRL);
    return m;
};

describe('model roots of maa-gen', () => {
    beforeAll(() => requireBuiltCli());

    it('takes the maa.json folder above an app (and above a file of a package) as its root', () => {
        const m = project();
        expect(modelRootOfApp(m.path('proj/apps/A.arcapp'))).toBe(m.path('proj'));
        expect(modelRootOfFile(m.path('proj/robot/Ctrl.arc'), CTRL)).toBe(m.path('proj'));
        // A maa.json wins over the package rule: proj/models/robot/Ctrl.arc declaring `package robot;`.
        expect(modelRootOfFile(m.path('proj/models/robot/Ctrl.arc'), CTRL)).toBe(m.path('proj'));
    });

    it('generate without --root resolves the app in the maa.json folder; --root still overrides', async () => {
        const m = project();
        const ok = await runCliInProcess(['generate', 'proj/apps/A.arcapp', '-p', 'timesync', '-o', 'out'], m.dir);
        expect(ok.stderr).toContain('0 errors');
        expect(ok.code).toBe(0);
        expect(existsSync(m.path(path.join('out', 'timesync')))).toBe(true);

        const explicit = await runCliInProcess(
            ['generate', 'proj/apps/A.arcapp', '-p', 'timesync', '-o', 'out2', '--root', 'proj/apps'],
            m.dir,
        );
        expect(explicit.code).toBe(1);
        expect(explicit.stdout).toContain('app/unknown-component');
    });

    it('check of the app file checks it within the same root', async () => {
        const m = project();
        const r = await runCliInProcess(['check', '-f', 'json', 'proj/apps/A.arcapp'], m.dir);
        expect(r.code).toBe(0);
        expect(JSON.parse(r.stdout)).toMatchObject({ diagnostics: [], summary: { errors: 0, files: 1, roots: 1 } });
    });
});
