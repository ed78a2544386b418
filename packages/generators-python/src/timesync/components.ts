import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import type { ComponentGenerationContext, ComponentGeneratorFactory } from '@maa/generator-core';
import { writeAppModule } from './app-module.js';
import { writeComponentModule } from './component-module.js';
import { writeLockstep } from './lockstep.js';

export { componentModule } from './component-module.js';

/** timesync.Components: the hierarchy in one process (maa_timesync), compute blocks, handwritten stubs, entry points. */
const create: ComponentGeneratorFactory = ({ packageDir }) => ({
    kind: 'component',
    async generate(ctx) {
        for (const c of ctx.architecture.components) await writeComponentModule(ctx, c);
        writeRuntimes(ctx, packageDir);
        writeAppModule(ctx);
        writeLockstep(ctx);
    },
});

export default create;

/** The run-time environments, copied so that the build runs with Python alone. */
function writeRuntimes(ctx: ComponentGenerationContext, packageDir: string): void {
    for (const rte of ['maa_behavior', 'maa_timesync']) {
        for (const { file, text } of rteFiles(packageDir, rte)) ctx.out.file(file).write(text);
    }
}

/** Reads the files of an RTE package shipped in `rte/<name>/`. */
function rteFiles(packageDir: string, name: string): Array<{ file: string; text: string }> {
    const dir = path.join(packageDir, 'rte', name);
    return readdirSync(dir)
        .filter((f) => f.endsWith('.py') || f === 'py.typed')
        .sort()
        .map((f) => ({ file: `${name}/${f}`, text: readFileSync(path.join(dir, f), 'utf8') }));
}
