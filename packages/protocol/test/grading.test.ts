import { describe, expect, test } from 'vitest';
import {
    driverLineContract,
    gradeJobContract,
    gradingSpecIssues,
    scenarioReportContract,
    streamStatesContract,
    submissionGradeContract,
} from '../dist/grading/index.js';

const spec = {
    format: 'maa-grading/1',
    criteria: [
        {
            id: 'architecture',
            title: "The controller's interface",
            kind: 'structure',
            weight: 20,
            require: [
                {
                    component: 'toast.Controller',
                    ports: [{ name: 'distance', direction: 'in', type: 'int' }],
                    subcomponents: [{ name: 'safety', type: 'follower.Safety' }],
                    behavior: { kind: 'automaton', minStates: 3, minTransitions: 3 },
                },
            ],
        },
        { id: 'no-errors', title: 'The model has no errors', kind: 'diagnostics', weight: 10 },
        { id: 'hidden-tests', title: 'Hidden stream tests', kind: 'tests', weight: 30, files: ['Controller.hidden.stream'] },
        {
            id: 'scenarios',
            title: 'The robot serves toast',
            kind: 'scenarios',
            weight: 30,
            scenarios: [
                {
                    id: 'standard',
                    title: 'Standard toaster',
                    world: { goldenSeconds: 6, breadJitter: 0, seed: 0 },
                    goal: 'toastOnPlate',
                    timeLimit: 60,
                },
            ],
            limits: { wallSeconds: 120 },
        },
        {
            id: 'coverage',
            title: 'Automaton coverage',
            kind: 'coverage',
            weight: 10,
            component: 'toast.Controller',
            states: 1.0,
            transitions: 1.0,
        },
    ],
};

const criteria = spec.criteria;
const withCriterion = (i: number, patch: Record<string, unknown>) => ({
    ...spec,
    criteria: criteria.map((c, j) => (j === i ? { ...c, ...patch } : c)),
});

describe('grading.json (GradingSpec)', () => {
    test('the design example is valid', () => {
        expect(gradingSpecIssues(spec)).toEqual([]);
    });

    test.each([
        ['wrong format', { ...spec, format: 'maa-grading/2' }, '/format', "format must be 'maa-grading/1'"],
        ['no criteria', { ...spec, criteria: [] }, '/criteria', 'non-empty list'],
        ['unknown kind', withCriterion(1, { kind: 'style' }), '/criteria/1/kind', 'kind must be one of'],
        ['negative weight', withCriterion(1, { weight: -1 }), '/criteria/1/weight', 'weight must be a number from 0'],
        ['bad id', withCriterion(1, { id: 'No Errors' }), '/criteria/1/id', 'lower case'],
        ['a structure criterion without requirements', withCriterion(0, { require: [] }), '/criteria/0/require', 'non-empty list'],
        [
            'a bad behavior kind',
            withCriterion(0, { require: [{ component: 'toast.Controller', behavior: { kind: 'statechart' } }] }),
            '/criteria/0/require/0/behavior/kind',
            'behavior kind must be one of',
        ],
        [
            'a port direction that is neither in nor out',
            withCriterion(0, { require: [{ component: 'toast.Controller', ports: [{ name: 'x', direction: 'inout' }] }] }),
            '/criteria/0/require/0/ports/0/direction',
            'direction must be in or out',
        ],
        [
            'a component that is no qualified name',
            withCriterion(4, { component: 'toast/Controller' }),
            '/criteria/4/component',
            'qualified name',
        ],
        ['a hidden test that is no .stream', withCriterion(2, { files: ['Controller.arc'] }), '/criteria/2/files/0', 'ending in .stream'],
        ['a hidden test outside the grading folder', withCriterion(2, { files: ['../x.stream'] }), '/criteria/2/files/0', 'no ..'],
        ['a coverage share above 1', withCriterion(4, { states: 1.5 }), '/criteria/4/states', 'share from 0 to 1'],
        [
            'a scenario without a time limit',
            withCriterion(3, { scenarios: [{ id: 's', title: 'S', world: {}, goal: 'toastOnPlate' }] }),
            '/criteria/3/scenarios/0/timeLimit',
            '',
        ],
        [
            'an unknown world field',
            withCriterion(3, { scenarios: [{ id: 's', title: 'S', world: { gravity: 3 }, goal: 'toastOnPlate', timeLimit: 9 }] }),
            '/criteria/3/scenarios/0/world/gravity',
            '',
        ],
        ['an unknown limit', withCriterion(3, { limits: { seconds: 3 } }), '/criteria/3/limits/seconds', ''],
        ['a criterion id used twice', withCriterion(1, { id: 'architecture' }), '/criteria/1/id', "'architecture' is used twice"],
        [
            'a scenario id used twice',
            withCriterion(3, {
                scenarios: [criteria[3].scenarios![0], { ...criteria[3].scenarios![0], title: 'Again' }],
            }),
            '/criteria/3/scenarios/1/id',
            "'standard' is used twice",
        ],
    ])('%s: an issue at the field', (_what, value, pointer, message) => {
        const issues = gradingSpecIssues(value);
        expect(
            issues.some((i) => i.pointer === pointer && i.message.includes(message)),
            JSON.stringify(issues),
        ).toBe(true);
    });
});

describe('grade results, jobs, driver lines, reports', () => {
    const grade = {
        submission: 'alice',
        score: 90,
        maxScore: 100,
        criteria: [
            {
                id: 'scenarios',
                title: 'The robot serves toast',
                kind: 'scenarios',
                score: 20,
                max: 30,
                feedback: [
                    {
                        severity: 'error',
                        text: "Scenario 'Slow toaster' failed",
                        element: { qualifiedName: 'toast.Controller', file: 'toast/Controller.arc', line: 22 },
                        scenario: 'slow',
                        simTime: 60,
                        state: 'Toasting',
                    },
                ],
            },
        ],
        recordings: [{ scenario: 'slow', file: '/tmp/w/alice/slow.mcap' }],
        tasks: [{ id: 'alice.scenario.slow', status: 'ok', seconds: 12.5 }],
    };

    test('a submission grade', () => {
        expect(submissionGradeContract.issues(grade)).toEqual([]);
        expect(submissionGradeContract.check({ ...grade, criteria: [{ ...grade.criteria[0], kind: 'style' }] })).toBe(false);
        expect(submissionGradeContract.check({ ...grade, tasks: [{ id: 't', status: 'lost', seconds: 1 }] })).toBe(false);
    });

    const job = {
        format: 'maa-grade-job/1',
        tasks: [
            {
                id: 's1.scenario.standard',
                input: '/abs/dir',
                argv: ['{python}', '-m', 'maa_sim', 'run', '--report', '{output}/report.json'],
                limits: { wallSeconds: 120, cpuSeconds: 100, memoryMB: 2048, processes: 64, fileSizeMB: 256 },
                env: {},
            },
        ],
    };

    test('a grade job', () => {
        expect(gradeJobContract.issues(job)).toEqual([]);
        const relative = { ...job, tasks: [{ ...job.tasks[0], input: 'rel/dir' }] };
        expect(gradeJobContract.issues(relative).map((i) => i.pointer)).toContain('/tasks/0/input');
        const noLimits = { ...job, tasks: [{ ...job.tasks[0], limits: { wallSeconds: 1 } }] };
        expect(gradeJobContract.check(noLimits)).toBe(false);
    });

    test('driver lines', () => {
        expect(driverLineContract.check({ event: 'started', tasks: 3, mode: 'local', address: null, nodes: 1, cpus: 2 })).toBe(true);
        expect(
            driverLineContract.check({
                event: 'task',
                id: 't',
                status: 'timeout',
                exitCode: null,
                signal: 9,
                seconds: 120.2,
                node: '127.0.0.1',
                message: 'killed: wall time limit (120 s)',
            }),
        ).toBe(true);
        expect(driverLineContract.check({ event: 'finished', wallSeconds: 3, counts: { ok: 2, failed: 1 } })).toBe(true);
        expect(driverLineContract.check({ event: 'task', id: 't', status: 'ok' })).toBe(false);
        expect(driverLineContract.check({ event: 'progress' })).toBe(false);
    });

    test('a scenario report and stream state traces', () => {
        const report = {
            format: 'maa-scenario-report/1',
            goal: 'toastOnPlate',
            goalReached: true,
            goalTime: 23.4,
            endReason: 'goal reached',
            simTime: 23.4,
            world: { goldenSeconds: 6, breadJitter: 0, seed: 0 },
            events: [{ time: 1.2, kind: 'toaster-on', text: 'the toaster started' }],
            states: [{ time: 0, node: 'controller', state: 'Idle' }],
            finalStates: { controller: 'Serving' },
            toast: { level: 0.9, color: 'GOLDEN', onPlate: true, dropped: false },
            error: null,
        };
        expect(scenarioReportContract.issues(report)).toEqual([]);
        expect(scenarioReportContract.check({ ...report, events: [{ time: 1, kind: 'exploded', text: '' }] })).toBe(false);
        expect(scenarioReportContract.check({ ...report, goalReached: 'yes' })).toBe(false);
        const states = {
            format: 'maa-stream-states/1',
            tests: [{ file: 'a.stream', line: 3, test: 'name', component: 'toast.Controller', states: ['Idle', 'Loading'] }],
        };
        expect(streamStatesContract.issues(states)).toEqual([]);
        expect(streamStatesContract.check({ ...states, tests: [{ file: 'a.stream' }] })).toBe(false);
    });
});
