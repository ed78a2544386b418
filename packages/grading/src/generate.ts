/**
 * Generating a submission's `timesync` platform with the generator core, as `maa-gen generate
 * --platform timesync` does (the CLI's runGenerator wraps the same call): the build the hidden
 * tests and the scenarios run.
 */
import path from 'node:path';
import { fileURLToPath } from 'node:url';
/** The outcome of the generator core's generate (a type only: the module is loaded on demand). */
type GenerateResult = Awaited<ReturnType<typeof import('@maa/generator-core/node').generate>>;

export const PLATFORM = 'timesync';

/** The folder of this package: the generators installed beside it (@maa/generators-python) are discovered from here. */
function installationDir(): string {
    return path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
}

export interface Generated {
    readonly ok: boolean;
    /** `<outDir>/timesync` when generated. */
    readonly build: string;
    /** The errors that stopped generation, as `file:line: message` relative to the model root. */
    readonly errors: readonly string[];
}

/** Generates the `timesync` platform of the submission's application into `<outDir>/timesync`. */
export async function generateTimesync(modelRoot: string, appFile: string, outDir: string): Promise<Generated> {
    const [{ createMaaServices }, { generate, GenerateInputError }, { NodeFileSystem }] = await Promise.all([
        import('@maa/language-server'),
        import('@maa/generator-core/node'),
        import('langium/node'),
    ]);
    let result: GenerateResult;
    try {
        result = await generate({
            services: createMaaServices(NodeFileSystem),
            appFile,
            modelRoot,
            platforms: [PLATFORM],
            outDir,
            discoveryRoots: [installationDir()],
        });
    } catch (e) {
        if (e instanceof GenerateInputError) return { ok: false, build: path.join(outDir, PLATFORM), errors: [e.message] };
        throw e;
    }
    const errors = result.diagnostics
        .filter((d) => d.severity === 'error')
        .map((d) => `${d.file ? `${path.relative(modelRoot, d.file).split(path.sep).join('/')}:${d.line}: ` : ''}${d.message}`);
    return { ok: result.ok, build: path.join(outDir, PLATFORM), errors };
}
