/**
 * Port topics ↔ port paths (docs/ide.md "Live values", docs/generating-ros2.md "Topics"): the out
 * port `arm` of instance `ctrl` of root `ToastServiceRobot` is `/toast_service_robot/ctrl/arm`,
 * every segment spelled by the ROS 2 generator's own `rosName`. An in port of the root is
 * `/<root>/<port>`. Snake case loses the original spelling (`armCmd` → `arm_cmd`), so the
 * inverse mapping uses the port paths the diagram knows when they are given and falls back to
 * the snake-case segments otherwise. Pure functions, no DOM.
 */
import { rosName } from '@maa/generators-python/ros-names';

/** The topic namespace of an application's root: `toast.ToastServiceRobot` → `/toast_service_robot`. */
export function rootNamespace(rootComponent: string): string {
    const simple = rootComponent.split('.').pop() ?? rootComponent;
    return `/${rosName(simple)}`;
}

/** The topic of a port path (`ctrl.arm` → `/toast_service_robot/ctrl/arm`; `distance` → `/toast_service_robot/distance`). */
export function portPathToTopic(rootComponent: string, portPath: string): string {
    const segs = portPath.split('.').filter((s) => s.length > 0);
    return `${rootNamespace(rootComponent)}/${segs.map(rosName).join('/')}`;
}

/** The node path of an instance path (`ctrl` → `/toast_service_robot/ctrl`; `""` → the root namespace). */
export function instancePathToNode(rootComponent: string, instancePath: string): string {
    const segs = instancePath.split('.').filter((s) => s.length > 0);
    return [rootNamespace(rootComponent), ...segs.map(rosName)].join('/');
}

/** Builds the inverse of {@link portPathToTopic} over known port paths (first spelling wins). */
export function topicIndex(rootComponent: string, knownPortPaths: Iterable<string>): Map<string, string> {
    const map = new Map<string, string>();
    for (const p of knownPortPaths) {
        const t = portPathToTopic(rootComponent, p);
        if (!map.has(t)) map.set(t, p);
    }
    return map;
}

export interface PortTopic {
    topic: string;
    /** The port path (`ctrl.arm`), or the snake-case spelling when the diagram did not know it. */
    portPath: string;
    /** The instance path (`ctrl`), `""` for a port of the root. */
    instancePath: string;
    /** The port's name (last segment of the port path). */
    port: string;
    /** A port of the root (`/<root>/<port>`), fed from outside: input injection is offered. */
    rootPort: boolean;
}

/**
 * Maps a topic to its port, `undefined` for topics outside the root's namespace (platform topics
 * like `/clock` or `/sensors/distance`, `/maa/automaton_states`). `known` is a
 * {@link topicIndex} of the diagram's port paths.
 */
export function topicToPort(rootComponent: string, topic: string, known?: ReadonlyMap<string, string>): PortTopic | undefined {
    const ns = rootNamespace(rootComponent);
    if (!topic.startsWith(`${ns}/`)) return undefined;
    const segs = topic.slice(ns.length + 1).split('/').filter((s) => s.length > 0);
    if (segs.length === 0) return undefined;
    const portPath = known?.get(`${ns}/${segs.join('/')}`) ?? segs.join('.');
    const parts = portPath.split('.');
    const port = parts.pop()!;
    return { topic, portPath, instancePath: parts.join('.'), port, rootPort: parts.length === 0 };
}

/**
 * Maps a node path of `/maa/automaton_states` (`/toast_service_robot/ctrl`) to the instance path
 * (`ctrl`), using known instance paths for the spelling; `undefined` outside the root's namespace.
 */
export function nodeToInstancePath(rootComponent: string, node: string, knownInstancePaths?: Iterable<string>): string | undefined {
    const ns = rootNamespace(rootComponent);
    const trimmed = node.replace(/\/+$/, '');
    if (trimmed === ns) return '';
    if (!trimmed.startsWith(`${ns}/`)) return undefined;
    const segs = trimmed.slice(ns.length + 1).split('/').filter((s) => s.length > 0);
    if (knownInstancePaths) {
        for (const p of knownInstancePaths) {
            if (instancePathToNode(rootComponent, p) === `${ns}/${segs.join('/')}`) return p;
        }
    }
    return segs.join('.');
}
