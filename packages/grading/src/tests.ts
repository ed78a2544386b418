/**
 * The tests criterion: the hidden stream tests' results (the runner's `--json` on the task's
 * stdout), score = passed / total, one sentence per failed test naming its problems and the state
 * the automaton under test ended in.
 */
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import type { StreamTestResult } from '@maa/generators-python';
import type { CriterionGrade, Feedback, FeedbackElement, TestsCriterion } from '@maa/protocol/grading';
import { automatonFacts, componentView } from './component.js';
import { criterionGrade, plural } from './feedback.js';
import { elementOf, type SubmissionModel } from './model.js';
import { lastLines, type TaskOutput } from './outputs.js';

/** The declaration of a component's automaton state (qualified component name, state path), for a link in feedback. */
export type StateLink = (component: string, state: string) => FeedbackElement | undefined;

/** Links a component's automaton state to its declaration in the submission's model. */
export function stateLinkOf(model: SubmissionModel): StateLink {
    return (component, state) => {
        const node = model.components.get(component);
        const declared = node ? automatonFacts(componentView(node))?.states.find((s) => s.path === state) : undefined;
        return declared ? elementOf(model, declared.node, `${component}.${state}`) : undefined;
    };
}

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
    link?: StateLink,
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
        feedback.push(failedTest(r, output, link));
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

/** The sentence of a failed test: at which tick it first went wrong, the problems in words, and the automaton's state then. */
function failedTest(r: StreamTestResult, output: TaskOutput | undefined, link: StateLink | undefined): Feedback {
    const all = r.problems.map(explainProblem);
    // the first failed state check stands for the others (each later one usually follows from it)
    const stateChecks = all.filter((e) => e.state);
    const explained = [...stateChecks.slice(0, 1), ...all.filter((e) => !e.state)];
    if (stateChecks.length > 1)
        explained[0] = { ...explained[0]!, text: `${explained[0]!.text} (and ${plural(stateChecks.length - 1, 'later state check')})` };
    const ticks = explained.flatMap((e) => (e.tick === undefined ? [] : [e.tick]));
    const tick = ticks.length > 0 ? Math.min(...ticks) : undefined;
    const traced = output?.states?.tests.find((t) => t.test === r.test && t.line === r.line);
    const trace = traced?.states;
    // the trace holds the state before the first tick and after every tick: at tick k the automaton started in trace[k - 1]
    const state = tick !== undefined ? trace?.[tick - 1] : trace?.at(-1);
    const where = tick !== undefined ? ` at tick ${tick}` : '';
    const element = state && traced ? link?.(traced.component, state) : undefined;
    const named = state ? `state ${state}${element ? ` (${element.file}:${element.line})` : ''}` : '';
    const then = state ? (tick !== undefined ? `; the automaton was in ${named} then` : `; the automaton ended in ${named}`) : '';
    return {
        severity: 'error',
        text: `Hidden test '${r.test}' failed${where}: ${explained.map((e) => e.text).join('; ')}${then}`,
        ...(state ? { state } : {}),
        ...(element ? { element } : {}),
    };
}

/**
 * A problem of the runner in words: `arm: expected NONE Tk LOAD_BREAD Tk; got NONE Tk NONE Tk`
 * becomes `port arm expected LOAD_BREAD, got NONE` at tick 2 (1-based: the time slice of the first
 * item that differs; none when the streams have no ticks); a failed state check becomes
 * `expected state Serving, got Toasting (line 66)`; other problems stay as they are.
 */
export function explainProblem(problem: string): { text: string; tick?: number; state?: true } {
    const state = /^state \(line (\d+)\): expected (.*); got (.*)$/.exec(problem);
    if (state) return { text: `expected state ${state[2]}, got ${state[3]} (line ${state[1]})`, state: true };
    const m = /^([A-Za-z_][A-Za-z0-9_]*): expected (.*); got (.*)$/.exec(problem);
    if (!m) return { text: problem };
    const [, port, expected, got] = m as unknown as [string, string, string, string];
    const want = expected === '(empty)' ? [] : expected.split(' ');
    const have = got === '(empty)' ? [] : got.split(' ');
    let i = 0;
    while (i < want.length && i < have.length && want[i] === have[i]) i++;
    const item = (items: string[]) => {
        const x = items[i];
        return x === undefined ? 'nothing (the stream ended)' : x === 'Tk' ? 'no message' : x;
    };
    const text = `port ${port} expected ${item(want)}, got ${item(have)}`;
    // without ticks (`~=` compares the messages only) there is no time slice to name
    if (!want.includes('Tk') && !have.includes('Tk')) return { text };
    return { text, tick: want.slice(0, i).filter((x) => x === 'Tk').length + 1 };
}
