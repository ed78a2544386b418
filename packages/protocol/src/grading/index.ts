import { contract, type ContractIssue, dedupeIssues } from '../contract.js';
import { DriverLine, GradeJob } from './job.js';
import { ScenarioReport, StreamStates } from './reports.js';
import { SubmissionGrade } from './result.js';
import { CoverageCriterion, DiagnosticsCriterion, GradingSpec, ScenariosCriterion, StructureCriterion, TestsCriterion } from './spec.js';

export * from './formats.js';
export * from './job.js';
export * from './reports.js';
export * from './result.js';
export * from './spec.js';

/** Checks a parsed `grading.json` (the schema; {@link gradingSpecIssues} names the field of a bad criterion and adds the rules between fields). */
export const gradingSpecContract = contract('grading.json', GradingSpec);
/** Checks the grade of a submission. */
export const submissionGradeContract = contract('submission grade', SubmissionGrade);
/** Checks a grade job file. */
export const gradeJobContract = contract('grade job', GradeJob);
/** Checks one JSON line of the grading driver. */
export const driverLineContract = contract('grading driver line', DriverLine);
/** Checks a scenario report (`maa-sim run --report`). */
export const scenarioReportContract = contract('scenario report', ScenarioReport);
/** Checks stream-test state traces (`streamtest --states`). */
export const streamStatesContract = contract('stream state traces', StreamStates);

const CRITERION_CONTRACTS = {
    structure: contract('structure criterion', StructureCriterion),
    diagnostics: contract('diagnostics criterion', DiagnosticsCriterion),
    tests: contract('tests criterion', TestsCriterion),
    scenarios: contract('scenarios criterion', ScenariosCriterion),
    coverage: contract('coverage criterion', CoverageCriterion),
} as const;

/**
 * Every issue of a parsed `grading.json`, each with the JSON pointer of the field: a criterion is
 * checked against the schema of its `kind` (so the issue names its bad field, not the union), then
 * criterion ids and the scenario ids of a criterion must be unique.
 */
export function gradingSpecIssues(value: unknown): ContractIssue[] {
    const issues = gradingSpecContract.issues(value);
    if (issues.length === 0) return uniqueIds(value as GradingSpec);
    const criteria = (value as { criteria?: unknown } | null)?.criteria;
    if (!Array.isArray(criteria)) return dedupeIssues(issues);
    const out = issues.filter((i) => !/^\/criteria\/\d+(\/|$)/.test(i.pointer));
    criteria.forEach((criterion: unknown, index) => {
        const kind = (criterion as { kind?: unknown } | null)?.kind;
        const own =
            typeof kind === 'string' && kind in CRITERION_CONTRACTS
                ? CRITERION_CONTRACTS[kind as keyof typeof CRITERION_CONTRACTS]
                : undefined;
        if (!own) {
            out.push({
                pointer: `/criteria/${index}/kind`,
                message: 'kind must be one of structure, diagnostics, tests, scenarios, coverage',
            });
            return;
        }
        for (const issue of own.issues(criterion)) out.push({ pointer: `/criteria/${index}${issue.pointer}`, message: issue.message });
    });
    return dedupeIssues(out);
}

function uniqueIds(spec: GradingSpec): ContractIssue[] {
    const out: ContractIssue[] = [];
    const ids = new Set<string>();
    spec.criteria.forEach((criterion, i) => {
        if (ids.has(criterion.id)) out.push({ pointer: `/criteria/${i}/id`, message: `criterion id '${criterion.id}' is used twice` });
        ids.add(criterion.id);
        if (criterion.kind !== 'scenarios') return;
        const scenarios = new Set<string>();
        criterion.scenarios.forEach((scenario, j) => {
            if (scenarios.has(scenario.id))
                out.push({ pointer: `/criteria/${i}/scenarios/${j}/id`, message: `scenario id '${scenario.id}' is used twice` });
            scenarios.add(scenario.id);
        });
    });
    return out;
}
