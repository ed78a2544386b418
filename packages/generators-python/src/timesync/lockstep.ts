/**
 * `lockstep.json` of a python-timesync build (the contract `Lockstep` of `@maa/protocol`,
 * docs/simulation.md "Lock-step mode"): how `maa-sim` loads the build into its own process.
 */
import { LOCKSTEP_FILE_NAME, LOCKSTEP_FORMAT, type Lockstep } from '@maa/protocol';
import type { ComponentGenerationContext } from '@maa/generator-core';
import { APP_MODULE } from './app-module.js';

/** The lock-step interface: the app module's controller factory, one period of 20 ms, no parameters. */
export function lockstepOf(): Lockstep {
    return {
        format: LOCKSTEP_FORMAT,
        factory: `${APP_MODULE}:create_controller`,
        python_path: ['.'],
        period: 0.02,
        parameters: {},
    };
}

export function writeLockstep(ctx: ComponentGenerationContext): void {
    ctx.out.file(LOCKSTEP_FILE_NAME).write(`${JSON.stringify(lockstepOf(), null, 2)}\n`);
}
