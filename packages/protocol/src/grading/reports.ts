/** The outputs of grading tasks that @maa/grading reads: scenario reports and stream-test state traces. */
import { Type, type Static } from '@sinclair/typebox';
import { SCENARIO_REPORT_FORMAT, STREAM_STATES_FORMAT } from './formats.js';
import { ScenarioWorld } from './spec.js';

export const ScenarioEventKind = Type.Union(
    ['bread-loaded', 'toaster-on', 'toaster-off', 'toast-golden', 'toast-burnt', 'toast-dropped', 'toast-on-plate', 'error'].map((k) =>
        Type.Literal(k),
    ),
);
export type ScenarioEventKind = Static<typeof ScenarioEventKind>;

export const ScenarioEvent = Type.Object(
    {
        /** Simulated seconds. */
        time: Type.Number(),
        kind: ScenarioEventKind,
        text: Type.String(),
    },
    { title: 'ScenarioEvent', additionalProperties: false },
);
export type ScenarioEvent = Static<typeof ScenarioEvent>;

/** A change of an automaton's state (`/maa/automaton_states`). */
export const ScenarioStateChange = Type.Object(
    {
        time: Type.Number(),
        /** The ROS 2 node name of the automaton instance (LockstepApp.states()). */
        node: Type.String(),
        state: Type.String(),
    },
    { title: 'ScenarioStateChange', additionalProperties: false },
);
export type ScenarioStateChange = Static<typeof ScenarioStateChange>;

export const ScenarioToast = Type.Object(
    {
        level: Type.Number(),
        color: Type.String(),
        onPlate: Type.Boolean(),
        dropped: Type.Boolean(),
    },
    { title: 'ScenarioToast', additionalProperties: false },
);
export type ScenarioToast = Static<typeof ScenarioToast>;

export const ScenarioReport = Type.Object(
    {
        format: Type.Literal(SCENARIO_REPORT_FORMAT),
        goal: Type.Union([Type.String(), Type.Null()]),
        goalReached: Type.Boolean(),
        goalTime: Type.Union([Type.Number(), Type.Null()]),
        /** Why the run ended, in words (`goal reached`, `time limit`, `error`). */
        endReason: Type.String(),
        /** Simulated seconds at the end. */
        simTime: Type.Number(),
        world: ScenarioWorld,
        events: Type.Array(ScenarioEvent),
        states: Type.Array(ScenarioStateChange),
        /** The last state of every automaton node. */
        finalStates: Type.Record(Type.String(), Type.String()),
        toast: Type.Union([ScenarioToast, Type.Null()]),
        error: Type.Union([Type.String(), Type.Null()]),
    },
    {
        $id: 'urn:maa:protocol:scenario-report',
        title: 'ScenarioReport',
        description: 'the report of a scenario run (maa-sim run --report FILE)',
    },
);
export type ScenarioReport = Static<typeof ScenarioReport>;

export const StreamStatesTest = Type.Object(
    {
        file: Type.String(),
        line: Type.Integer(),
        test: Type.String(),
        /** The qualified name of the component under test. */
        component: Type.String(),
        /** The state before the first tick and after every tick. */
        states: Type.Array(Type.String()),
    },
    { title: 'StreamStatesTest', additionalProperties: false },
);
export type StreamStatesTest = Static<typeof StreamStatesTest>;

export const StreamStates = Type.Object(
    {
        format: Type.Literal(STREAM_STATES_FORMAT),
        tests: Type.Array(StreamStatesTest),
    },
    {
        $id: 'urn:maa:protocol:stream-states',
        title: 'StreamStates',
        description: 'the automaton state traces of stream tests (python -m maa_timesync.streamtest --states FILE)',
        additionalProperties: false,
    },
);
export type StreamStates = Static<typeof StreamStates>;
