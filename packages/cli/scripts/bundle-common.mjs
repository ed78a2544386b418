// What the two bundles of @maa/cli (bundle-check.mjs, bundle-generate.mjs) build alike: esbuild
// when installed, the options of an ES module bundle for Node, and the list of workspace modules
// inside a bundle that its loader compares with their rebuilt files (src/check-loader.ts).
import path from 'node:path';

/** esbuild's build(), or exit 0 with a warning without it (a devDependency: the bundles are an optimization). */
export async function esbuildOrSkip(script, fallback) {
    try {
        return (await import('esbuild')).build;
    } catch {
        console.warn(`${script}: esbuild is not installed; ${fallback}`);
        process.exit(0);
    }
}

/** The options both bundles share: ES modules for Node 20, with a metafile. */
export const NODE_ESM = {
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    metafile: true,
    legalComments: 'none',
    logLevel: 'warning',
    // Some dependencies are CommonJS and call require(): give each ES module of a bundle one.
    banner: {
        js: "import { createRequire as __maaCreateRequire } from 'node:module';\nconst require = __maaCreateRequire(import.meta.url);",
    },
};

/**
 * The workspace modules inside a bundle (not those of node_modules, nor `skip`), relative to
 * `dir`, sorted: a bundle older than one of them is not used.
 */
export function workspaceInputs(metafile, packageDir, dir, skip = []) {
    return Object.keys(metafile.inputs)
        .filter((input) => !skip.includes(input) && !input.split(/[\\/]/).includes('node_modules'))
        .map((input) => path.relative(dir, path.resolve(packageDir, input)).split(path.sep).join('/'))
        .sort();
}
