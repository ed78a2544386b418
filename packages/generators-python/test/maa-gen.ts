// Driving `maa-gen` as users run it, for the tests that generate models and run the result:
// a model root in a temporary folder, `maa-gen test` (python-timesync stream tests) and
// `maa-gen generate`.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll } from 'vitest';
import { runCliInProcess } from '../../cli/test/helpers.js';
import { repoDir, run, venvPython, type RunResult } from './python-env.js';

export const maaGen = path.join(repoDir, 'packages', 'cli', 'bin', 'maa-gen.js');

/** One stream test's outcome in `maa-gen test --format json`. */
export interface StreamResult {
    file: string;
    test: string | null;
    passed: boolean;
    problems: string[];
}

export interface StreamReport {
    results: StreamResult[];
    summary: { passed: number; failed: number };
}

/** An application of `component` for both Python platforms (components, automata, data types). */
export function bothPlatformsApp(component: string, name = 'A'): string {
    return `application ${name} for ${component} {
  platform timesync {
    timesync.Components;
    timesync.AutomataBehavior;
    timesync.DataTypes;
  }
  platform rospython {
    ros2.Components;
    ros2.AutomataBehavior;
    ros2.DataTypes;
  }
}
`;
}

/**
 * A model root in a temporary folder holding `files` (path relative to the root -> text), made
 * before the test file's tests and removed after them. `dir` is valid inside tests.
 */
export function tempModelRoot(prefix: string, files: Readonly<Record<string, string>>): { readonly dir: string } {
    let dir = '';
    beforeAll(() => {
        dir = mkdtempSync(path.join(tmpdir(), `maa-${prefix}-`));
        for (const [rel, text] of Object.entries(files)) {
            mkdirSync(path.dirname(path.join(dir, rel)), { recursive: true });
            writeFileSync(path.join(dir, rel), text);
        }
    });
    afterAll(() => {
        if (dir) rmSync(dir, { recursive: true, force: true });
    });
    return {
        get dir() {
            return dir;
        },
    };
}

/** `maa-gen test <app> --format json` with the package's venv: the report (if it printed one) and the run. */
export async function streamTests(
    app: string,
    cwd: string,
    extra: readonly string[] = [],
): Promise<{ report?: StreamReport; run: RunResult }> {
    const r = await run(process.execPath, [maaGen, 'test', app, '--format', 'json', '--python', venvPython, ...extra], cwd);
    let report: StreamReport | undefined;
    try {
        report = JSON.parse(r.stdout) as StreamReport;
    } catch {
        report = undefined;
    }
    return { ...(report ? { report } : {}), run: r };
}

/** `maa-gen generate <app> --platform <platform> --out <out>`. */
export function generate(app: string, platform: string, out: string, cwd: string): Promise<RunResult> {
    return run(process.execPath, [maaGen, 'generate', app, '--platform', platform, '--out', out], cwd);
}

/**
 * `maa-gen <args>` in a warm worker thread of the test process (the CLI tests' runCliInProcess):
 * the language services load once per test file instead of once per command (a second or two of
 * CPU each). For tests of what a command does; its exit code is what the bin would exit with.
 */
export async function maaGenInProcess(args: readonly string[], cwd: string): Promise<RunResult> {
    const r = await runCliInProcess([...args], cwd);
    return { status: r.code ?? 1, stdout: r.stdout, stderr: r.stderr };
}
