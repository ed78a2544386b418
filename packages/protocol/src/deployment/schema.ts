/**
 * `deployment.json` (docs/simulation.md "deployment.json"): how `maa-sim` starts a generated
 * ROS 2 application without `launch`. Written by the ros2-python generator next to the launch
 * file, read by `sim-server/src/maa_sim/deployment.py` (which checks the emitted JSON Schema,
 * then the rules a schema cannot say: unique node names, one type and one publisher per topic).
 */
import { Type, type Static } from '@sinclair/typebox';

export const DEPLOYMENT_FORMAT = 'maa-deployment/1';

/** A ROS node or namespace segment. */
const ROS_SEGMENT = '[A-Za-z][A-Za-z0-9_]*';

/** The simulator's environment variables; a deployment must not set them. */
export const RESERVED_ENV = ['ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE', 'ROS_STATIC_PEERS', 'ROS_LOCALHOST_ONLY'] as const;

export const PortTopic = Type.Object({
    /** Absolute ROS topic name (`/toast/ctrl/arm`). */
    topic: Type.String({ pattern: `^/${ROS_SEGMENT}(/${ROS_SEGMENT})*$`, description: 'absolute ROS name like /a/b' }),
    /** ROS 2 message type (`std_msgs/msg/Int32`; `std_msgs/Int32` is accepted and normalized by the reader). */
    type: Type.String({ minLength: 1, description: 'ROS 2 type name like std_msgs/msg/Int32' }),
    /** The MontiArc port the topic carries. */
    port: Type.Optional(Type.String()),
}, { description: 'A topic of a node with its ROS 2 type and port' });
export type PortTopic = Static<typeof PortTopic>;

/** A field the simulator sets itself: a deployment must not. */
const SimulatorsOwn = Type.Optional(Type.Never({ description: 'set by the simulator' }));

const Scalar = Type.Union([Type.Boolean(), Type.Number(), Type.String()]);

/** A ROS parameter: a boolean, number or string, or a non-empty list of one kind. */
export const ParameterValue = Type.Union([
    Scalar,
    Type.Array(Type.Boolean(), { minItems: 1 }),
    Type.Array(Type.Number(), { minItems: 1 }),
    Type.Array(Type.String(), { minItems: 1 }),
], { description: 'a boolean, number or string, or a non-empty list of one kind' });
export type ParameterValue = Static<typeof ParameterValue>;

const NodeCommon = {
    /** ROS node name. */
    name: Type.String({ pattern: `^${ROS_SEGMENT}$`, description: 'a ROS node name (letters, digits, _)' }),
    /** Absolute namespace (`/`, `/toast`). */
    namespace: Type.Optional(Type.String({ pattern: `^/(${ROS_SEGMENT}(/${ROS_SEGMENT})*)?$`, description: 'absolute, like / or /toast' })),
    /** Extra arguments before `--ros-args`. */
    args: Type.Optional(Type.Array(Type.String())),
    /** ROS parameters; `use_sim_time` is the simulator's. */
    parameters: Type.Optional(Type.Intersect([
        Type.Record(Type.String(), ParameterValue),
        Type.Object({ use_sim_time: SimulatorsOwn }),
    ])),
    publishes: Type.Optional(Type.Array(PortTopic)),
    subscribes: Type.Optional(Type.Array(PortTopic)),
    /** The instance path (`toastServiceRobot.ctrl`), for reports and the IDE. */
    instance: Type.Optional(Type.String()),
    /** The qualified component type (`toast.Controller`). */
    component: Type.Optional(Type.String()),
};

/** A node run as `python -m module`. */
export const ModuleNode = Type.Object({
    ...NodeCommon,
    module: Type.String({ pattern: '^[A-Za-z_][A-Za-z0-9_.]*$', description: 'a dotted Python module name' }),
    executable: Type.Optional(Type.Never({ description: 'give exactly one of module and executable' })),
});
/** A node run as an executable (relative to the file, or on PATH). */
export const ExecutableNode = Type.Object({
    ...NodeCommon,
    executable: Type.String({ minLength: 1 }),
    module: Type.Optional(Type.Never({ description: 'give exactly one of module and executable' })),
});

/** One node: exactly one of `module` and `executable`. */
export const DeploymentNode = Type.Union([ModuleNode, ExecutableNode], { description: 'a node: exactly one of module and executable' });
export type DeploymentNode = Static<typeof ModuleNode> | Static<typeof ExecutableNode>;

export const Deployment = Type.Object({
    format: Type.Literal(DEPLOYMENT_FORMAT),
    /** The architecture's qualified name, for display. */
    application: Type.Optional(Type.String()),
    /** The ROS package, for display. */
    package: Type.Optional(Type.String()),
    /** Folders (relative to the file) on the nodes' PYTHONPATH and the simulator's sys.path. */
    python_path: Type.Optional(Type.Array(Type.String())),
    /** Extra environment variables of the nodes (not the simulator's own). */
    env: Type.Optional(Type.Intersect([
        Type.Record(Type.String(), Type.String()),
        Type.Object({
            ROS_DOMAIN_ID: SimulatorsOwn,
            ROS_AUTOMATIC_DISCOVERY_RANGE: SimulatorsOwn,
            ROS_STATIC_PEERS: SimulatorsOwn,
            ROS_LOCALHOST_ONLY: SimulatorsOwn,
        }),
    ])),
    nodes: Type.Array(DeploymentNode, { minItems: 1 }),
}, {
    $id: 'urn:maa:protocol:deployment',
    title: 'maa-sim deployment (deployment.json)',
    description: 'How maa-sim starts a generated ROS 2 application (docs/simulation.md)',
});
export type Deployment = Static<typeof Deployment>;
