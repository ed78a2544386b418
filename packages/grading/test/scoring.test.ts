import path from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import type { CoverageCriterion, DriverTask, ScenarioReport, ScenariosCriterion, TestsCriterion } from '@maa/protocol/grading';
import { expectedAutomaton, gradeCoverage } from '../src/coverage.js';
import { type AutomatonInstance, automatonInstances } from '../src/instances.js';
import { loadSubmissionModel, type SubmissionModel } from '../src/model.js';
import type { TaskOutput } from '../src/outputs.js';
import { type PlannedTask, scenarioArgv } from '../src/plan.js';
import { gradeScenarios } from '../src/scenarios.js';
import { explainProblem, gradeTests, stateLinkOf } from '../src/tests.js';
import { fixtures, tempDir, toastController } from './exercise.js';

const gradingDir = path.join(fixtures, 'toast-controller');
const ok: DriverTask = { event: 'task', id: 't', status: 'ok', exitCode: 0, signal: null, seconds: 1, node: 'n', message: 'exited with 0' };
const output = (o: Partial<TaskOutput>): TaskOutput => ({
    result: ok,
    stdout: '',
    stderr: '',
    report: undefined,
    states: undefined,
    recording: undefined,
    ...o,
});

const scenarios: ScenariosCriterion = {
    id: 'scenarios',
    title: 'Serves toast',
    kind: 'scenarios',
    weight: 30,
    scenarios: [
        { id: 'standard', title: 'Standard toaster', world: { goldenSeconds: 6 }, goal: 'toastOnPlate', timeLimit: 60 },
        { id: 'slow', title: 'Slow toaster', world: { goldenSeconds: 12 }, goal: 'toastOnPlate', timeLimit: 60 },
        { id: 'crash', title: 'Crashing run', world: {}, goal: 'toastOnPlate', timeLimit: 60 },
    ],
};
const planned: PlannedTask[] = scenarios.scenarios.map((scenario) => ({
    kind: 'scenario',
    criterion: 'scenarios',
    scenario,
    task: {
        id: `s.scenario.${scenario.id}`,
        input: '/in',
        argv: scenarioArgv(scenario),
        limits: { wallSeconds: 1, cpuSeconds: 1, memoryMB: 64, processes: 1, fileSizeMB: 1 },
        env: {},
    },
}));
const CTRL = '/toast_service_robot/ctrl';
const report = (o: Partial<ScenarioReport>): ScenarioReport => ({
    format: 'maa-scenario-report/1',
    goal: 'toastOnPlate',
    goalReached: false,
    goalTime: null,
    endReason: 'time limit reached',
    simTime: 60,
    world: {},
    events: [],
    states: [],
    finalStates: {},
    toast: null,
    error: null,
    ...o,
});

describe('scoring and feedback (the toast-controller solution model, synthetic task outputs)', () => {
    const work = tempDir('scoring');
    let model: SubmissionModel;
    let instances: AutomatonInstance[];
    beforeAll(async () => {
        const root = toastController(work.dir, { solution: true });
        model = await loadSubmissionModel(root, path.join(root, 'TR.arcapp'));
        instances = automatonInstances(model.appRoot);
    });
    afterAll(() => work.remove());

    test('the automaton instances get the ROS 2 node names of the generated app', () => {
        expect(instances.map((i) => `${i.node} ${i.component.qualifiedName}`)).toEqual(
            expect.arrayContaining([`${CTRL} toast.Controller`, '/toast_service_robot/toaster_ctrl toast.ToasterController']),
        );
    });

    test('scenarios: reached / total; a failed one says when, what happened and the state, linked to its declaration', () => {
        const outputs = new Map<string, TaskOutput>([
            [
                's.scenario.standard',
                output({ report: report({ goalReached: true, goalTime: 15.06, simTime: 15.06, endReason: 'goal reached' }) }),
            ],
            [
                's.scenario.slow',
                output({
                    report: report({
                        events: [{ time: 31.2, kind: 'toast-burnt', text: 'the toast burnt' }],
                        finalStates: { [CTRL]: 'Toasting', '/toast_service_robot/toaster_ctrl': 'On' },
                    }),
                }),
            ],
            [
                's.scenario.crash',
                output({
                    result: { ...ok, status: 'timeout', message: 'killed: wall time limit (1 s)' },
                    stderr: 'Traceback\nRuntimeError: boom\n',
                }),
            ],
        ]);
        const grade = gradeScenarios(scenarios, planned, outputs, { model, instances, focus: new Set(['toast.Controller']) });
        expect(grade.score).toBe(10);
        expect(grade.feedback[0]).toEqual({ severity: 'error', text: '1 of 3 scenarios reached the goal.' });
        expect(grade.feedback[1]).toMatchObject({
            severity: 'info',
            scenario: 'standard',
            simTime: 15.06,
            text: "Scenario 'Standard toaster': toast on the plate after 15.1 s of simulated time.",
        });
        const slow = grade.feedback[2]!;
        expect(slow.text).toMatch(
            /^Scenario 'Slow toaster' failed: no toast on the plate after 60\.0 s of simulated time; at 31\.2 s the toast burnt; Controller was in state Toasting \(toast\/Controller\.arc:\d+\)\.$/,
        );
        expect(slow).toMatchObject({
            scenario: 'slow',
            simTime: 60,
            state: 'Toasting',
            element: { qualifiedName: 'toast.Controller.Toasting', file: 'toast/Controller.arc' },
        });
        expect(grade.feedback[3]!.text).toBe(
            "Scenario 'Crashing run' did not run to its end: killed: wall time limit (1 s) (Traceback | RuntimeError: boom)",
        );
    });

    test('scenarios that could not run score 0 and say why', () => {
        const grade = gradeScenarios(scenarios, [], new Map(), { model, instances, focus: new Set() }, 'the model does not generate: x');
        expect(grade.score).toBe(0);
        expect(grade.feedback.filter((f) => f.text.includes('did not run to its end: the model does not generate: x'))).toHaveLength(3);
    });

    const tests: TestsCriterion = { id: 'hidden', title: 'Hidden tests', kind: 'tests', weight: 30, files: ['Controller.hidden.stream'] };

    test('tests: passed / declared tests; a failed test names its problems and the state it ended in', async () => {
        const file = '/worker/in/tests/Controller.hidden.stream';
        const stdout = JSON.stringify([
            {
                file,
                test: 'serves when golden',
                line: 4,
                passed: false,
                problems: [
                    'arm: expected NONE Tk LOAD_BREAD Tk Tk PICKUP_AND_DEPLOY Tk Tk; got NONE Tk LOAD_BREAD Tk Tk Tk Tk',
                    'state (line 9): expected Serving; got Toasting',
                ],
            },
            { file, test: 'a far plate starts nothing', line: 13, passed: true, problems: [] },
        ]);
        const states = {
            format: 'maa-stream-states/1' as const,
            tests: [
                {
                    file,
                    line: 4,
                    test: 'serves when golden',
                    component: 'toast.Controller',
                    states: ['Idle', 'Loading', 'Toasting', 'Toasting', 'Toasting'],
                },
            ],
        };
        const grade = await gradeTests(tests, gradingDir, output({ stdout, states }), undefined, stateLinkOf(model));
        expect(grade.score).toBe(15);
        expect(grade.feedback).toEqual([
            { severity: 'error', text: '1 of 2 hidden tests passed.' },
            {
                severity: 'error',
                state: 'Toasting',
                text: "Hidden test 'serves when golden' failed at tick 4: expected state Serving, got Toasting (line 9); port arm expected PICKUP_AND_DEPLOY, got no message; the automaton was in state Toasting (toast/Controller.arc:18) then",
                element: { qualifiedName: 'toast.Controller.Toasting', file: 'toast/Controller.arc', line: 18 },
            },
        ]);
    });

    test.each([
        ['arm: expected NONE Tk LOAD_BREAD Tk; got NONE Tk NONE Tk', 'port arm expected LOAD_BREAD, got NONE', 2],
        ['arm: expected A Tk B Tk; got A Tk', 'port arm expected B, got nothing (the stream ended)', 2],
        ['toaster: expected Tk; got STOP Tk', 'port toaster expected no message, got STOP', 1],
        ['arm: expected (empty); got NONE', 'port arm expected nothing (the stream ended), got NONE', undefined],
        [
            'arm: expected NONE LOAD_BREAD PICKUP_AND_DEPLOY; got NONE LOAD_BREAD',
            'port arm expected PICKUP_AND_DEPLOY, got nothing (the stream ended)',
            undefined,
        ],
        ['empty distance: 1 item(s) left buffered: 20', 'empty distance: 1 item(s) left buffered: 20', undefined],
    ])('the runner problem %j in words: %j at tick %j', (problem, text, tick) => {
        expect(explainProblem(problem)).toEqual(tick === undefined ? { text } : { text, tick });
    });

    test('a failed state check in words; the later ones are counted', () => {
        expect(explainProblem('state (line 3): expected Idle; got Loading')).toEqual({
            text: 'expected state Idle, got Loading (line 3)',
            state: true,
        });
    });

    test('tests: a file whose tests did not run counts all its declared tests as failed', async () => {
        const stdout = JSON.stringify([
            {
                file: '/w/tests/Controller.hidden.stream',
                test: null,
                line: 0,
                passed: false,
                problems: ['the application has no component type toast.Controller'],
            },
        ]);
        const grade = await gradeTests(tests, gradingDir, output({ stdout }));
        expect(grade.score).toBe(0);
        expect(grade.feedback.map((f) => f.text)).toEqual([
            '0 of 2 hidden tests passed.',
            'The hidden tests of Controller.hidden.stream did not run: the application has no component type toast.Controller',
        ]);
    });

    test('tests: no results (the runner crashed) scores 0 with the driver message', async () => {
        const grade = await gradeTests(
            tests,
            gradingDir,
            output({ result: { ...ok, status: 'failed', message: 'exited with 1' }, stderr: 'ModuleNotFoundError: maa_app' }),
        );
        expect(grade.score).toBe(0);
        expect(grade.feedback[0]!.text).toBe('The hidden tests did not run: exited with 1 (ModuleNotFoundError: maa_app)');
    });

    const coverage: CoverageCriterion = {
        id: 'cov',
        title: 'Coverage',
        kind: 'coverage',
        weight: 10,
        component: 'toast.Controller',
        states: 1,
        transitions: 1,
    };

    test('coverage: from scenario states and test traces; the unvisited state and untaken transitions are linked', () => {
        const outputs = [
            output({
                report: report({
                    states: [
                        { time: 0, node: CTRL, state: 'Idle' },
                        { time: 0, node: '/toast_service_robot/toaster_ctrl', state: 'Serving' },
                        { time: 0.1, node: CTRL, state: 'Loading' },
                    ],
                }),
            }),
            output({
                states: {
                    format: 'maa-stream-states/1',
                    tests: [{ file: 'f', line: 1, test: 't', component: 'toast.Controller', states: ['Idle', 'Loading', 'Toasting'] }],
                },
            }),
        ];
        const grade = gradeCoverage(coverage, model, instances, outputs);
        // states 3/4, transitions 2/4: (0.75 + 0.5) / 2 of 10
        expect(grade.score).toBe(6.25);
        const texts = grade.feedback.map((f) => f.text);
        expect(texts[0]).toBe('The scenarios and hidden tests visited 3 of 4 states of Controller (75 %, 100 % needed).');
        expect(texts).toContainEqual(expect.stringMatching(/^State Serving was never visited \(toast\/Controller\.arc:\d+\)\.$/));
        expect(texts).toContain('They took 2 of 4 state-changing transitions (50 %, 100 % needed).');
        expect(texts).toContainEqual(
            expect.stringMatching(/^Transition Toasting -> Serving was never taken \(toast\/Controller\.arc:\d+\)\.$/),
        );
        expect(texts).toContainEqual(expect.stringMatching(/^Transition Serving -> Idle was never taken/));
    });

    test('coverage counts against what the structure criterion expects: a smaller automaton does not cover itself fully', () => {
        const outputs = [
            output({
                states: {
                    format: 'maa-stream-states/1',
                    tests: [
                        {
                            file: 'f',
                            line: 1,
                            test: 't',
                            component: 'toast.Controller',
                            states: ['Idle', 'Loading', 'Toasting', 'Serving', 'Idle'],
                        },
                    ],
                },
            }),
        ];
        // every declared state and transition visited: full marks without expectations
        expect(gradeCoverage(coverage, model, instances, outputs).score).toBe(10);
        const expected = expectedAutomaton(
            {
                format: 'maa-grading/1',
                criteria: [
                    coverage,
                    {
                        id: 'arch',
                        title: 'Architecture',
                        kind: 'structure',
                        weight: 5,
                        require: [
                            {
                                component: 'toast.Controller',
                                behavior: { kind: 'automaton', minTransitions: 8, states: ['Idle', 'Cleaning'] },
                            },
                        ],
                    },
                ],
            },
            'toast.Controller',
        );
        expect(expected).toEqual({ states: ['Idle', 'Cleaning'], minStates: 0, minTransitions: 8 });
        const grade = gradeCoverage(coverage, model, instances, outputs, expected);
        // states 4 of 5 (Cleaning is missing), transitions 4 of 8: (0.8 + 0.5) / 2 of 10
        expect(grade.score).toBe(6.5);
        const texts = grade.feedback.map((f) => f.text);
        expect(texts[0]).toBe('The scenarios and hidden tests visited 4 of 5 states of Controller (80 %, 100 % needed).');
        expect(texts[1]).toBe(
            'Controller declares 4 states and 4 state-changing transitions; the exercise expects at least 5 states and 8 transitions (missing: Cleaning), so coverage counts against those.',
        );
        expect(texts).toContain('They took 4 of 8 state-changing transitions (50 %, 100 % needed).');
    });

    test('coverage of a component that is missing or no automaton scores 0', () => {
        expect(gradeCoverage({ ...coverage, component: 'toast.Nope' }, model, instances, []).feedback[0]!.text).toBe(
            'There is no component toast.Nope: there is nothing to cover.',
        );
        const arm = gradeCoverage({ ...coverage, component: 'toast.ArmController' }, model, instances, []);
        expect(arm.score).toBe(0);
        expect(arm.feedback[0]!.text).toBe('ArmController has no automaton: there is nothing to cover.');
    });
});
