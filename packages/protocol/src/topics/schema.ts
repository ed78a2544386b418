/**
 * The port topics of a generated application (`GET /api/sim/topics`): which ROS topic carries
 * which port, read by the backend from what the generator wrote (`deployment.json` of a ros2
 * platform, the `PORT_TOPICS`/`NODE_NAMES` tables of a timesync platform's app module), so the
 * IDE never guesses a port back from a snake-case topic name. It also lists the automata of the
 * application (their states and transitions with source positions), the table the trace panels
 * and breakpoints resolve `/maa/transitions` and `/maa/automaton_states` against.
 */
import { Type, type Static } from '@sinclair/typebox';
import { SimMode } from '../http/sim.js';

export const PortTopicEntry = Type.Object({
    /** The port path as the diagram knows it: `ctrl.arm`, or `distance` for a port of the root. */
    portPath: Type.String({ minLength: 1 }),
    /** The instance path (`ctrl`, `unit.ctrl`); `""` for a port of the root. */
    instancePath: Type.String(),
    /** The port's name (the last segment of portPath). */
    port: Type.String({ minLength: 1 }),
    /** `out`: the topic the port publishes; `in`: the topic the port reads. */
    direction: Type.Union([Type.Literal('out'), Type.Literal('in')]),
    /** Absolute ROS topic (`/toast_service_robot/ctrl/arm`). */
    topic: Type.String({ pattern: '^/' }),
    /** ROS 2 message type (`std_msgs/msg/Int32`). */
    type: Type.String(),
    /** No port of the application publishes the topic: it is fed from outside (input injection). */
    external: Type.Boolean(),
});
export type PortTopicEntry = Static<typeof PortTopicEntry>;

export const InstanceNode = Type.Object({
    /** The instance path (`ctrl`); `""` for the root. */
    instancePath: Type.String(),
    /** Its ROS node (`/toast_service_robot/ctrl`), the key of `/maa/automaton_states`. */
    node: Type.String({ pattern: '^/' }),
});
export type InstanceNode = Static<typeof InstanceNode>;

/** A state of an automaton in the automata table. */
export const AutomatonStateEntry = Type.Object({
    /** Its path from the top state (`Outer.Inner`), as on `/maa/automaton_states`. */
    path: Type.String({ minLength: 1 }),
    /** 1-based line of its declaration in the automaton's file. */
    line: Type.Integer({ minimum: 1 }),
});
export type AutomatonStateEntry = Static<typeof AutomatonStateEntry>;

/** A transition of an automaton in the automata table. */
export const AutomatonTransitionEntry = Type.Object({
    /**
     * 0-based position in the automaton's transitions (@maa/language-automata's allTransitions; a
     * mode automaton's mode transitions in declaration order), the `index` of `/maa/transitions`.
     */
    index: Type.Integer({ minimum: 0 }),
    /** Path of the declared source state. */
    from: Type.String({ minLength: 1 }),
    /** Path of the declared target state (the source's for an internal transition). */
    to: Type.String({ minLength: 1 }),
    /** `trigger [guard] / action` as the diagram shows it (`""` for none). */
    label: Type.String(),
    /** 1-based line and column of the transition in the automaton's file. */
    line: Type.Integer({ minimum: 1 }),
    column: Type.Integer({ minimum: 1 }),
});
export type AutomatonTransitionEntry = Static<typeof AutomatonTransitionEntry>;

/** One automaton instance of a generated application: a component instance with an automaton, or a mode component's mode automaton. */
export const AutomatonEntry = Type.Object({
    /** The instance path (`ctrl`, `unit.ctrl`). */
    instancePath: Type.String(),
    /** Its ROS node (`/toast_service_robot/ctrl`), the `node` of `/maa/transitions` and the key of `/maa/automaton_states`. */
    node: Type.String({ pattern: '^/' }),
    /** Qualified name of the component type. */
    component: Type.String({ minLength: 1 }),
    /** The component's file, relative to the model root (`toast/Controller.arc`). */
    file: Type.String(),
    states: Type.Array(AutomatonStateEntry),
    transitions: Type.Array(AutomatonTransitionEntry),
    /**
     * `modes`: a decomposed component's mode automaton (states are its modes, transitions its mode
     * transitions in declaration order, the order the generated code tries them); absent: an automaton.
     */
    kind: Type.Optional(Type.Literal('modes')),
});
export type AutomatonEntry = Static<typeof AutomatonEntry>;

export const TopicMapAnswer = Type.Object(
    {
        app: Type.String(),
        platform: Type.String(),
        mode: SimMode,
        ports: Type.Array(PortTopicEntry),
        nodes: Type.Array(InstanceNode),
        /** The automata of the application (absent from an answer of a build generated before the table existed). */
        automata: Type.Optional(Type.Array(AutomatonEntry)),
    },
    { $id: 'urn:maa:protocol:topic-map', title: 'TopicMap', description: 'Port topics of a generated application (GET /api/sim/topics)' },
);
export type TopicMapAnswer = Static<typeof TopicMapAnswer>;
