import { readFileSync, statSync } from 'node:fs';

/** What `maa-gen check` needs of the language services. */
export interface Checker {
    checkModelRoots: typeof import('@maa/language-server').checkModelRoots;
    CheckInputError: typeof import('@maa/language-server').CheckInputError;
}

const BUNDLE = new URL('./check-bundle.js', import.meta.url);
const INPUTS = new URL('./check-bundle.inputs.json', import.meta.url);

/**
 * The checking path of `maa-gen check`: the one-module bundle the build writes
 * (scripts/bundle-check.mjs; it loads several times faster than the ~1,000 modules it holds) when
 * it is there and up to date, else `@maa/language-server` itself. `MAA_GEN_NO_BUNDLE=1` forces
 * the latter. Both give the same diagnostics: the bundle is the same code.
 */
export async function loadChecker(env: NodeJS.ProcessEnv = process.env): Promise<Checker> {
    if (!env['MAA_GEN_NO_BUNDLE'] && bundleIsCurrent()) {
        // A variable specifier: the bundle is a build output, not a module TypeScript resolves.
        const bundle: string = BUNDLE.href;
        return (await import(bundle)) as Checker;
    }
    const { checkModelRoots, CheckInputError } = await import('@maa/language-server');
    return { checkModelRoots, CheckInputError };
}

/**
 * Whether the bundle exists and no workspace module it holds was rebuilt after it (in a
 * published install those paths do not exist or carry the same packing date: it is current).
 */
export function bundleIsCurrent(bundle: URL = BUNDLE, inputsFile: URL = INPUTS): boolean {
    let built: number;
    let inputs: string[];
    try {
        built = statSync(bundle).mtimeMs;
        inputs = (JSON.parse(readFileSync(inputsFile, 'utf8')) as { inputs: string[] }).inputs;
    } catch {
        return false;
    }
    for (const input of inputs) {
        let modified: number;
        try {
            modified = statSync(new URL(input, bundle)).mtimeMs;
        } catch {
            continue;
        }
        if (modified > built) return false;
    }
    return true;
}
