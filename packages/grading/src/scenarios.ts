/**
 * The scenarios criterion: score = scenarios whose goal was reached within the time limit / all;
 * for a failed one, what happened in words: the simulated time, notable events (the toast fell, it
 * burnt), and the state each graded automaton was in, linked to the state's declaration.
 */
import type { CriterionGrade, Feedback, ScenarioReport, ScenariosCriterion } from '@maa/protocol/grading';
import { criterionGrade, plural, seconds } from './feedback.js';
import { type AutomatonInstance, instanceOfNode } from './instances.js';
import { elementOf, type SubmissionModel, where } from './model.js';
import type { TaskOutput } from './outputs.js';
import type { PlannedTask } from './plan.js';
import { taskFailure } from './tests.js';

export interface ScenarioContext {
    readonly model: SubmissionModel;
    readonly instances: readonly AutomatonInstance[];
    /** Qualified names of the components whose state failed-scenario feedback names (all automata when empty). */
    readonly focus: ReadonlySet<string>;
}

const GOALS: Record<string, string> = { toastOnPlate: 'toast on the plate' };
const NOTABLE = new Set(['toast-dropped', 'toast-burnt', 'error']);

export function gradeScenarios(
    criterion: ScenariosCriterion,
    tasks: readonly PlannedTask[],
    outputs: ReadonlyMap<string, TaskOutput>,
    context: ScenarioContext,
    notRun?: string,
): CriterionGrade {
    let reached = 0;
    const feedback: Feedback[] = [];
    for (const scenario of criterion.scenarios) {
        const planned = tasks.find((t) => t.kind === 'scenario' && t.criterion === criterion.id && t.scenario.id === scenario.id);
        const output = planned ? outputs.get(planned.task.id) : undefined;
        const base = { scenario: scenario.id };
        const goal = GOALS[scenario.goal] ?? scenario.goal;
        const report = output?.report;
        if (notRun || !report) {
            feedback.push({
                ...base,
                severity: 'error',
                text: `Scenario '${scenario.title}' did not run to its end: ${notRun ?? taskFailure(output)}`,
            });
            continue;
        }
        if (report.goalReached && report.goalTime !== null && report.goalTime <= scenario.timeLimit) {
            reached++;
            const burnt = report.toast?.color === 'BURNT';
            feedback.push({
                ...base,
                severity: burnt ? 'warning' : 'info',
                simTime: report.goalTime,
                text: `Scenario '${scenario.title}': ${goal} after ${seconds(report.goalTime)} of simulated time${burnt ? ', but the toast is burnt' : ''}.`,
            });
            continue;
        }
        feedback.push(failedScenario(scenario.title, goal, report, context, base));
    }
    const total = criterion.scenarios.length;
    feedback.unshift({
        severity: reached === total ? 'info' : 'error',
        text: `${reached} of ${plural(total, 'scenario')} reached the goal.`,
    });
    return criterionGrade(criterion, total === 0 ? 0 : reached / total, feedback);
}

function failedScenario(
    title: string,
    goal: string,
    report: ScenarioReport,
    context: ScenarioContext,
    base: { scenario: string },
): Feedback {
    const parts = [
        report.error
            ? `Scenario '${title}' failed: the simulation stopped with an error after ${seconds(report.simTime)} of simulated time: ${report.error}`
            : `Scenario '${title}' failed: no ${goal} after ${seconds(report.simTime)} of simulated time`,
    ];
    for (const e of report.events.filter((x) => NOTABLE.has(x.kind))) parts.push(`at ${seconds(e.time)} ${e.text}`);
    const states = finalStates(report, context);
    for (const s of states) parts.push(`${s.component} was in state ${s.state}${s.element ? ` (${where(s.element)})` : ''}`);
    const first = states[0];
    return {
        ...base,
        severity: 'error',
        simTime: report.simTime,
        text: `${parts.join('; ')}.`,
        ...(first ? { state: first.state } : {}),
        ...(first?.element ? { element: first.element } : {}),
    };
}

/** The state each focused automaton ended in, with the state's declaration. */
function finalStates(report: ScenarioReport, context: ScenarioContext) {
    const out: Array<{ component: string; state: string; element?: ReturnType<typeof elementOf> }> = [];
    for (const [node, state] of Object.entries(report.finalStates)) {
        const inst = instanceOfNode(context.instances, node);
        if (!inst || (context.focus.size > 0 && !context.focus.has(inst.component.qualifiedName))) continue;
        const declared = inst.facts.states.find((s) => s.path === state);
        out.push({
            component: inst.component.name,
            state,
            ...(declared ? { element: elementOf(context.model, declared.node, `${inst.component.qualifiedName}.${state}`) } : {}),
        });
    }
    return out;
}
