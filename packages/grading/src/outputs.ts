/** Reading a task's outputs from the driver's output folder (`OUTDIR/<task>/`): result, stdout/stderr tails, report, state traces, recording. */
import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import {
    type DriverTask,
    driverLineContract,
    type ScenarioReport,
    type StreamStates,
    scenarioReportContract,
    streamStatesContract,
} from '@maa/protocol/grading';

export interface TaskOutput {
    /** The driver's line for the task (from the run, else `result.json`); undefined when the task never ran. */
    readonly result: DriverTask | undefined;
    readonly stdout: string;
    readonly stderr: string;
    /** `report.json` of a scenario run, when written and valid. */
    readonly report: ScenarioReport | undefined;
    /** `states.json` of the stream tests, when written and valid. */
    readonly states: StreamStates | undefined;
    /** `recording.mcap` (absolute) when written. */
    readonly recording: string | undefined;
}

async function text(file: string): Promise<string | undefined> {
    try {
        return await readFile(file, 'utf8');
    } catch {
        return undefined;
    }
}

async function json(file: string): Promise<unknown> {
    const t = await text(file);
    if (t === undefined) return undefined;
    try {
        return JSON.parse(t) as unknown;
    } catch {
        return undefined;
    }
}

async function isFile(file: string): Promise<boolean> {
    return stat(file).then(
        (s) => s.isFile() && s.size > 0,
        () => false,
    );
}

export async function readTaskOutput(outDir: string, id: string, fromRun: DriverTask | undefined): Promise<TaskOutput> {
    const dir = path.join(outDir, id);
    const stored = await json(path.join(dir, 'result.json'));
    const storedLine = driverLineContract.check(stored) && stored.event === 'task' ? stored : undefined;
    const report = await json(path.join(dir, 'report.json'));
    const states = await json(path.join(dir, 'states.json'));
    const recording = path.join(dir, 'recording.mcap');
    return {
        result: fromRun ?? storedLine,
        stdout: (await text(path.join(dir, 'stdout.txt'))) ?? '',
        stderr: (await text(path.join(dir, 'stderr.txt'))) ?? '',
        report: scenarioReportContract.check(report) ? report : undefined,
        states: streamStatesContract.check(states) ? states : undefined,
        recording: (await isFile(recording)) ? recording : undefined,
    };
}

/** The last non-empty lines of a tail (for feedback on a crashed run). */
export function lastLines(tail: string, n = 3): string {
    return tail
        .split('\n')
        .map((l) => l.trimEnd())
        .filter((l) => l.length > 0)
        .slice(-n)
        .join(' | ');
}
