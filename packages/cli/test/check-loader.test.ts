// The checking path of `maa-gen check` (src/check-loader.ts): the one-module bundle the build
// writes is used only while no workspace module it holds was rebuilt after it, and it gives the
// same diagnostics as @maa/language-server itself.
import { mkdirSync, mkdtempSync, rmSync, utimesSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { afterEach, describe, expect, it } from 'vitest';
import { bundleIsCurrent, loadChecker } from '../src/check-loader.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const BUILT_BUNDLE = new URL('../dist/check-bundle.js', import.meta.url);
const BUILT_INPUTS = new URL('../dist/check-bundle.inputs.json', import.meta.url);

describe('bundleIsCurrent', () => {
    let dir: string | undefined;
    afterEach(() => {
        if (dir) rmSync(dir, { recursive: true, force: true });
        dir = undefined;
    });

    /** A bundle in dist/ of a fake package, with one input module in a sibling package; times in seconds since 2000. */
    function layout(bundleTime: number | undefined, inputTime: number | undefined): { bundle: URL; inputs: URL } {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-check-loader-'));
        const dist = path.join(dir, 'cli', 'dist');
        mkdirSync(dist, { recursive: true });
        mkdirSync(path.join(dir, 'lang', 'dist'), { recursive: true });
        const at = (file: string, seconds: number): void => {
            const t = new Date(Date.UTC(2000, 0, 1) + seconds * 1000);
            utimesSync(file, t, t);
        };
        const bundle = path.join(dist, 'check-bundle.js');
        const inputs = path.join(dist, 'check-bundle.inputs.json');
        writeFileSync(inputs, JSON.stringify({ inputs: ['../../lang/dist/index.js', '../../gone/dist/index.js'] }));
        if (bundleTime !== undefined) {
            writeFileSync(bundle, 'export {};\n');
            at(bundle, bundleTime);
        }
        if (inputTime !== undefined) {
            const input = path.join(dir, 'lang', 'dist', 'index.js');
            writeFileSync(input, 'export {};\n');
            at(input, inputTime);
        }
        return { bundle: pathToFileURL(bundle), inputs: pathToFileURL(inputs) };
    }

    it('is false without a bundle', () => {
        const { bundle, inputs } = layout(undefined, 10);
        expect(bundleIsCurrent(bundle, inputs)).toBe(false);
    });

    it('is false when a module it holds was rebuilt after it', () => {
        const { bundle, inputs } = layout(10, 20);
        expect(bundleIsCurrent(bundle, inputs)).toBe(false);
    });

    it('is true when it is at least as new as every module it holds (missing ones, as in an install, do not count)', () => {
        const newer = layout(20, 10);
        expect(bundleIsCurrent(newer.bundle, newer.inputs)).toBe(true);
        rmSync(dir!, { recursive: true, force: true });
        const packed = layout(10, 10);
        expect(bundleIsCurrent(packed.bundle, packed.inputs)).toBe(true);
        rmSync(dir!, { recursive: true, force: true });
        const installed = layout(10, undefined);
        expect(bundleIsCurrent(installed.bundle, installed.inputs)).toBe(true);
    });
});

describe('loadChecker', () => {
    const toast = path.join(repo, 'examples', 'toast-service');
    const broken = (): string => {
        const root = mkdtempSync(path.join(tmpdir(), 'maa-check-loader-model-'));
        writeFileSync(
            path.join(root, 'A.arc'),
            'component A {\n  port in int i;\n  port out boolean o;\n  port out Missing m;\n  i -> o;\n}\n',
        );
        return root;
    };

    it('with MAA_GEN_NO_BUNDLE=1 is @maa/language-server itself', async () => {
        const server = await import('@maa/language-server');
        const checker = await loadChecker({ MAA_GEN_NO_BUNDLE: '1' });
        expect(checker.checkModelRoots).toBe(server.checkModelRoots);
        expect(checker.CheckInputError).toBe(server.CheckInputError);
    });

    it.skipIf(!bundleIsCurrent(BUILT_BUNDLE, BUILT_INPUTS))(
        'the built bundle gives the same diagnostics as the package (a clean example and a broken model)',
        async () => {
            // The built loader (dist/check-loader.js) finds the bundle beside it.
            const built = (await import(
                new URL('../dist/check-loader.js', import.meta.url).href
            )) as typeof import('../src/check-loader.js');
            const bundled = await built.loadChecker({});
            const server = await loadChecker({ MAA_GEN_NO_BUNDLE: '1' });
            expect(bundled.checkModelRoots).not.toBe(server.checkModelRoots);
            const root = broken();
            try {
                for (const r of [toast, root]) {
                    const a = await bundled.checkModelRoots([{ root: r }]);
                    const b = await server.checkModelRoots([{ root: r }]);
                    expect(a).toEqual(b);
                    if (r === root) expect(a.filter((d) => d.severity === 'error').length).toBeGreaterThan(0);
                }
                await expect(bundled.checkModelRoots([{ root: path.join(root, 'nope') }])).rejects.toBeInstanceOf(bundled.CheckInputError);
            } finally {
                rmSync(root, { recursive: true, force: true });
            }
        },
    );
});
