/**
 * `deployment.json` (docs/simulation.md "deployment.json"): how `maa-sim` starts a generated
 * ROS 2 application without `launch`. Written by the ros2-python generator next to the launch
 * file, read by `sim-server/src/maa_sim/deployment.py`, which checks this schema (emitted into
 * `maa_sim/protocol.py`) and then the rules a schema cannot say: unique node names, one type and
 * one publisher per topic.
 *
 * `errorMessage` (a keyword validators ignore) is the message a reader shows for a field that
 * breaks its schema; `{key}` stands for the field's name.
 */
import { Type, type Static } from '@sinclair/typebox';
import { DEPLOYMENT_FORMAT } from '../formats.js';
import { AutomatonEntry } from '../topics/schema.js';

export { DEPLOYMENT_FORMAT } from '../formats.js';

/** A ROS node or namespace segment. */
const ROS_SEGMENT = '[A-Za-z][A-Za-z0-9_]*';

/** The simulator's environment variables; a deployment must not set them. */
export const RESERVED_ENV = ['ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE', 'ROS_STATIC_PEERS', 'ROS_LOCALHOST_ONLY'] as const;

const StringList = (field: string) =>
    Type.Array(Type.String({ errorMessage: `${field} must be a list of strings` }), { errorMessage: `${field} must be a list of strings` });

export const PortTopic = Type.Object(
    {
        /** Absolute ROS topic name (`/toast/ctrl/arm`). */
        topic: Type.String({
            pattern: `^/${ROS_SEGMENT}(/${ROS_SEGMENT})*$`,
            errorMessage: 'topic must be an absolute ROS name like /a/b',
        }),
        /** ROS 2 message type (`std_msgs/msg/Int32`; the reader also accepts and normalizes `std_msgs/Int32`). */
        type: Type.String({ minLength: 1, errorMessage: 'type must be a string like std_msgs/msg/Int32' }),
        /** The MontiArc port the topic carries. */
        port: Type.Optional(Type.String({ errorMessage: 'port must be a string' })),
    },
    {
        title: 'PortTopic',
        description: 'A topic of a node with its ROS 2 type and port',
        errorMessage: 'expected an object {topic, type, port}',
    },
);
export type PortTopic = Static<typeof PortTopic>;

const Scalar = Type.Union([Type.Boolean(), Type.Number(), Type.String()]);

/** A ROS parameter: a boolean, number or string, or a non-empty list of one kind. */
export const ParameterValue = Type.Union(
    [
        Scalar,
        Type.Array(Type.Boolean(), { minItems: 1 }),
        Type.Array(Type.Number(), { minItems: 1 }),
        Type.Array(Type.String(), { minItems: 1 }),
    ],
    { errorMessage: 'parameter {key} must be a boolean, number, string or a non-empty list of one of them' },
);
export type ParameterValue = Static<typeof ParameterValue>;

/** A field the simulator sets itself: a deployment must not. */
const SimulatorsOwn = (message: string) => Type.Optional(Type.Never({ errorMessage: message }));

const Topics = Type.Array(PortTopic, { errorMessage: '{key} must be a list of {topic, type, port}' });

/** The fields of a node; {@link NodeRunner} says how it runs. */
export const NodeFields = Type.Object(
    {
        /** ROS node name. */
        name: Type.String({ pattern: `^${ROS_SEGMENT}$`, errorMessage: 'name must be a ROS node name (letters, digits, _)' }),
        /** Absolute namespace (`/`, `/toast`); default `/`. */
        namespace: Type.Optional(
            Type.String({
                pattern: `^/(${ROS_SEGMENT}(/${ROS_SEGMENT})*)?$`,
                errorMessage: 'namespace must be absolute, like / or /toast',
            }),
        ),
        /** Run as `python -m module`. */
        module: Type.Optional(
            Type.String({ pattern: '^[A-Za-z_][A-Za-z0-9_.]*$', errorMessage: 'module must be a dotted Python module name' }),
        ),
        /** Run as an executable (relative to the file, or on PATH). */
        executable: Type.Optional(Type.String({ minLength: 1, errorMessage: 'executable must be a non-empty string' })),
        /** Extra arguments before `--ros-args`. */
        args: Type.Optional(StringList('args')),
        /** ROS parameters; `use_sim_time` is the simulator's. */
        parameters: Type.Optional(
            Type.Intersect(
                [
                    Type.Record(Type.String(), ParameterValue),
                    Type.Object({ use_sim_time: SimulatorsOwn('use_sim_time is set by the simulator') }),
                ],
                { errorMessage: 'parameters must be an object' },
            ),
        ),
        publishes: Type.Optional(Topics),
        subscribes: Type.Optional(Topics),
        /** The instance path (`toastServiceRobot.ctrl`), for reports and the IDE. */
        instance: Type.Optional(Type.String()),
        /** The qualified component type (`toast.Controller`), for reports and the IDE. */
        component: Type.Optional(Type.String()),
    },
    { title: 'DeploymentNode', errorMessage: 'expected an object' },
);

/** Exactly one of `module` and `executable`. */
export const NodeRunner = Type.Union(
    [
        Type.Object({ module: Type.String(), executable: Type.Optional(Type.Never()) }),
        Type.Object({ executable: Type.String(), module: Type.Optional(Type.Never()) }),
    ],
    { errorMessage: 'give exactly one of module and executable' },
);

/** One node of the application. */
export const DeploymentNode = Type.Intersect([NodeFields, NodeRunner]);
export type DeploymentNode = Static<typeof DeploymentNode>;

export const Deployment = Type.Object(
    {
        format: Type.Literal(DEPLOYMENT_FORMAT, { errorMessage: `format must be '${DEPLOYMENT_FORMAT}'` }),
        /** The architecture's qualified name, for display. */
        application: Type.Optional(Type.String()),
        /** The ROS package, for display. */
        package: Type.Optional(Type.String()),
        /** Folders (relative to the file) on the nodes' PYTHONPATH and the simulator's sys.path. */
        python_path: Type.Optional(StringList('python_path')),
        /** Extra environment variables of the nodes (not the simulator's own). */
        env: Type.Optional(
            Type.Intersect(
                [
                    Type.Record(Type.String(), Type.String({ errorMessage: 'env must map names to strings' })),
                    Type.Object({
                        ROS_DOMAIN_ID: SimulatorsOwn('env must not set ROS_DOMAIN_ID (the simulator sets it)'),
                        ROS_AUTOMATIC_DISCOVERY_RANGE: SimulatorsOwn(
                            'env must not set ROS_AUTOMATIC_DISCOVERY_RANGE (the simulator sets it)',
                        ),
                        ROS_STATIC_PEERS: SimulatorsOwn('env must not set ROS_STATIC_PEERS (the simulator sets it)'),
                        ROS_LOCALHOST_ONLY: SimulatorsOwn('env must not set ROS_LOCALHOST_ONLY (the simulator sets it)'),
                    }),
                ],
                { errorMessage: 'env must map names to strings' },
            ),
        ),
        nodes: Type.Array(DeploymentNode, { minItems: 1, errorMessage: 'nodes must be a non-empty list' }),
        /** The automata of the application with their states and transitions (the IDE's GET /api/sim/topics). */
        automata: Type.Optional(Type.Array(AutomatonEntry)),
    },
    {
        $id: 'urn:maa:protocol:deployment',
        title: 'Deployment',
        description: 'deployment.json: how maa-sim starts a generated ROS 2 application (docs/simulation.md)',
        errorMessage: 'expected an object',
    },
);
export type Deployment = Static<typeof Deployment>;
