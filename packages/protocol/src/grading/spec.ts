/**
 * `grading.json` (docs/lab.md "Grading"): an exercise's weighted grading criteria, kept in the
 * exercise's `grading/` folder with the hidden `.stream` files it names; never released to students.
 */
import { Type, type Static } from '@sinclair/typebox';
import { GRADING_FORMAT } from './formats.js';

/** A dotted qualified name of a model element (`toast.Controller`). */
const QualifiedName = (what: string) =>
    Type.String({
        pattern: '^[A-Za-z_][A-Za-z0-9_]*(\\.[A-Za-z_][A-Za-z0-9_]*)*$',
        errorMessage: `${what} must be a qualified name like toast.Controller`,
    });

const Name = (what: string) =>
    Type.String({ pattern: '^[A-Za-z_][A-Za-z0-9_]*$', errorMessage: `${what} must be a name (letters, digits, _)` });

/** A file of the grading folder: relative, `/`-separated, no `..`. */
const GradingFile = (suffix: string) =>
    Type.String({
        pattern: `^(?!/)(?!.*\\\\)(?!.*//)(?!(.*/)?\\.\\.?(/|$))[^\\u0000-\\u001f]{1,512}${suffix.replace(/\./g, '\\.')}$`,
        errorMessage: `a file of the grading folder: a relative path with / (no .. or leading /) ending in ${suffix}`,
    });

/** Resource limits of one task (tests of a submission, a scenario run); the driver's defaults when absent. */
export const TaskLimits = Type.Object(
    {
        wallSeconds: Type.Number({ exclusiveMinimum: 0, maximum: 86400, errorMessage: 'wallSeconds must be a positive number of seconds' }),
        cpuSeconds: Type.Integer({ minimum: 1, errorMessage: 'cpuSeconds must be a positive integer' }),
        memoryMB: Type.Integer({ minimum: 16, errorMessage: 'memoryMB must be an integer from 16' }),
        processes: Type.Integer({ minimum: 1, errorMessage: 'processes must be a positive integer' }),
        fileSizeMB: Type.Integer({ minimum: 1, errorMessage: 'fileSizeMB must be a positive integer' }),
    },
    {
        title: 'TaskLimits',
        additionalProperties: false,
        errorMessage: 'limits must be an object of wallSeconds, cpuSeconds, memoryMB, processes, fileSizeMB',
    },
);
export type TaskLimits = Static<typeof TaskLimits>;

const PartialLimits = Type.Partial(TaskLimits, {
    title: 'PartialTaskLimits',
    additionalProperties: false,
    errorMessage: 'limits must be an object of wallSeconds, cpuSeconds, memoryMB, processes, fileSizeMB',
});

export const BehaviorKind = Type.Union(
    ['automaton', 'robotarm', 'compute', 'handwritten', 'composed', 'none'].map((k) => Type.Literal(k)),
    { errorMessage: 'behavior kind must be one of automaton, robotarm, compute, handwritten, composed, none' },
);
export type BehaviorKind = Static<typeof BehaviorKind>;

/** What one required component must have; every field but `component` is optional. */
export const StructureRequirement = Type.Object(
    {
        component: QualifiedName('component'),
        ports: Type.Optional(
            Type.Array(
                Type.Object(
                    {
                        name: Name('port name'),
                        direction: Type.Optional(
                            Type.Union([Type.Literal('in'), Type.Literal('out')], { errorMessage: 'direction must be in or out' }),
                        ),
                        /** The port's type as written in the model (`int`, `ArmCommand`, `toast.types.ArmCommand`). */
                        type: Type.Optional(Type.String({ minLength: 1, errorMessage: 'type must be a type name' })),
                    },
                    {
                        title: 'PortRequirement',
                        additionalProperties: false,
                        errorMessage: 'a port requirement has name, direction?, type?',
                    },
                ),
            ),
        ),
        subcomponents: Type.Optional(
            Type.Array(
                Type.Object(
                    {
                        name: Type.Optional(Name('subcomponent name')),
                        type: Type.Optional(QualifiedName('subcomponent type')),
                    },
                    {
                        title: 'SubcomponentRequirement',
                        additionalProperties: false,
                        errorMessage: 'a subcomponent requirement has name? and type?',
                    },
                ),
            ),
        ),
        behavior: Type.Optional(
            Type.Object(
                {
                    kind: BehaviorKind,
                    minStates: Type.Optional(Type.Integer({ minimum: 0, errorMessage: 'minStates must be an integer from 0' })),
                    minTransitions: Type.Optional(Type.Integer({ minimum: 0, errorMessage: 'minTransitions must be an integer from 0' })),
                    /** Named states the automaton must declare. */
                    states: Type.Optional(Type.Array(Name('state name'), { uniqueItems: true })),
                },
                {
                    title: 'BehaviorRequirement',
                    additionalProperties: false,
                    errorMessage: 'behavior has kind, minStates?, minTransitions?, states?',
                },
            ),
        ),
    },
    {
        title: 'StructureRequirement',
        additionalProperties: false,
        errorMessage: 'a requirement has component, ports?, subcomponents?, behavior?',
    },
);
export type StructureRequirement = Static<typeof StructureRequirement>;

const CriterionFields = {
    /** Unique in the spec: the key of the criterion in results and the CSV export. */
    id: Type.String({ pattern: '^[a-z0-9][a-z0-9-]*$', errorMessage: 'id must be lower case letters, digits and -' }),
    /** Shown to students and instructors. */
    title: Type.String({ minLength: 1, maxLength: 200, errorMessage: 'title must be a non-empty string (at most 200 characters)' }),
    /** Points of the criterion (the grade's maximum is the sum of the weights). */
    weight: Type.Number({ minimum: 0, errorMessage: 'weight must be a number from 0' }),
};

export const StructureCriterion = Type.Object(
    {
        ...CriterionFields,
        kind: Type.Literal('structure'),
        require: Type.Array(StructureRequirement, { minItems: 1, errorMessage: 'require must be a non-empty list of requirements' }),
    },
    {
        title: 'StructureCriterion',
        additionalProperties: false,
        errorMessage: 'a structure criterion has id, title, kind, weight, require',
    },
);
export type StructureCriterion = Static<typeof StructureCriterion>;

export const DiagnosticsCriterion = Type.Object(
    { ...CriterionFields, kind: Type.Literal('diagnostics') },
    { title: 'DiagnosticsCriterion', additionalProperties: false, errorMessage: 'a diagnostics criterion has id, title, kind, weight' },
);
export type DiagnosticsCriterion = Static<typeof DiagnosticsCriterion>;

export const TestsCriterion = Type.Object(
    {
        ...CriterionFields,
        kind: Type.Literal('tests'),
        /** Hidden `.stream` files of the grading folder. */
        files: Type.Array(GradingFile('.stream'), {
            minItems: 1,
            uniqueItems: true,
            errorMessage: 'files must be a non-empty list of distinct .stream files',
        }),
        limits: Type.Optional(PartialLimits),
    },
    { title: 'HiddenTestsCriterion', additionalProperties: false, errorMessage: 'a tests criterion has id, title, kind, weight, files' },
);
export type TestsCriterion = Static<typeof TestsCriterion>;

/** A scenario's initial world (`maa-sim run --world FILE`). */
export const ScenarioWorld = Type.Object(
    {
        /** Simulated seconds of toasting to toast level 1 (golden at 0.8 of it): the bread colour threshold. */
        goldenSeconds: Type.Optional(Type.Number({ exclusiveMinimum: 0, errorMessage: 'goldenSeconds must be a positive number' })),
        /** Standard deviation in metres of the bread's start position in its holder (0: none; maa-sim allows up to 0.005). */
        breadJitter: Type.Optional(Type.Number({ minimum: 0, errorMessage: 'breadJitter must be a number from 0' })),
        /** The scene's random seed. */
        seed: Type.Optional(Type.Integer({ errorMessage: 'seed must be an integer' })),
    },
    { title: 'ScenarioWorld', additionalProperties: false, errorMessage: 'world has goldenSeconds?, breadJitter?, seed?' },
);
export type ScenarioWorld = Static<typeof ScenarioWorld>;

export const Scenario = Type.Object(
    {
        id: Type.String({ pattern: '^[a-z0-9][a-z0-9-]*$', errorMessage: 'scenario id must be lower case letters, digits and -' }),
        title: Type.String({ minLength: 1, maxLength: 200, errorMessage: 'scenario title must be a non-empty string' }),
        world: ScenarioWorld,
        /** The goal the run must reach (`maa-sim run --until-goal`). */
        goal: Type.Literal('toastOnPlate', { errorMessage: 'goal must be toastOnPlate' }),
        /** Simulated seconds the goal must be reached within. */
        timeLimit: Type.Number({
            exclusiveMinimum: 0,
            maximum: 3600,
            errorMessage: 'timeLimit must be a positive number of simulated seconds (at most 3600)',
        }),
    },
    { title: 'Scenario', additionalProperties: false, errorMessage: 'a scenario has id, title, world, goal, timeLimit' },
);
export type Scenario = Static<typeof Scenario>;

export const ScenariosCriterion = Type.Object(
    {
        ...CriterionFields,
        kind: Type.Literal('scenarios'),
        scenarios: Type.Array(Scenario, { minItems: 1, errorMessage: 'scenarios must be a non-empty list' }),
        limits: Type.Optional(PartialLimits),
    },
    {
        title: 'ScenariosCriterion',
        additionalProperties: false,
        errorMessage: 'a scenarios criterion has id, title, kind, weight, scenarios',
    },
);
export type ScenariosCriterion = Static<typeof ScenariosCriterion>;

const Share = (what: string) => Type.Number({ minimum: 0, maximum: 1, errorMessage: `${what} must be a share from 0 to 1` });

export const CoverageCriterion = Type.Object(
    {
        ...CriterionFields,
        kind: Type.Literal('coverage'),
        /** The component whose automaton is covered. */
        component: QualifiedName('component'),
        /** The share of the declared states that must be visited for full points. */
        states: Share('states'),
        /** The share of the declared transitions (that change the state) that must be taken for full points. */
        transitions: Share('transitions'),
    },
    {
        title: 'CoverageCriterion',
        additionalProperties: false,
        errorMessage: 'a coverage criterion has id, title, kind, weight, component, states, transitions',
    },
);
export type CoverageCriterion = Static<typeof CoverageCriterion>;

export const Criterion = Type.Union([StructureCriterion, DiagnosticsCriterion, TestsCriterion, ScenariosCriterion, CoverageCriterion], {
    errorMessage: 'kind must be one of structure, diagnostics, tests, scenarios, coverage',
});
export type Criterion = Static<typeof Criterion>;
export type CriterionKind = Criterion['kind'];

export const GradingSpec = Type.Object(
    {
        format: Type.Literal(GRADING_FORMAT, { errorMessage: `format must be '${GRADING_FORMAT}'` }),
        criteria: Type.Array(Criterion, { minItems: 1, errorMessage: 'criteria must be a non-empty list' }),
        /** Default limits of every task (a criterion's own limits win). */
        limits: Type.Optional(PartialLimits),
    },
    {
        $id: 'urn:maa:protocol:grading',
        title: 'GradingSpec',
        description: 'grading.json: the grading criteria of a lab exercise (docs/lab.md "Grading")',
        additionalProperties: false,
        errorMessage: 'expected an object with format and criteria',
    },
);
export type GradingSpec = Static<typeof GradingSpec>;
