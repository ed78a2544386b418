/**
 * The simulator's side of the wire (docs/simulation.md): its platform topics (what the generated
 * sensor and actuator components talk to) and its status (`/sim/get_status` over rosbridge, read
 * by the IDE's simulate panel). `sim-server/src/maa_sim/interface.py` builds its topic table from
 * {@link SIMULATOR_TOPICS} (emitted into `maa_sim/protocol.py`).
 */
import { Type, type Static } from '@sinclair/typebox';

export const SimulatorTopic = Type.Object({
    name: Type.String({ pattern: '^/' }),
    type: Type.String(),
    /** Who publishes: `sim` (sensors and state) or `controller` (actuator commands). */
    publisher: Type.Union([Type.Literal('sim'), Type.Literal('controller')]),
    description: Type.String(),
});
export type SimulatorTopic = Static<typeof SimulatorTopic>;

/** The simulator's platform topics, in the order `maa_sim.interface` lists them. */
export const SIMULATOR_TOPICS: readonly SimulatorTopic[] = [
    { name: '/clock', type: 'rosgraph_msgs/msg/Clock', publisher: 'sim', description: 'simulation time' },
    {
        name: '/joint_states',
        type: 'sensor_msgs/msg/JointState',
        publisher: 'sim',
        description: 'base_yaw (rad), lift (m, gripper height), finger_inner and finger_outer (m, half opening)',
    },
    {
        name: '/sensors/distance',
        type: 'std_msgs/msg/Int32',
        publisher: 'sim',
        description: 'distance sensor at the bread holder (mm, 2000 when nothing is in range)',
    },
    {
        name: '/sensors/color',
        type: 'std_msgs/msg/String',
        publisher: 'sim',
        description: 'ToastColor by constant name (WHITE, GOLDEN, BURNT) of what the slot sensor sees',
    },
    {
        name: '/arm/joint_command',
        type: 'sensor_msgs/msg/JointState',
        publisher: 'controller',
        description: 'position targets by name: base_yaw (rad), lift (m); other fields ignored',
    },
    {
        name: '/arm/gripper_command',
        type: 'std_msgs/msg/Float64',
        publisher: 'controller',
        description: 'target opening between the finger pads (m, 0 .. 0.08; 0 closes with limited force)',
    },
    {
        name: '/toaster/command',
        type: 'std_msgs/msg/String',
        publisher: 'controller',
        description: 'ToasterCmd by constant name: START (lever down, heater on) or STOP (lever up)',
    },
];

/** The topic of the automaton states of a run: a JSON object `{node: state}` in a std_msgs/String. */
export const AUTOMATON_STATES_TOPIC = '/maa/automaton_states';

/**
 * The topic of the transitions taken (std_msgs/String, `data` = JSON {@link TransitionEvent}), one
 * message per transition in the period it is taken, on both platforms.
 */
export const TRANSITIONS_TOPIC = '/maa/transitions';

/** A transition taken by the automaton of a node (the `data` of a `/maa/transitions` message). */
export const TransitionEvent = Type.Object(
    {
        /** The node of the automaton's instance (`/toast_service_robot/ctrl`), as on `/maa/automaton_states`. */
        node: Type.String({ pattern: '^/' }),
        /** The state path before the transition (the innermost active state, as on `/maa/automaton_states`). */
        from: Type.String(),
        /** The state path after it. */
        to: Type.String(),
        /** The transition's 0-based position in the automaton's transitions (the automata table's `index`). */
        index: Type.Integer({ minimum: 0 }),
    },
    { $id: 'urn:maa:protocol:transition-event', title: 'TransitionEvent', description: 'a message of /maa/transitions' },
);
export type TransitionEvent = Static<typeof TransitionEvent>;

/** The topic of RobotArm program steps (std_msgs/String, `data` = JSON {@link ProgramStepEvent}), one message per statement started. */
export const PROGRAM_STEPS_TOPIC = '/maa/program_steps';

/** A RobotArm program starting one of its statements (the `data` of a `/maa/program_steps` message). */
export const ProgramStepEvent = Type.Object(
    {
        node: Type.String({ pattern: '^/' }),
        /** The program's name. */
        program: Type.String(),
        /** The statement's 0-based index in the program. */
        step: Type.Integer({ minimum: 0 }),
        /** Its 1-based line in the program's file. */
        line: Type.Integer({ minimum: 1 }),
        /** Its source, one line (whitespace collapsed). */
        text: Type.String(),
        /** The program's file relative to the model root (`toast/ArmController.arc`). */
        file: Type.Optional(Type.String()),
    },
    { $id: 'urn:maa:protocol:program-step-event', title: 'ProgramStepEvent', description: 'a message of /maa/program_steps' },
);
export type ProgramStepEvent = Static<typeof ProgramStepEvent>;

/** A breakpoint of a lock-step run: a state entered, or a transition taken (state names or paths). */
export const Breakpoint = Type.Union([
    Type.Object({ node: Type.String({ pattern: '^/' }), state: Type.String({ minLength: 1 }) }, { additionalProperties: false }),
    Type.Object(
        { node: Type.String({ pattern: '^/' }), from: Type.String({ minLength: 1 }), to: Type.String({ minLength: 1 }) },
        { additionalProperties: false },
    ),
]);
export type Breakpoint = Static<typeof Breakpoint>;

/** The request of the rosbridge service `/sim/set_breakpoints`: the whole set (an empty list clears them). */
export const SetBreakpoints = Type.Object(
    { breakpoints: Type.Array(Breakpoint, { maxItems: 1000 }) },
    {
        $id: 'urn:maa:protocol:set-breakpoints',
        title: 'SetBreakpoints',
        description: 'the request of /sim/set_breakpoints',
        additionalProperties: false,
    },
);
export type SetBreakpoints = Static<typeof SetBreakpoints>;

/** `/sim/get_status` (docs/simulation.md "Services"). */
export const SimulatorStatus = Type.Object(
    {
        /** `lockstep` or `ros2`. */
        mode: Type.String(),
        /** Simulated seconds (the clock). */
        time: Type.Number(),
        world_time: Type.Number(),
        paused: Type.Boolean(),
        /** Simulated seconds per wall second; 0 = as fast as possible. */
        speed: Type.Number({ minimum: 0 }),
        real_time_factor: Type.Number(),
        periods: Type.Integer({ minimum: 0 }),
        period: Type.Number(),
        toast_level: Type.Number(),
        toast_on_plate: Type.Boolean(),
        /** Why the run finished (`goal reached`, `time limit`), null while it runs. */
        finished: Type.Union([Type.String(), Type.Null()]),
        /** `[done, asked]` while a /sim/step runs. */
        stepping: Type.Union([Type.Array(Type.Integer()), Type.Null()]),
        domain_id: Type.Union([Type.Integer(), Type.Null()]),
        nodes: Type.Array(Type.Record(Type.String(), Type.Unknown())),
        /** Node → active state (the latched `/maa/automaton_states`). */
        automaton_states: Type.Record(Type.String(), Type.String()),
        /** The breakpoint the run paused at (until it resumes, steps or resets); null otherwise. */
        breakpoint: Type.Optional(Type.Union([Breakpoint, Type.Null()])),
        events: Type.Array(Type.Record(Type.String(), Type.Unknown())),
        rosbridge: Type.Union([Type.String(), Type.Null()]),
        viser: Type.Union([Type.String(), Type.Null()]),
    },
    { $id: 'urn:maa:protocol:simulator-status', title: 'SimulatorStatus', description: 'the answer of /sim/get_status' },
);
export type SimulatorStatus = Static<typeof SimulatorStatus>;
