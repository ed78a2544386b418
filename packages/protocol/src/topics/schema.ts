/**
 * The port topics of a generated application (`GET /api/sim/topics`): which ROS topic carries
 * which port, read by the backend from what the generator wrote (`deployment.json` of a ros2
 * platform, the `PORT_TOPICS`/`NODE_NAMES` tables of a timesync platform's app module), so the
 * IDE never guesses a port back from a snake-case topic name.
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

export const TopicMapAnswer = Type.Object(
    {
        app: Type.String(),
        platform: Type.String(),
        mode: SimMode,
        ports: Type.Array(PortTopicEntry),
        nodes: Type.Array(InstanceNode),
    },
    { $id: 'urn:maa:protocol:topic-map', title: 'TopicMap', description: 'Port topics of a generated application (GET /api/sim/topics)' },
);
export type TopicMapAnswer = Static<typeof TopicMapAnswer>;
