import type { ArchitectureModel, ComponentView, InstanceView } from '@maa/generator-core';
import type { ConstantValue } from '@maa/language-adl';
import { rosName, type RosDataTypeResult } from '../naming.js';
import { PyImports } from './imports.js';
import type {
    BehaviorRef,
    ComponentNode,
    Gate,
    ModeManagerNode,
    NodeIdentity,
    NodePort,
    Relay,
    Ros2Application,
    TopicRef,
} from './model.js';
import { instanceParameters, rosParameter } from './parameters.js';
import { codecNames, portCodec } from './ports.js';
import { TopicNames } from './topics.js';

/** The class an atomic component type's nodes run, and the topics it uses beside its ports (handwritten and RobotArm nodes). */
export interface ComponentBehavior extends BehaviorRef {
    readonly platform: { readonly subscribes: readonly TopicRef[]; readonly publishes: readonly TopicRef[] };
}

export interface BuildInput {
    readonly arch: ArchitectureModel;
    readonly dt: RosDataTypeResult;
    /** The ament_python package. */
    readonly pkg: string;
    readonly ifacePkg: string;
    readonly behaviors: ReadonlyMap<ComponentView, ComponentBehavior>;
}

/** The application model: every node and mode manager with its topics, parameters and imports. */
export function buildApplication(input: BuildInput): Ros2Application {
    const builder = new ApplicationBuilder(input);
    return {
        pkg: input.pkg,
        ifacePkg: input.ifacePkg,
        rootNs: builder.topics.rootNs,
        nodes: input.arch.instances.filter((i) => i.component.atomic).map((i) => builder.componentNode(i)),
        managers: input.arch.instances.filter((i) => i.component.modes).map((i) => builder.modeManager(i)),
    };
}

class ApplicationBuilder {
    readonly topics: TopicNames;
    private readonly params: Map<InstanceView, Map<string, ConstantValue>>;
    private readonly rootInstance: string;

    constructor(private readonly input: BuildInput) {
        this.topics = new TopicNames(input.arch);
        this.params = instanceParameters(input.arch);
        const rootName = input.arch.root.name;
        this.rootInstance = rootName.charAt(0).toLowerCase() + rootName.slice(1);
    }

    /** Name, module, file and parameters of the node of `inst` (module `moduleName` in `<pkg>.nodes`). */
    private identity(
        inst: InstanceView,
        name: string,
        namespace: string,
        fqn: string,
        moduleName: string,
        imports: PyImports,
    ): NodeIdentity {
        const { pkg, dt } = this.input;
        const values = this.params.get(inst)!;
        return {
            instance: inst,
            name,
            namespace,
            fqn,
            moduleName,
            imports,
            module: `${pkg}.nodes.${moduleName}`,
            file: `${pkg}/${pkg}/nodes/${moduleName}.py`,
            instancePath: [this.rootInstance, ...inst.path].join('.'),
            parameters: inst.component.parameters.map((p) => rosParameter(p, values.get(p.name)!, dt, imports)),
        };
    }

    /** The in ports of `inst` that a connector chain feeds, with their topics. */
    private inputs(inst: InstanceView, imports: PyImports): NodePort[] {
        const inputs: NodePort[] = [];
        for (const p of inst.component.ports.filter((x) => x.direction === 'in')) {
            const codec = portCodec(p, this.input.dt, imports);
            const topic = this.topics.sourceTopic(inst, { port: p.name });
            if (topic) inputs.push({ port: p.name, topic, ...codec, delayed: false, node: p.node });
        }
        return inputs;
    }

    componentNode(inst: InstanceView): ComponentNode {
        const c = inst.component;
        const behavior = this.input.behaviors.get(c)!;
        const gates = this.gates(inst);
        // the run-time names first: a model type of the same name is imported under an alias
        const imports = new PyImports().add(behavior.module, behavior.cls);
        imports.addAll('maa_ros2', ['ComponentNode', 'InPort', 'OutPort', 'run_node']);
        if (gates.length > 0) imports.add('maa_ros2', 'ModeGate');
        const { name, namespace } = this.topics.nodeOf(inst);
        const moduleName = inst.path.length === 0 ? rosName(this.input.arch.root.name) : inst.path.map(rosName).join('__');
        // Codecs in port declaration order (the imports do not depend on it, the lists keep it).
        const inputs = this.inputs(inst, imports);
        const outputs: NodePort[] = c.ports
            .filter((p) => p.direction === 'out')
            .map((p) => ({
                port: p.name,
                topic: this.topics.outTopic(inst, p.name),
                ...portCodec(p, this.input.dt, imports),
                sampled: false,
                delayed: p.delayed,
                node: p.node,
            }));
        const identity = this.identity(inst, name, namespace, this.topics.fqnOf(inst), moduleName, imports);
        imports.addAll('maa_ros2', codecNames([...inputs, ...outputs]));
        return { ...identity, kind: 'component', component: c, behavior, inputs, outputs, platform: behavior.platform, gates };
    }

    /** The modes of enclosing mode components in which the node of `inst` is active. */
    private gates(inst: InstanceView): Gate[] {
        const gates: Gate[] = [];
        for (let k = 0; k < inst.path.length; k++) {
            const ancestor = this.topics.instance(inst.path.slice(0, k))!;
            const m = ancestor.component.modes;
            const modes = m?.modes.filter((x) => x.subcomponents.includes(inst.path[k]!)).map((x) => x.name) ?? [];
            if (m && modes.length > 0) gates.push({ topic: this.topics.modeTopic(ancestor), modes, initial: m.initial });
        }
        return gates;
    }

    modeManager(inst: InstanceView): ModeManagerNode {
        // the run-time names first: a model type of the same name is imported under an alias
        const imports = new PyImports().add('collections.abc', 'Mapping');
        imports.addAll('maa_ros2', ['InPort', 'ModeManagerNode', 'Relay', 'run_node']);
        const inputs = this.inputs(inst, imports);
        const relays = this.relays(inst, imports);
        const base = inst.path.length === 0 ? '' : `${inst.path.map(rosName).join('__')}__`;
        const identity = this.identity(
            inst,
            'maa_modes',
            this.topics.fqnOf(inst),
            this.topics.managerFqn(inst),
            `${base}maa_modes`,
            imports,
        );
        imports.addAll('maa_ros2', codecNames([...inputs, ...relays]));
        return { ...identity, kind: 'manager', modeTopic: this.topics.modeTopic(inst), inputs, relays };
    }

    /** The connectors of the modes of `inst`, one relay per source and target with the modes that declare it. */
    private relays(inst: InstanceView, imports: PyImports): Relay[] {
        const c = inst.component;
        const relays: Relay[] = [];
        for (const mode of c.modes!.modes) {
            for (const k of mode.connectors) {
                const source = this.topics.sourceTopic(inst, { sub: k.source.subcomponent, port: k.source.port });
                if (!source) continue;
                for (const t of k.targets) {
                    const port = t.subcomponent
                        ? this.topics.instance([...inst.path, t.subcomponent])?.component.ports.find((x) => x.name === t.port)
                        : c.ports.find((x) => x.name === t.port);
                    if (!port) continue;
                    const target = this.topics.relayTopic(inst, t.subcomponent, t.port);
                    const known = relays.find((r) => r.source === source && r.target === target);
                    if (known) known.modes.push(mode.name);
                    else
                        relays.push({
                            source,
                            target,
                            ...portCodec(port, this.input.dt, imports),
                            modes: [mode.name],
                            ...(t.subcomponent ? {} : { port: t.port }),
                        });
                }
            }
        }
        return relays;
    }
}
