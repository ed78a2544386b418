/**
 * The automaton instances of the application and their ROS 2 node names, the keys of the states
 * in scenario reports (`/maa/automaton_states`): the generator's rule (generators-python
 * timesync/app-module.ts `liveTopics`): `/<root>/<subcomponent>/...` in ROS names.
 */
import { buildArchitecture, type ComponentView } from '@maa/generator-core';
import { rosName } from '@maa/generators-python/ros-names';
import type { ast } from '@maa/language-adl';
import { type AutomatonFacts, automatonFacts } from './component.js';

export interface AutomatonInstance {
    /** The ROS 2 node name (`/toast_service_robot/controller`). */
    readonly node: string;
    /** Subcomponent names from the application's root. */
    readonly path: readonly string[];
    readonly component: ComponentView;
    readonly facts: AutomatonFacts;
}

/** Every instance of an automaton component below the application's root (none when the architecture cannot be built). */
export function automatonInstances(appRoot: ast.ComponentType | undefined): AutomatonInstance[] {
    if (!appRoot) return [];
    let architecture: ReturnType<typeof buildArchitecture>;
    try {
        architecture = buildArchitecture(appRoot);
    } catch {
        return []; // a model too broken to instantiate: no instances to name
    }
    const rootNs = `/${rosName(architecture.root.name)}`;
    const out: AutomatonInstance[] = [];
    for (const inst of architecture.instances) {
        const facts = inst.component.atomic ? automatonFacts(inst.component) : undefined;
        if (!facts) continue;
        out.push({ node: [rootNs, ...inst.path.map(rosName)].join('/'), path: inst.path, component: inst.component, facts });
    }
    return out;
}

/** The instance a node name of a report is (exact, else by its last segments, for a differently named root). */
export function instanceOfNode(instances: readonly AutomatonInstance[], node: string): AutomatonInstance | undefined {
    const exact = instances.find((i) => i.node === node);
    if (exact) return exact;
    const tail = node.split('/').filter(Boolean).slice(1).join('/');
    return tail ? instances.find((i) => i.path.map(rosName).join('/') === tail) : undefined;
}
