// The IDE backend generates in the model root of resolveModelRoot (docs/user-guide.md "Model
// roots"), the same root maa-gen generate takes by default (packages/cli/test/model-root.test.ts
// has the same layout): proj/maa.json, proj/apps/A.arcapp, proj/robot/Ctrl.arc.
import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterEach, describe, expect, it } from 'vitest';
import type { GenerateAnswer } from '../src/index.js';
import { authFetch, json, q, startSite, type TestSite } from './helpers.js';

const APP = 'application A for robot.Ctrl {\n  platform timesync {\n    timesync.Components;\n    timesync.DataTypes;\n  }\n}\n';
const CTRL = 'package robot;\n\ncomponent Ctrl {\n  port in int a;\n  port out int b;\n}\n';

describe('model root of an application in the IDE backend', () => {
    let site: TestSite | undefined;
    afterEach(async () => {
        await site?.dispose();
        site = undefined;
    });

    it('is the nearest maa.json folder above the app, as for maa-gen generate', async () => {
        site = await startSite({ empty: true });
        const write = (rel: string, text: string) => {
            const file = path.join(site!.workspace, rel);
            mkdirSync(path.dirname(file), { recursive: true });
            writeFileSync(file, text);
        };
        write('proj/maa.json', '{}\n');
        write('proj/apps/A.arcapp', APP);
        write('proj/robot/Ctrl.arc', CTRL);

        const res = await authFetch(site.url('/api/generate'), {
            method: 'POST',
            body: JSON.stringify({ app: 'proj/apps/A.arcapp', platform: 'timesync' }),
            headers: { 'Content-Type': 'application/json' },
        });
        expect(res.status).toBe(200);
        const answer = await json<GenerateAnswer>(res);
        expect(answer.ok, JSON.stringify(answer.diagnostics)).toBe(true);

        // The trace names model files relative to the model root: proj/, not proj/apps/.
        const trace = await json<{ modelRoot?: string; files: Array<{ traces: Array<{ element: { file: string } }> }> }>(
            await authFetch(site.url(`/api/generated/trace?${q({ app: 'proj/apps/A.arcapp', platform: 'timesync' })}`)),
        );
        const files = new Set(trace.files.flatMap((f) => f.traces.map((t) => t.element.file)));
        expect([...files]).toContain('robot/Ctrl.arc');
    });
});
