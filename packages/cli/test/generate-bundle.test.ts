// The generation path of `maa-gen generate` (src/generate-loader.ts): the bundle the build writes
// (scripts/bundle-generate.mjs) with the resolution hooks that give generators loaded at run time
// the bundle's modules (src/generate-hooks.ts), or the packages themselves (MAA_GEN_NO_BUNDLE=1).
import { execFile } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterEach, describe, expect, it } from 'vitest';
import { bundleIsCurrent } from '../src/check-loader.js';
import { initialize, resolve } from '../src/generate-hooks.js';

const BIN = fileURLToPath(new URL('../bin/maa-gen.js', import.meta.url));
const BUNDLE = new URL('../dist/generate-bundle/', import.meta.url);
const REPO_MAA = fileURLToPath(new URL('../../../node_modules/@maa', import.meta.url));

describe('the resolution hooks', () => {
    type Next = Parameters<typeof resolve>[2];
    const next = (url: string): Next => (async () => ({ url, format: 'module' })) as unknown as Next;

    it('send an import that resolves to a bundled package entry to the bundle', async () => {
        initialize({ redirects: { 'file:///pkg/dist/index.js': 'file:///cli/dist/generate-bundle/pkg.js' } });
        expect(await resolve('pkg', { conditions: [], importAttributes: {} }, next('file:///pkg/dist/index.js'))).toEqual({
            url: 'file:///cli/dist/generate-bundle/pkg.js',
            format: 'module',
            shortCircuit: true,
        });
    });

    it('leave every other import as Node resolves it (another file of the package, another copy of it)', async () => {
        initialize({ redirects: { 'file:///pkg/dist/index.js': 'file:///cli/dist/generate-bundle/pkg.js' } });
        for (const url of ['file:///pkg/dist/other.js', 'file:///elsewhere/node_modules/pkg/dist/index.js']) {
            expect(await resolve('pkg', { conditions: [], importAttributes: {} }, next(url))).toEqual({ url, format: 'module' });
        }
    });
});

const MODELS: Record<string, string> = {
    // A feature: the application's feature configuration is module state of @maa/language-adl.
    'models/robot/Robot.arc':
        'package robot;\n\ncomponent Robot {\n  feature fast;\n  port in int distance;\n  Inner inner;\n  distance -> inner.value;\n}\n',
    'models/robot/Inner.arc': 'package robot;\n\n<<handwritten>> component Inner {\n  port in int value;\n}\n',
    'models/App.arcapp':
        'application Demo for robot.Robot(fast = true) {\n  platform alpha {\n    s.Components;\n    s.DataTypes;\n  }\n}\n',
    'models/node_modules/s-gens/package.json': JSON.stringify({
        name: 's-gens',
        version: '1.0.0',
        type: 'module',
        maa: {
            generators: [
                {
                    name: 's.Components',
                    kind: 'component',
                    supports: ['compute'],
                    output: { gpl: 'python', rte: 's-rte' },
                    entry: 'components.js',
                },
                { name: 's.DataTypes', kind: 'datatype', output: { gpl: 'python' }, entry: 'datatypes.js' },
            ],
        },
    }),
    'models/node_modules/s-gens/datatypes.js': 'export default { kind: "datatype", generate() {} };\n',
    // A generator that imports the packages it shares with maa-gen: the language package's feature
    // configuration (module state the pipeline sets) and generator-core's classes must be maa-gen's own.
    'models/node_modules/s-gens/components.js': [
        "import { currentVariant } from '@maa/language-adl';",
        "import { GenerationError } from '@maa/generator-core/node';",
        'export default () => ({ kind: "component", generate(ctx) {',
        '  const f = ctx.out.file("modules.txt");',
        '  f.line("feature configuration of the generation: " + (currentVariant() === undefined ? "not seen" : "seen"));',
        '  f.line("components: " + ctx.architecture.components.map((c) => c.name).join(", "));',
        '  if (process.env.S_GENS_FAIL) throw new GenerationError("refused by s.Components", ctx.architecture.components[0].node);',
        '} });',
        '',
    ].join('\n'),
};

function run(args: string[], cwd: string, env: Record<string, string>): Promise<{ code: number; stdout: string; stderr: string }> {
    return new Promise((done, fail) => {
        execFile(process.execPath, [BIN, ...args], { cwd, env: { ...process.env, NO_COLOR: '1', ...env } }, (error, stdout, stderr) => {
            if (error && typeof error.code !== 'number') fail(error);
            else done({ code: error ? (error.code as number) : 0, stdout, stderr });
        });
    });
}

// Only where the build's bundle is current (a language package rebuilt without @maa/cli makes
// maa-gen fall back to the packages, which the second run below covers).
describe.skipIf(!bundleIsCurrent(new URL('modules.json', BUNDLE), new URL('inputs.json', BUNDLE)))(
    'maa-gen generate with the bundle',
    () => {
        let dir: string | undefined;
        afterEach(() => {
            if (dir) rmSync(dir, { recursive: true, force: true });
            dir = undefined;
        });

        function project(): string {
            dir = mkdtempSync(path.join(tmpdir(), 'maa-gen-bundle-'));
            for (const [rel, text] of Object.entries(MODELS)) {
                mkdirSync(path.dirname(path.join(dir, rel)), { recursive: true });
                writeFileSync(path.join(dir, rel), text);
            }
            // The workspace's packages, as an installed generator finds them next to maa-gen.
            symlinkSync(REPO_MAA, path.join(dir, 'models', 'node_modules', '@maa'));
            return dir;
        }

        it("gives a generator's imports maa-gen's modules, and the same output as without the bundle", async () => {
            const root = project();
            const bundled = await run(['generate', 'models/App.arcapp', '--out', 'bundled'], root, {});
            const unbundled = await run(['generate', 'models/App.arcapp', '--out', 'unbundled'], root, { MAA_GEN_NO_BUNDLE: '1' });
            expect(bundled.stderr).not.toMatch(/internal error/);
            expect(bundled.code).toBe(0);
            expect(unbundled.code).toBe(0);
            const output = (out: string): string => readFileSync(path.join(root, out, 'alpha', 'modules.txt'), 'utf8');
            expect(output('bundled')).toBe('feature configuration of the generation: seen\ncomponents: Inner, Robot\n');
            expect(output('bundled')).toBe(output('unbundled'));
        });

        it("reports a generator's GenerationError at its model element (a generator error, not an internal one)", async () => {
            const root = project();
            const bundled = await run(['generate', 'models/App.arcapp', '--format', 'json'], root, { S_GENS_FAIL: '1' });
            expect(bundled.code).toBe(1);
            const errors = (JSON.parse(bundled.stdout) as { diagnostics: Array<{ severity: string }> }).diagnostics.filter(
                (d) => d.severity === 'error',
            );
            expect(errors).toEqual([
                expect.objectContaining({
                    code: 'gen/generator-failed',
                    file: path.join(root, 'models', 'robot', 'Inner.arc'),
                    message: expect.stringContaining('refused by s.Components'),
                }),
            ]);
        });
    },
);
