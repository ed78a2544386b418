/**
 * The coverage criterion: which declared states of a component's automaton the scenario runs and
 * the hidden tests visited, and which of its state-changing transitions they took, from the state
 * traces (scenario reports' `states`, the stream tests' `--states`). A trace only shows state
 * changes, so a self-loop (a transition back into its own state, an internal transition) is not
 * observable: those do not count. Two transitions with the same source and target cannot be told
 * apart: they count as one.
 *
 * Coverage is measured against what the exercise expects, not only against what the submission
 * declares: otherwise a one-state stub would cover itself completely. The structure criterion's
 * automaton requirement for the same component (named `states`, `minStates`, `minTransitions`)
 * raises the totals: a required state the automaton lacks counts as not visited.
 */
import type { ComponentView } from '@maa/generator-core';
import type { CoverageCriterion, CriterionGrade, Feedback, GradingSpec } from '@maa/protocol/grading';
import { type AutomatonFacts, automatonFacts, componentView } from './component.js';
import { criterionGrade, plural } from './feedback.js';
import { type AutomatonInstance, instanceOfNode } from './instances.js';
import { elementOf, type SubmissionModel, where } from './model.js';
import type { TaskOutput } from './outputs.js';

/** The state sequences of a component seen in the tasks' outputs (one per scenario node, one per stream test). */
export function tracesOf(qualifiedName: string, instances: readonly AutomatonInstance[], outputs: Iterable<TaskOutput>): string[][] {
    const traces: string[][] = [];
    for (const out of outputs) {
        if (out.report) {
            const byNode = new Map<string, string[]>();
            for (const change of [...out.report.states].sort((a, b) => a.time - b.time)) {
                const inst = instanceOfNode(instances, change.node);
                if (inst?.component.qualifiedName !== qualifiedName) continue;
                const seq = byNode.get(change.node) ?? [];
                seq.push(change.state);
                byNode.set(change.node, seq);
            }
            traces.push(...byNode.values());
        }
        for (const test of out.states?.tests ?? []) if (test.component === qualifiedName) traces.push(test.states);
    }
    return traces;
}

/** Whether a state path (`Outer.Inner`) is in the declared state `state` (it or one of its substates). */
export function inState(path: string, state: string): boolean {
    return path === state || path.startsWith(`${state}.`);
}

export interface Coverage {
    /** Declared states (paths) and which were visited. */
    readonly states: ReadonlyArray<{ path: string; visited: boolean }>;
    /** State-changing transitions, one per source and target, and which were taken. */
    readonly transitions: ReadonlyArray<{ source: string; target: string; taken: boolean }>;
    /** Transitions that stay in their state (not observable). */
    readonly selfLoops: number;
}

/** Coverage of an automaton by state traces. */
export function computeCoverage(facts: AutomatonFacts, traces: readonly (readonly string[])[]): Coverage {
    const seen = new Set(traces.flat());
    const changes: Array<[string, string]> = [];
    for (const trace of traces)
        for (let i = 1; i < trace.length; i++) if (trace[i] !== trace[i - 1]) changes.push([trace[i - 1]!, trace[i]!]);
    const pairs = new Map<string, { source: string; target: string }>();
    let selfLoops = 0;
    for (const t of facts.transitions) {
        if (t.source === t.target) selfLoops++;
        else pairs.set(`${t.source}\u0000${t.target}`, { source: t.source, target: t.target });
    }
    return {
        states: facts.states.map((s) => ({ path: s.path, visited: [...seen].some((p) => inState(p, s.path)) })),
        transitions: [...pairs.values()].map((t) => ({
            ...t,
            taken: changes.some(([from, to]) => inState(from, t.source) && inState(to, t.target) && !inState(from, t.target)),
        })),
        selfLoops,
    };
}

/** min(1, covered share / required share); a required share of 0 is always met. */
export function coverageShare(covered: number, total: number, required: number): number {
    if (required <= 0) return 1;
    if (total === 0) return 1;
    return Math.min(1, covered / total / required);
}

/** What the exercise expects of a component's automaton (the structure criteria's requirements on it). */
export interface ExpectedAutomaton {
    /** states the automaton must declare (paths) */
    readonly states: readonly string[];
    readonly minStates: number;
    readonly minTransitions: number;
}

/** The structure criteria's automaton requirements on `component`, merged (none: nothing expected). */
export function expectedAutomaton(spec: GradingSpec, component: string): ExpectedAutomaton {
    const states = new Set<string>();
    let minStates = 0;
    let minTransitions = 0;
    for (const c of spec.criteria) {
        if (c.kind !== 'structure') continue;
        for (const r of c.require) {
            if (r.component !== component || r.behavior?.kind !== 'automaton') continue;
            for (const s of r.behavior.states ?? []) states.add(s);
            minStates = Math.max(minStates, r.behavior.minStates ?? 0);
            minTransitions = Math.max(minTransitions, r.behavior.minTransitions ?? 0);
        }
    }
    return { states: [...states], minStates, minTransitions };
}

const NOTHING_EXPECTED: ExpectedAutomaton = { states: [], minStates: 0, minTransitions: 0 };

export function gradeCoverage(
    criterion: CoverageCriterion,
    model: SubmissionModel,
    instances: readonly AutomatonInstance[],
    outputs: Iterable<TaskOutput>,
    expected: ExpectedAutomaton = NOTHING_EXPECTED,
): CriterionGrade {
    const node = model.components.get(criterion.component);
    const view: ComponentView | undefined = node ? componentView(node) : undefined;
    const facts = view ? automatonFacts(view) : undefined;
    if (!view || !facts) {
        const text = view
            ? `${view.name} has no automaton: there is nothing to cover.`
            : `There is no component ${criterion.component}: there is nothing to cover.`;
        return criterionGrade(criterion, 0, [{ severity: 'error', text }]);
    }
    const coverage = computeCoverage(facts, tracesOf(view.qualifiedName, instances, outputs));
    const visited = coverage.states.filter((s) => s.visited).length;
    const taken = coverage.transitions.filter((t) => t.taken).length;
    const lacking = expected.states.filter((name) => !coverage.states.some((s) => s.path === name));
    const stateTotal = Math.max(coverage.states.length + lacking.length, expected.minStates);
    const transitionTotal = Math.max(coverage.transitions.length, expected.minTransitions);
    const stateShare = coverageShare(visited, stateTotal, criterion.states);
    const transitionShare = coverageShare(taken, transitionTotal, criterion.transitions);
    const pct = (a: number, b: number) => (b === 0 ? 100 : Math.round((a / b) * 100));
    const feedback: Feedback[] = [];
    const link = (n: (typeof facts.states)[number]['node'], name: string) => elementOf(model, n, `${view.qualifiedName}.${name}`);
    feedback.push({
        severity: stateShare < 1 ? 'error' : 'info',
        text: `The scenarios and hidden tests visited ${visited} of ${plural(stateTotal, 'state')} of ${view.name} (${pct(visited, stateTotal)} %, ${Math.round(criterion.states * 100)} % needed).`,
    });
    if (stateTotal > coverage.states.length || transitionTotal > coverage.transitions.length)
        feedback.push({
            severity: 'warning',
            text: `${view.name} declares ${plural(coverage.states.length, 'state')} and ${plural(coverage.transitions.length, 'state-changing transition')}; the exercise expects at least ${plural(stateTotal, 'state')} and ${plural(transitionTotal, 'transition')}${lacking.length > 0 ? ` (missing: ${lacking.join(', ')})` : ''}, so coverage counts against those.`,
        });
    for (const s of coverage.states.filter((x) => !x.visited)) {
        const element = link(facts.states.find((d) => d.path === s.path)!.node, s.path);
        feedback.push({ severity: 'warning', text: `State ${s.path} was never visited (${where(element)}).`, element, state: s.path });
    }
    feedback.push({
        severity: transitionShare < 1 ? 'error' : 'info',
        text: `They took ${taken} of ${plural(transitionTotal, 'state-changing transition')} (${pct(taken, transitionTotal)} %, ${Math.round(criterion.transitions * 100)} % needed).`,
    });
    for (const t of coverage.transitions.filter((x) => !x.taken)) {
        const declared = facts.transitions.find((d) => d.source === t.source && d.target === t.target)!;
        const element = link(declared.node, `${t.source}->${t.target}`);
        feedback.push({ severity: 'warning', text: `Transition ${t.source} -> ${t.target} was never taken (${where(element)}).`, element });
    }
    if (coverage.selfLoops > 0)
        feedback.push({
            severity: 'info',
            text: `${plural(coverage.selfLoops, 'transition')} of ${view.name} stay${coverage.selfLoops === 1 ? 's' : ''} in ${coverage.selfLoops === 1 ? 'its' : 'their'} state: a state trace cannot show ${coverage.selfLoops === 1 ? 'it' : 'them'}, so ${coverage.selfLoops === 1 ? 'it does' : 'they do'} not count.`,
        });
    return criterionGrade(criterion, (stateShare + transitionShare) / 2, feedback);
}
