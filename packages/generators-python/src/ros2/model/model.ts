import type { AstNode } from 'langium';
import type { ComponentView, InstanceView } from '@maa/generator-core';
import type { PyImports } from './imports.js';

/**
 * The typed model of a ROS 2 application as ros2.Components generates it: one node per atomic
 * component instance, one mode manager node per instance of a component with a mode automaton,
 * their topics and parameters, and the Python imports of every node file. Built in one pass from
 * the architecture model (build.ts), checked by the topic rules (topic-rules.ts), then rendered:
 * the Python files through the templates in `templates/ros2/`, `deployment.json` by serializing
 * the model (deployment.ts).
 */

/** A ROS topic and its message type (`/robot/sensor/value`, `std_msgs/msg/Int32`). */
export interface TopicRef {
    readonly topic: string;
    readonly type: string;
}

/** How a port's values travel: the ROS type and the `maa_ros2` codec that converts them. */
export interface PortCodec {
    readonly rosType: string;
    /** The `maa_ros2` function that makes the codec. */
    readonly helper: 'std_port' | 'char_port' | 'enum_port' | 'class_port';
    /** A Python expression: `std_port(Int32, int)`, `enum_port(pkg.msg.Color, Color)`. */
    readonly codec: string;
    /** Sampled (primitive) in ports keep their last value between messages. */
    readonly sampled: boolean;
}

/** A port of a node with its topic. */
export interface NodePort extends PortCodec {
    readonly port: string;
    readonly topic: string;
    readonly delayed: boolean;
    readonly node: AstNode;
}

/** A ROS parameter: its value (an enum constant's by ordinal) and, for an enum, the Python enum it converts back to. */
export interface Parameter {
    readonly name: string;
    readonly value: boolean | number | string;
    readonly enumType?: string | undefined;
    /** A floating-point parameter: an integral value is still written with a decimal point. */
    readonly float: boolean;
}

/** The modes of an enclosing mode component a node belongs to (docs/generating-ros2.md, "Mode automata"). */
export interface Gate {
    readonly topic: string;
    readonly modes: readonly string[];
    readonly initial: string;
}

/** A connector declared in modes, relayed by the mode manager in the modes that declare it. */
export interface Relay extends PortCodec {
    readonly source: string;
    readonly target: string;
    readonly modes: string[];
    /** The port of the mode component when the target is one of its out ports. */
    readonly port?: string;
}

/** The Python class a node runs: a behavior generator's, a compute block's, a handwritten one or none. */
export interface BehaviorRef {
    readonly module: string;
    readonly cls: string;
    readonly language?: string | undefined;
}

/** What every generated node has: the instance it runs, its ROS name and its Python module. */
export interface NodeIdentity {
    readonly instance: InstanceView;
    readonly name: string;
    readonly namespace: string;
    readonly fqn: string;
    /** `robot.nodes.unit__ctrl` */
    readonly module: string;
    /** `unit__ctrl`: the console script and the file name. */
    readonly moduleName: string;
    readonly file: string;
    /** The instance path with the root's instance name (`robot.unit.ctrl`). */
    readonly instancePath: string;
    readonly parameters: readonly Parameter[];
    readonly imports: PyImports;
}

/** The node of an atomic component instance. */
export interface ComponentNode extends NodeIdentity {
    readonly kind: 'component';
    readonly component: ComponentView;
    readonly behavior: BehaviorRef;
    readonly inputs: readonly NodePort[];
    readonly outputs: readonly NodePort[];
    /** Topics a handwritten or RobotArm node uses beside its ports. */
    readonly platform: { readonly subscribes: readonly TopicRef[]; readonly publishes: readonly TopicRef[] };
    readonly gates: readonly Gate[];
}

/** The mode manager node of an instance of a component with a mode automaton. */
export interface ModeManagerNode extends NodeIdentity {
    readonly kind: 'manager';
    readonly modeTopic: string;
    readonly inputs: readonly NodePort[];
    readonly relays: readonly Relay[];
}

export interface Ros2Application {
    /** The ament_python package. */
    readonly pkg: string;
    /** The ament_cmake package of the messages. */
    readonly ifacePkg: string;
    /** The namespace of the root instance (`/robot`): in ports of the root are read from `<rootNs>/<port>`. */
    readonly rootNs: string;
    readonly nodes: readonly ComponentNode[];
    readonly managers: readonly ModeManagerNode[];
}

/** The topics a node publishes and reads, for the topic rules and deployment.json. */
export function publishedTopics(n: ComponentNode | ModeManagerNode): Array<TopicRef & { readonly port?: string; readonly node: AstNode }> {
    if (n.kind === 'component') {
        return [
            ...n.outputs.map((o) => ({ port: o.port, topic: o.topic, type: o.rosType, node: o.node })),
            ...n.platform.publishes.map((t) => ({ ...t, node: n.component.node })),
        ];
    }
    const node = n.instance.component.node;
    return [
        { topic: n.modeTopic, type: MODE_TYPE, node },
        ...[...new Map(n.relays.map((r) => [r.target, r])).values()].map((r) => ({
            ...(r.port ? { port: r.port } : {}),
            topic: r.target,
            type: r.rosType,
            node,
        })),
    ];
}

/** The topics a node subscribes to. */
export function subscribedTopics(n: ComponentNode | ModeManagerNode): Array<TopicRef & { readonly port?: string; readonly node: AstNode }> {
    if (n.kind === 'component') {
        return [
            ...n.inputs.map((i) => ({ port: i.port, topic: i.topic, type: i.rosType, node: i.node })),
            ...n.platform.subscribes.map((t) => ({ ...t, node: n.component.node })),
            ...n.gates.map((g) => ({ topic: g.topic, type: MODE_TYPE, node: n.component.node })),
        ];
    }
    const node = n.instance.component.node;
    const relayed = [...new Map(n.relays.map((r) => [r.source, r.rosType])).entries()].filter(
        ([t]) => !n.inputs.some((i) => i.topic === t),
    );
    return [
        ...n.inputs.map((i) => ({ port: i.port, topic: i.topic, type: i.rosType, node: i.node })),
        ...relayed.map(([topic, type]) => ({ topic, type, node })),
    ];
}

/** The message type of mode topics. */
export const MODE_TYPE = 'std_msgs/msg/String';
