import { chainSource, feedingSource, type ChainGraph, type PortEnd } from '@maa/language-adl';
import type { ArchitectureModel, ConnectorView, InstanceView, PortRef } from '@maa/generator-core';
import { rosName } from '../ros-names.js';

/**
 * ROS names of an architecture's instances and the topics of their ports: a node per atomic
 * instance named by its instance path (`/robot/unit/ctrl`), a topic per out port
 * (`/robot/unit/ctrl/value`), a mode manager per mode component (`<instance>/maa_modes`) that
 * relays the connectors of modes to topics of their own, and an in port reads the topic at the
 * end of its connector chain (the shared walk of `@maa/language-adl`).
 */
export class TopicNames {
    readonly rootNs: string;
    private readonly byPath: ReadonlyMap<string, InstanceView>;
    private readonly graph: ChainGraph<InstanceView, string>;

    constructor(private readonly arch: ArchitectureModel) {
        this.rootNs = `/${rosName(arch.root.name)}`;
        this.byPath = new Map(arch.instances.map((i) => [i.path.join('.'), i]));
        this.graph = {
            child: (inst, sub) => this.byPath.get([...inst.path, sub].join('.')),
            parent: (inst) =>
                inst.path.length === 0 ? undefined : { scope: this.parentOf(inst)!, name: inst.path[inst.path.length - 1]! },
            isAtomic: (inst) => inst.component.atomic,
            feeder: (inst, target) => {
                if (feedingSource(modeConnectors(inst).map(portEnds), target))
                    return { stop: this.relayTopic(inst, target.sub, target.port) };
                const source = feedingSource(inst.component.connectors.map(portEnds), target);
                return source ? { source } : undefined;
            },
        };
    }

    instance(path: readonly string[]): InstanceView | undefined {
        return this.byPath.get(path.join('.'));
    }

    parentOf(inst: InstanceView): InstanceView | undefined {
        return inst.path.length === 0 ? undefined : this.instance(inst.path.slice(0, -1));
    }

    /** The node name and namespace of an instance's node (the root's node is in `/`). */
    nodeOf(inst: InstanceView): { name: string; namespace: string } {
        if (inst.path.length === 0) return { name: rosName(this.arch.root.name), namespace: '/' };
        return {
            name: rosName(inst.path[inst.path.length - 1]!),
            namespace: [this.rootNs, ...inst.path.slice(0, -1).map(rosName)].join('/'),
        };
    }

    fqnOf(inst: InstanceView): string {
        const n = this.nodeOf(inst);
        return `${n.namespace === '/' ? '' : n.namespace}/${n.name}`;
    }

    outTopic(inst: InstanceView, port: string): string {
        return `${this.fqnOf(inst)}/${rosName(port)}`;
    }

    managerFqn(inst: InstanceView): string {
        return `${this.fqnOf(inst)}/maa_modes`;
    }

    modeTopic(inst: InstanceView): string {
        return `${this.managerFqn(inst)}/mode`;
    }

    /** The topic a mode manager relays a connector of its modes to: `<manager>/<sub>/<port>`, or the instance's out port topic. */
    relayTopic(inst: InstanceView, sub: string | undefined, port: string): string {
        return sub ? `${this.managerFqn(inst)}/${rosName(sub)}/${rosName(port)}` : `${this.fqnOf(inst)}/${rosName(port)}`;
    }

    /**
     * The topic that `end` (a subcomponent's out port, or an in port of `inst`) carries: an atomic
     * instance's out port, a mode manager's relay, or a root in port (fed from outside);
     * undefined when no connector feeds it.
     */
    sourceTopic(inst: InstanceView, end: PortEnd): string | undefined {
        const found = chainSource(this.graph, inst, end);
        if (!found) return undefined;
        if (found.kind === 'stop') return found.stop;
        return found.kind === 'atomic' ? this.outTopic(found.scope, found.port) : `${this.rootNs}/${rosName(found.port)}`;
    }
}

/** The connectors declared in the modes of a mode component (relayed by its mode manager). */
export function modeConnectors(inst: InstanceView): ConnectorView[] {
    return inst.component.modes?.modes.flatMap((m) => [...m.connectors]) ?? [];
}

function portEnd(ref: PortRef): PortEnd {
    return { sub: ref.subcomponent, port: ref.port };
}

function portEnds(c: ConnectorView): { source: PortEnd; targets: PortEnd[] } {
    return { source: portEnd(c.source), targets: c.targets.map(portEnd) };
}
