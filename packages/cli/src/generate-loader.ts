import { readFileSync } from 'node:fs';
import { register } from 'node:module';
import { bundleIsCurrent } from './check-loader.js';
import type { RedirectData } from './generate-hooks.js';

/** What `maa-gen generate` (and test, sim) needs to generate. */
export interface GenerateServices {
    createMaaServices: typeof import('@maa/language-server').createMaaServices;
    generate: typeof import('@maa/generator-core/node').generate;
    GenerateInputError: typeof import('@maa/generator-core/node').GenerateInputError;
    NodeFileSystem: typeof import('langium/node').NodeFileSystem;
}

const BUNDLE_DIR = new URL('./generate-bundle/', import.meta.url);
/** Written last by scripts/bundle-generate.mjs: the entries of the bundle (`modules.json`). */
const MODULES = new URL('modules.json', BUNDLE_DIR);
const INPUTS = new URL('inputs.json', BUNDLE_DIR);

interface BundleModules {
    /** The family's services (createMaaServices). */
    readonly family: string;
    /** Package specifier -> its entry module, relative to the bundle's folder. */
    readonly modules: Readonly<Record<string, string>>;
}

let loading: Promise<GenerateServices> | undefined;

/**
 * The generation path: the bundle the build writes (scripts/bundle-generate.mjs; it loads several
 * times faster than the packages) when it is there and up to date, with the resolution hooks
 * that give generators the bundle's modules (generate-hooks.ts); else the packages themselves.
 * `MAA_GEN_NO_BUNDLE=1` forces the latter. Loaded once per thread: the hooks are registered once,
 * and a process uses one of the two, never both (two copies of the packages).
 */
export function loadGenerateServices(env: NodeJS.ProcessEnv = process.env): Promise<GenerateServices> {
    loading ??= env['MAA_GEN_NO_BUNDLE'] || !bundleIsCurrent(MODULES, INPUTS) ? loadPackages() : loadBundle();
    return loading;
}

async function loadPackages(): Promise<GenerateServices> {
    const [{ createMaaServices }, { generate, GenerateInputError }, { NodeFileSystem }] = await Promise.all([
        import('@maa/language-server'),
        import('@maa/generator-core/node'),
        import('langium/node'),
    ]);
    return { createMaaServices, generate, GenerateInputError, NodeFileSystem };
}

async function loadBundle(): Promise<GenerateServices> {
    const { family, modules } = JSON.parse(readFileSync(MODULES, 'utf8')) as BundleModules;
    const entry = (file: string): string => new URL(file, BUNDLE_DIR).href;
    const redirects: Record<string, string> = {};
    for (const [specifier, file] of Object.entries(modules)) {
        let resolved: string;
        try {
            resolved = import.meta.resolve(specifier);
        } catch {
            continue; // not installed beside maa-gen: a generator importing it has a copy of its own either way
        }
        redirects[resolved] = entry(file);
    }
    const data: RedirectData = { redirects };
    register(new URL('./generate-hooks.js', import.meta.url), { data });
    // Variable specifiers: the bundle is a build output, not modules TypeScript resolves.
    type Family = Pick<GenerateServices, 'createMaaServices'>;
    type Core = Pick<GenerateServices, 'generate' | 'GenerateInputError'>;
    type LangiumNode = Pick<GenerateServices, 'NodeFileSystem'>;
    const [{ createMaaServices }, { generate, GenerateInputError }, { NodeFileSystem }] = await Promise.all([
        import(entry(family)) as Promise<Family>,
        import(entry(modules['@maa/generator-core/node']!)) as Promise<Core>,
        import(entry(modules['langium/node']!)) as Promise<LangiumNode>,
    ]);
    return { createMaaServices, generate, GenerateInputError, NodeFileSystem };
}
