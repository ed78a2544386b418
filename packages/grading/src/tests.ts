/**
 * The tests criterion: the hidden stream tests' results (the runner's `--json` on the task's
 * stdout), score = passed / total, one sentence per failed test naming its problems and the state
 * the automaton under test ended in.
 */
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import type { StreamTestResult } from '@maa/generators-python';
import type { CriterionGrade, Feedback, TestsCriterion } from '@maa/protocol/grading';
import { criterionGrade, plural } from './feedback.js';
import { lastLines, type TaskOutput } from './outputs.js';

/** How many tests a stream file declares (`test "name" {`). */
export async function declaredTests(file: string): Promise<number> {
    try {
        return (await readFile(file, 'utf8')).match(/^\s*test\s+"/gm)?.length ?? 0;
    } catch {
        return 0;
    }
}

/** The hidden file (relative to the grading folder) a result of the runner is of: the path after `/tests/`. */
export function hiddenFileOf(resultFile: string, files: readonly string[]): string | undefined {
    const posix = resultFile.split(path.sep).join('/');
    return files.find((f) => posix === f || posix.endsWith(`/tests/${f}`));
}

export function parseResults(stdout: string): StreamTestResult[] | undefined {
    try {
        const value: unknown = JSON.parse(stdout);
        return Array.isArray(value) ? (value as StreamTestResult[]) : undefined;
    } catch {
        return undefined;
    }
}

export async function gradeTests(
    criterion: TestsCriterion,
    gradingDir: string,
    output: TaskOutput | undefined,
    notRun?: string,
): Promise<CriterionGrade> {
    let total = 0;
    for (const f of criterion.files) total += await declaredTests(path.join(gradingDir, f));
    const results = output ? parseResults(output.stdout) : undefined;
    if (notRun || !results) {
        const why = notRun ?? taskFailure(output);
        return criterionGrade(criterion, 0, [{ severity: 'error', text: `The hidden tests did not run: ${why}` }]);
    }
    const mine = results.filter((r) => hiddenFileOf(r.file, criterion.files) !== undefined);
    const ran = mine.filter((r) => r.test !== null);
    total = Math.max(total, ran.length);
    const passed = ran.filter((r) => r.passed).length;
    const feedback: Feedback[] = [];
    for (const r of mine) {
        if (r.passed) continue;
        const file = hiddenFileOf(r.file, criterion.files) ?? r.file;
        if (r.test === null) {
            feedback.push({ severity: 'error', text: `The hidden tests of ${file} did not run: ${r.problems.join('; ')}` });
            continue;
        }
        const state = endState(output, r);
        const problems = r.problems.join('; ');
        feedback.push({
            severity: 'error',
            text: `Hidden test '${r.test}' failed: ${problems}${state ? `; the automaton ended in state ${state}` : ''}`,
            ...(state ? { state } : {}),
        });
    }
    feedback.unshift({ severity: passed === total ? 'info' : 'error', text: `${passed} of ${plural(total, 'hidden test')} passed.` });
    return criterionGrade(criterion, total === 0 ? 0 : passed / total, feedback);
}

/** Why a task gave no results: the driver's message and the end of stderr. */
export function taskFailure(output: TaskOutput | undefined): string {
    if (!output?.result) return 'the task did not run (no result from the grading driver)';
    const tail = lastLines(output.stderr);
    return `${output.result.message}${tail ? ` (${tail})` : ''}`;
}

/** The last state of the automaton under a test, from the state traces. */
function endState(output: TaskOutput | undefined, r: StreamTestResult): string | undefined {
    const trace = output?.states?.tests.find((t) => t.test === r.test && t.line === r.line);
    return trace?.states.at(-1);
}
