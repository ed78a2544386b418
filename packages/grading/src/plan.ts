/**
 * Task planning: for a generated submission, the task input folders (a copy of the build, the
 * hidden tests or the scenario's world) and the grade job's tasks: one task running every hidden
 * stream test, one task per scenario (grading-design.md, "Grade job").
 */
import { cp, mkdir, writeFile } from 'node:fs/promises';
import path from 'node:path';
import type { GradeJobTask, GradingSpec, Scenario, TaskLimits } from '@maa/protocol/grading';

/** The limits of a task when the specification gives none. */
export const DEFAULT_LIMITS: Readonly<Record<'tests' | 'scenarios', TaskLimits>> = {
    tests: { wallSeconds: 120, cpuSeconds: 100, memoryMB: 2048, processes: 64, fileSizeMB: 64 },
    scenarios: { wallSeconds: 600, cpuSeconds: 540, memoryMB: 3072, processes: 64, fileSizeMB: 512 },
};

/** What a planned task is for, so its outputs can be read back. */
export type PlannedTask =
    | { readonly kind: 'tests'; readonly task: GradeJobTask; readonly files: readonly string[] }
    | { readonly kind: 'scenario'; readonly task: GradeJobTask; readonly criterion: string; readonly scenario: Scenario };

/** The id of the hidden-tests task and of a scenario's task of a submission. */
export const testsTaskId = (key: string): string => `${key}.tests`;
export const scenarioTaskId = (key: string, scenario: string): string => `${key}.scenario.${scenario}`;

/** A submission id as a task id prefix: letters, digits, `.`, `_`, `-` (others become `_`), never empty or starting with a sign. */
export function taskKey(id: string): string {
    const cleaned = id.replace(/[^A-Za-z0-9._-]/g, '_');
    return /^[A-Za-z0-9]/.test(cleaned) ? cleaned : `s${cleaned}`;
}

function limitsOf(spec: GradingSpec, kind: 'tests' | 'scenarios', own: Partial<TaskLimits> | undefined): TaskLimits {
    return { ...DEFAULT_LIMITS[kind], ...spec.limits, ...own };
}

/** Every hidden stream file of the specification (relative to the grading folder), each once. */
export function hiddenTestFiles(spec: GradingSpec): string[] {
    const files = new Set<string>();
    for (const c of spec.criteria) if (c.kind === 'tests') for (const f of c.files) files.add(f);
    return [...files];
}

export interface PlanInput {
    readonly spec: GradingSpec;
    readonly gradingDir: string;
    /** The submission's task id prefix ({@link taskKey}). */
    readonly key: string;
    /** The generated timesync build (`<out>/timesync`, a link to a version folder). */
    readonly build: string;
    /** Where the task input folders go. */
    readonly inputsDir: string;
}

/** Writes the input folders of a submission's tasks and returns the tasks. */
export async function planTasks(input: PlanInput): Promise<PlannedTask[]> {
    const { spec, key } = input;
    const planned: PlannedTask[] = [];
    const files = hiddenTestFiles(spec);
    if (files.length > 0) {
        const id = testsTaskId(key);
        const dir = await taskInput(input, id);
        for (const f of files) {
            await mkdir(path.dirname(path.join(dir, 'tests', f)), { recursive: true });
            await cp(path.join(input.gradingDir, f), path.join(dir, 'tests', f));
        }
        const testsCriterion = spec.criteria.find((c) => c.kind === 'tests');
        const argv = ['{python}', '-m', 'maa_timesync.streamtest', '{input}/build/timesync', '--json', '--states', '{output}/states.json'];
        argv.push(...files.map((f) => `{input}/tests/${f}`));
        planned.push({
            kind: 'tests',
            files,
            task: {
                id,
                input: dir,
                argv,
                limits: limitsOf(spec, 'tests', testsCriterion?.kind === 'tests' ? testsCriterion.limits : undefined),
                env: timesyncEnv(),
            },
        });
    }
    for (const criterion of spec.criteria) {
        if (criterion.kind !== 'scenarios') continue;
        for (const scenario of criterion.scenarios) {
            const id = scenarioTaskId(key, scenario.id);
            const dir = await taskInput(input, id);
            await writeFile(path.join(dir, 'world.json'), `${JSON.stringify(scenario.world, null, 2)}\n`);
            planned.push({
                kind: 'scenario',
                criterion: criterion.id,
                scenario,
                task: {
                    id,
                    input: dir,
                    argv: scenarioArgv(scenario),
                    limits: limitsOf(spec, 'scenarios', criterion.limits),
                    env: timesyncEnv(),
                },
            });
        }
    }
    return planned;
}

/** A task's input folder with its own copy of the build (links resolved, so it travels as plain files). */
async function taskInput(input: PlanInput, id: string): Promise<string> {
    const dir = path.join(input.inputsDir, id);
    await mkdir(dir, { recursive: true });
    await cp(input.build, path.join(dir, 'build', 'timesync'), { recursive: true, dereference: true });
    return dir;
}

/** The generated build's run-time packages (maa_timesync, maa_behavior) and modules are importable from anywhere. */
function timesyncEnv(): Record<string, string> {
    return { PYTHONPATH: '{input}/build/timesync', PYTHONDONTWRITEBYTECODE: '1' };
}

/** `maa-sim run` of a scenario: headless, lock-step, as fast as possible, until the goal or the time limit; a recording and a report. */
export function scenarioArgv(scenario: Scenario): string[] {
    return [
        '{python}',
        '-m',
        'maa_sim.cli',
        'run',
        '--package',
        '{input}/build/timesync',
        '--mode',
        'lockstep',
        '--speed',
        '0',
        '--world',
        '{input}/world.json',
        '--until-goal',
        '--max-time',
        String(scenario.timeLimit),
        '--rosbridge-port',
        'off',
        '--viser-port',
        'off',
        '--record',
        '{output}/recording.mcap',
        '--report',
        '{output}/report.json',
    ];
}
