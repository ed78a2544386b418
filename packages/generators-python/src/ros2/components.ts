import { GenerationError } from '@maa/generator-core/node';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { AstUtils, type AstNode } from 'langium';
import type { SymType } from '@maa/language-adl';
import { sourceText, type ComponentGenerationContext, type ComponentGeneratorFactory, type ComponentView,
    type ConnectorView, type InstanceView, type PortView
} from '@maa/generator-core';
import { behaviorModule, moduleText } from '../behavior/automata.js';
import { Imports } from '../behavior/common.js';
import { computeClass } from '../behavior/compute.js';
import { modeTransitionBody } from '../timesync/modes.js';
import { MODEL_PACKAGE, interfacePackageName, isBuiltinDecl, isRosDataTypeResult, primitiveOf, rosName, rosPackageName, typeKey, type RosDataTypeResult } from './naming.js';

/**
 * ros2.Components: one rclpy node per atomic component instance (the hierarchy flattened; the
 * instance path names the node), every connector chain from a source port to its targets one
 * topic with exactly one publisher, parameters from configuration arguments, an ament_python
 * package (package.xml format 3, setup.py, setup.cfg, resource/<pkg>, console scripts), a
 * launch file (launch_ros) and `deployment.json` for tools without `launch` (the simulator).
 * Behavior classes come from the behavior generators (maa_behavior); `<<handwritten>>`
 * components get a generated base class and a user file created once.
 *
 * Output (platform folder):
 *   <pkg>/                       the ament_python package (deployment.json at its top)
 *   <pkg>_interfaces/            ros2.DataTypes' ament_cmake package
 */

interface TopicRef {
    readonly topic: string;
    readonly type: string;
}

interface NodePort {
    readonly port: string;
    readonly topic: string;
    readonly rosType: string;
    readonly codec: string;
    readonly sampled: boolean;
    readonly delayed: boolean;
    readonly node: AstNode;
}

/** A ROS parameter: its value (an enum constant's by ordinal) and, for an enum, the Python enum it converts back to. */
interface ParameterSpec {
    readonly name: string;
    readonly value: boolean | number | string;
    readonly enumType?: string | undefined;
    readonly float: boolean;
}

/** What every generated node has: the instance it runs, its ROS name and its Python module. */
interface NodeIdentity {
    readonly instance: InstanceView;
    readonly name: string;
    readonly namespace: string;
    readonly fqn: string;
    readonly module: string;
    readonly moduleName: string;
    readonly file: string;
}

interface NodeSpec extends NodeIdentity {
    readonly component: ComponentView;
    readonly inputs: NodePort[];
    readonly outputs: NodePort[];
    readonly parameters: ParameterSpec[];
    readonly platformSubscribes: TopicRef[];
    readonly platformPublishes: TopicRef[];
    /** The modes of enclosing mode components this node belongs to (docs/generating-ros2.md, "Mode automata"). */
    readonly gates: Array<{ topic: string; modes: string[]; initial: string }>;
}

/** The mode manager node of an instance of a component with a mode automaton. */
interface ManagerSpec extends NodeIdentity {
    readonly modeTopic: string;
    readonly inputs: NodePort[];
    readonly relays: Array<{ source: string; target: string; rosType: string; codec: string; modes: string[]; port?: string }>;
    readonly parameters: ParameterSpec[];
    readonly imports: Map<string, Set<string>>;
}

const FLOAT_MARK = '__maa_float__';

const ARM_TOPICS = {
    subscribes: [{ topic: '/joint_states', type: 'sensor_msgs/msg/JointState' }],
    publishes: [{ topic: '/arm/joint_command', type: 'sensor_msgs/msg/JointState' }, { topic: '/arm/gripper_command', type: 'std_msgs/msg/Float64' }]
};

function compare(a: string, b: string): number {
    return a < b ? -1 : a > b ? 1 : 0;
}

/** Reads the files of an RTE package shipped in `rte/<name>/`. */
function rteFiles(packageDir: string, name: string): Array<{ file: string; text: string }> {
    const dir = path.join(packageDir, 'rte', name);
    return readdirSync(dir)
        .filter((f) => f.endsWith('.py') || f === 'py.typed')
        .sort()
        .map((f) => ({ file: `${name}/${f}`, text: readFileSync(path.join(dir, f), 'utf8') }));
}

/** The model file of a component, for user files that live next to the model. */
function modelFile(node: AstNode): string | undefined {
    const uri = AstUtils.getDocument(node).uri;
    return uri.scheme === 'file' ? uri.fsPath : undefined;
}

/** `SUBSCRIBES = {"/t": "pkg/msg/T", ...}` and `PUBLISHES = {...}` of a handwritten platform component. */
export function platformTopics(text: string): { subscribes: TopicRef[]; publishes: TopicRef[] } {
    const read = (key: string): TopicRef[] => {
        const m = new RegExp(`^\\s*${key}\\b[^=\\n]*=\\s*\\{([^}]*)\\}`, 'm').exec(text);
        if (!m) return [];
        return [...m[1]!.matchAll(/["']([^"']+)["']\s*:\s*["']([^"']+)["']/g)].map((x) => ({ topic: x[1]!, type: x[2]! }));
    };
    return { subscribes: read('SUBSCRIBES'), publishes: read('PUBLISHES') };
}

/** A literal value of a configuration argument or parameter default (ROS parameters are static). */
function evaluate(expr: AstNode, type: SymType, env: ReadonlyMap<string, boolean | number | string>, ctx: ComponentGenerationContext): boolean | number | string {
    const text = sourceText(expr).trim();
    if (/^-?\d+[lL]?$/.test(text)) return Number(text.replace(/[lL]$/, ''));
    if (/^-?(\d+\.\d*|\.\d+|\d+)([eE][-+]?\d+)?[fFdD]?$/.test(text)) {
        const v = Number(text.replace(/[fFdD]$/, ''));
        return primitiveOf(type)?.py === 'float' && Number.isInteger(v) ? v + 0.0 : v;
    }
    if (text === 'true' || text === 'false') return text === 'true';
    if (/^"([^"\\]|\\.)*"$/.test(text)) return JSON.parse(text) as string;
    if (/^'([^'\\]|\\.)'$/.test(text)) return text.slice(1, -1);
    if (env.has(text)) return env.get(text)!;
    if (type.kind === 'object' && !isBuiltinDecl(type.decl)) {
        const view = ctx.architecture.dataType(typeKey(type));
        const constant = text.split('.').pop() ?? '';
        const index = view?.kind === 'enum' ? view.constants.indexOf(constant) : -1;
        if (index >= 0) return index;
    }
    throw new GenerationError(`ros2.Components needs a literal value here (ROS parameters are static): '${text}'`, expr);
}

/** A Python tuple of strings. */
function pyTuple(xs: readonly string[]): string {
    return xs.length === 0 ? '()' : `(${xs.map((x) => JSON.stringify(x)).join(', ')}${xs.length === 1 ? ',' : ''})`;
}

function isFloatType(t: SymType): boolean {
    return primitiveOf(t)?.py === 'float';
}

function pyLiteral(v: boolean | number | string, float: boolean): string {
    if (typeof v === 'boolean') return v ? 'True' : 'False';
    if (typeof v === 'number') return float && Number.isInteger(v) ? `${v}.0` : String(v);
    return JSON.stringify(v);
}

/**
 * One import block in isort order (ruff `I`): `import m` lines, then `from m import ...` lines, each
 * sorted by module; names: constants, classes, then functions. The name '' stands for `import m`.
 */
export function importLines(imports: ReadonlyMap<string, ReadonlySet<string>>): string[] {
    const modules = [...imports.keys()].sort((a, b) => compare(a.toLowerCase(), b.toLowerCase()));
    const plain = modules.filter((m) => imports.get(m)!.has('')).map((m) => `import ${m}`);
    const rank = (n: string): number => (/^[A-Z0-9_]+$/.test(n) && n.length > 1 ? 0 : /^[A-Z]/.test(n) ? 1 : 2);
    const from = modules
        .map((m) => [m, [...imports.get(m)!].filter((n) => n !== '')] as const)
        .filter(([, names]) => names.length > 0)
        .map(([m, names]) => `from ${m} import ${names.sort((a, b) => rank(a) - rank(b) || compare(a.toLowerCase(), b.toLowerCase()) || compare(a, b)).join(', ')}`);
    return [...plain, ...from];
}

const create: ComponentGeneratorFactory = ({ packageDir }) => ({
    kind: 'component',
    async generate(ctx) {
        if (!isRosDataTypeResult(ctx.datatypes)) {
            throw new GenerationError('ros2.Components needs the message types of ros2.DataTypes (configure ros2.DataTypes in this platform)');
        }
        const dt: RosDataTypeResult = ctx.datatypes;
        const pkg = rosPackageName(ctx.platform);
        const ifacePkg = interfacePackageName(ctx.platform);
        const arch = ctx.architecture;
        const rootName = arch.root.name;
        const rootNs = `/${rosName(rootName)}`;
        const rootInstance = rootName.charAt(0).toLowerCase() + rootName.slice(1);
        const files = new Set<string>();
        const write = (file: string, text: string, element?: AstNode, userFile = false): void => {
            files.add(file);
            ctx.out.file(file, userFile ? { userFile: true } : undefined).write(text, element);
        };

        // ---- types of ports -------------------------------------------------------------------
        const pyImports = new Map<string, Set<string>>();
        const portType = (p: PortView, imports: Map<string, Set<string>>): { rosType: string; codec: string; sampled: boolean } => {
            const add = (module: string, name: string): void => {
                let set = imports.get(module);
                if (!set) imports.set(module, (set = new Set()));
                set.add(name);
            };
            const prim = primitiveOf(p.type);
            if (prim) {
                add('std_msgs.msg', prim.std);
                // A char is its code inside the behavior and a one-character string on the topic.
                const isChar = p.typeName === 'char' || p.typeName === 'Character';
                return { rosType: `std_msgs/msg/${prim.std}`, codec: isChar ? `char_port(${prim.std})` : `std_port(${prim.std}, ${prim.py})`, sampled: true };
            }
            if (p.type.kind === 'object') {
                const msg = dt.messages[typeKey(p.type)];
                const py = dt.types?.[typeKey({ kind: 'object', decl: p.type.decl, args: [] })];
                if (msg && py?.module && py.name) {
                    add(msg.module, '');
                    add(py.module, py.name);
                    const qualified = `${msg.module}.${msg.name}`;
                    const codec = msg.kind === 'enum' ? `enum_port(${qualified}, ${py.name})` : `class_port(${qualified}, ${py.name})`;
                    return { rosType: msg.type, codec, sampled: false };
                }
            }
            throw new GenerationError(`ros2.Components cannot carry port '${p.name}' of type ${p.typeName} on a ROS 2 topic (primitives, enums and non-generic classes can)`, p.node);
        };

        // ---- nodes and topics -------------------------------------------------------------------
        const atomic = arch.instances.filter((i) => i.component.atomic);
        const byPath = new Map(arch.instances.map((i) => [i.path.join('.'), i]));
        const nodeOf = (inst: InstanceView): { name: string; namespace: string } => {
            if (inst.path.length === 0) return { name: rosName(rootName), namespace: '/' };
            return { name: rosName(inst.path[inst.path.length - 1]!), namespace: [rootNs, ...inst.path.slice(0, -1).map(rosName)].join('/') };
        };
        const fqnOf = (inst: InstanceView): string => {
            const n = nodeOf(inst);
            return `${n.namespace === '/' ? '' : n.namespace}/${n.name}`;
        };
        const outTopic = (inst: InstanceView, port: string): string => `${fqnOf(inst)}/${rosName(port)}`;

        // Mode automata: the connectors declared in modes are relayed by the instance's mode manager
        // node, `<instance>/maa_modes`, to topics of their own (the instance's out ports: `<instance>/<port>`).
        const modeConnectors = (inst: InstanceView): ConnectorView[] => inst.component.modes?.modes.flatMap((m) => [...m.connectors]) ?? [];
        const managerFqn = (inst: InstanceView): string => `${fqnOf(inst)}/maa_modes`;
        const modeTopic = (inst: InstanceView): string => `${managerFqn(inst)}/mode`;
        const relayTopic = (inst: InstanceView, sub: string | undefined, port: string): string =>
            sub ? `${managerFqn(inst)}/${rosName(sub)}/${rosName(port)}` : `${fqnOf(inst)}/${rosName(port)}`;

        /** The topic an instance's in port reads: follow the connectors back to an atomic source (or a root in port). */
        const sourceTopic = (inst: InstanceView, port: string, depth = 0): string | undefined => {
            if (depth > 64) return undefined;
            if (inst.path.length === 0) return `${rootNs}/${rosName(port)}`; // an in port of the root: fed from outside
            const parent = byPath.get(inst.path.slice(0, -1).join('.'))!;
            const name = inst.path[inst.path.length - 1]!;
            if (modeConnectors(parent).some((c) => c.targets.some((t) => t.subcomponent === name && t.port === port))) return relayTopic(parent, name, port);
            const conn = parent.component.connectors.find((c) => c.targets.some((t) => t.subcomponent === name && t.port === port));
            if (!conn) return undefined;
            return resolveSource(parent, conn.source.subcomponent, conn.source.port, depth + 1);
        };
        const resolveSource = (inst: InstanceView, sub: string | undefined, port: string, depth: number): string | undefined => {
            if (depth > 64) return undefined;
            if (!sub) return sourceTopic(inst, port, depth + 1); // an in port of the composed component
            const child = byPath.get([...inst.path, sub].join('.'));
            if (!child) return undefined;
            if (child.component.atomic) return outTopic(child, port);
            if (modeConnectors(child).some((c) => c.targets.some((t) => !t.subcomponent && t.port === port))) return relayTopic(child, undefined, port);
            const conn = child.component.connectors.find((c) => c.targets.some((t) => !t.subcomponent && t.port === port));
            return conn ? resolveSource(child, conn.source.subcomponent, conn.source.port, depth + 1) : undefined;
        };

        const behaviors = new Map<ComponentView, { module: string; cls: string; language?: string }>();
        const handwritten = new Map<ComponentView, { subscribes: TopicRef[]; publishes: TopicRef[] }>();
        const behaviorFiles = new Set<string>();
        for (const c of arch.components.filter((x) => x.atomic && atomic.some((i) => i.component === x))) {
            const delegated = await ctx.behavior(c);
            if (c.handwritten) {
                handwritten.set(c, writeHandwritten(c));
                behaviors.set(c, { module: `${pkg}.handwritten.${rosName(c.name)}`, cls: c.name });
            } else if (delegated?.handledBy === 'behavior-generator') {
                const module = String(delegated.result.module);
                const cls = String(delegated.result.class ?? delegated.result.className);
                for (const f of (delegated.result.files as string[] | undefined) ?? []) behaviorFiles.add(f);
                behaviors.set(c, { module, cls, language: delegated.language });
            } else if (delegated?.handledBy === 'component-generator') {
                // compute/init blocks: the shared compute translation, placed like a behavior generator's module
                const imports = new Imports();
                const cls = computeClass(c, dt, imports);
                const { module, file } = behaviorModule(c.packageName, c.name);
                const target = `${pkg}/${pkg}/${MODEL_PACKAGE}/${file}`;
                behaviorFiles.add(file);
                files.add(target);
                const out = ctx.out.file(target);
                out.traced(delegated.behavior.node, () => out.write(moduleText(`Behavior of ${c.qualifiedName}: its compute block (generated by ros2.Components).`, imports, cls)));
                behaviors.set(c, { module: `${pkg}.${MODEL_PACKAGE}.${module}`, cls: `${c.name}Behavior` });
            } else {
                behaviors.set(c, { module: 'maa_behavior', cls: 'NoBehavior' });
            }
        }

        function writeHandwritten(c: ComponentView): { subscribes: TopicRef[]; publishes: TopicRef[] } {
            const ins = c.ports.filter((p) => p.direction === 'in');
            const outs = c.ports.filter((p) => p.direction === 'out');
            const typeImports = new Map<string, Set<string>>();
            const annotations = new Map<string, string>();
            for (const p of c.ports) {
                const prim = primitiveOf(p.type);
                if (prim) annotations.set(p.name, prim.py);
                else {
                    const py = p.type.kind === 'object' ? dt.types?.[typeKey({ kind: 'object', decl: p.type.decl, args: [] })] : undefined;
                    if (!py?.module || !py.name) throw new GenerationError(`port type ${p.typeName} has no Python type`, p.node);
                    if (p.direction === 'out') {
                        let set = typeImports.get(py.module);
                        if (!set) typeImports.set(py.module, (set = new Set()));
                        set.add(py.name);
                    }
                    annotations.set(p.name, py.name);
                }
            }
            const tuple = (xs: readonly PortView[]): string => (xs.length === 0 ? '()' : `(${xs.map((p) => JSON.stringify(p.name)).join(', ')}${xs.length === 1 ? ',' : ''})`);
            const base = `${pkg}/${pkg}/handwritten/${rosName(c.name)}_base.py`;
            const text = ctx.templates.render('handwritten_base.py.njk', {
                c,
                timing: c.behavior?.timing ?? 'sync',
                inPorts: tuple(ins),
                outPorts: tuple(outs),
                delayed: outs.filter((p) => p.delayed).map((p) => JSON.stringify(p.name)),
                outs: outs.map((p) => ({ name: p.name, method: `send_${rosName(p.name)}`, type: annotations.get(p.name), node: p.node })),
                ins: ins.map((p) => ({ name: p.name, type: annotations.get(p.name) })),
                typeImports: importLines(new Map([...typeImports, ['maa_ros2', new Set(['PlatformBehavior'])]]))
            });
            files.add(base);
            ctx.out.file(base).write(text, c.node);
            // The user file: the model root's `<package>/<Name>.ros2.py` when there is one, else a stub.
            const model = modelFile(c.node);
            const provided = model ? path.join(path.dirname(model), `${c.name}.ros2.py`) : undefined;
            const userText = provided && existsSync(provided)
                ? readFileSync(provided, 'utf8')
                : ctx.templates.render('handwritten_user.py.njk', { c, pkg, base: `${pkg}.handwritten.${rosName(c.name)}_base` });
            write(`${pkg}/${pkg}/handwritten/${rosName(c.name)}.py`, userText, c.node, true);
            return platformTopics(userText);
        }

        // Parameters of every instance: its arguments (positional, then `key = value`), else the
        // defaults; arguments may name the enclosing instance's parameters.
        const instanceParams = new Map<InstanceView, Map<string, boolean | number | string>>();
        for (const inst of arch.instances) {
            const c = inst.component;
            const parent = inst.path.length > 0 ? byPath.get(inst.path.slice(0, -1).join('.')) : undefined;
            const env = (parent && instanceParams.get(parent)) ?? new Map<string, boolean | number | string>();
            const given = new Map<string, AstNode>();
            inst.args.forEach((arg, i) => {
                const a = arg as AstNode & { op?: string; left?: AstNode & { ref?: { $refText?: string } }; right?: AstNode };
                if (a.$type === 'AssignmentExpression' && a.op === '=' && a.left && a.right) given.set(a.left.ref?.$refText ?? sourceText(a.left), a.right);
                else if (c.parameters[i]) given.set(c.parameters[i]!.name, arg);
            });
            const values = new Map<string, boolean | number | string>();
            for (const p of c.parameters) {
                const arg = given.get(p.name);
                const expr = arg ?? p.default;
                if (!expr) throw new GenerationError(`parameter '${p.name}' of ${c.qualifiedName} has no value`, inst.node ?? p.node);
                values.set(p.name, evaluate(expr, p.type, arg ? env : values, ctx));
            }
            instanceParams.set(inst, values);
        }

        /** A ROS parameter of a node or mode manager: its value (an enum's by ordinal) and the enum type to convert it back to. */
        const parameterSpec = (p: ComponentView['parameters'][number], value: boolean | number | string, imports: Map<string, Set<string>>): ParameterSpec => {
            const enumType = p.type.kind === 'object' && !primitiveOf(p.type) ? dt.types?.[typeKey(p.type)] : undefined;
            if (enumType?.module && enumType.name) {
                let set = imports.get(enumType.module);
                if (!set) imports.set(enumType.module, (set = new Set()));
                set.add(enumType.name);
            }
            return { name: p.name, value, enumType: enumType?.name, float: isFloatType(p.type) };
        };

        const nodes: NodeSpec[] = [];
        for (const inst of atomic) {
            const c = inst.component;
            const { name, namespace } = nodeOf(inst);
            const moduleName = inst.path.length === 0 ? rosName(rootName) : inst.path.map(rosName).join('__');
            const imports = new Map<string, Set<string>>();
            const inputs: NodePort[] = [];
            const outputs: NodePort[] = [];
            for (const p of c.ports) {
                const t = portType(p, imports);
                if (p.direction === 'in') {
                    const topic = sourceTopic(inst, p.name);
                    if (topic) inputs.push({ port: p.name, topic, ...t, delayed: false, node: p.node });
                } else {
                    outputs.push({ port: p.name, topic: outTopic(inst, p.name), ...t, sampled: false, delayed: p.delayed, node: p.node });
                }
            }
            const parameters = c.parameters.map((p) => parameterSpec(p, instanceParams.get(inst)!.get(p.name)!, imports));
            const b = behaviors.get(c)!;
            let set = imports.get(b.module);
            if (!set) imports.set(b.module, (set = new Set()));
            set.add(b.cls);
            const platform = handwritten.get(c) ?? (b.language === 'robotarm' ? ARM_TOPICS : { subscribes: [], publishes: [] });
            const gates: NodeSpec['gates'] = [];
            for (let k = 0; k < inst.path.length; k++) {
                const ancestor = byPath.get(inst.path.slice(0, k).join('.'))!;
                const m = ancestor.component.modes;
                const modes = m?.modes.filter((x) => x.subcomponents.includes(inst.path[k]!)).map((x) => x.name) ?? [];
                if (m && modes.length > 0) gates.push({ topic: modeTopic(ancestor), modes, initial: m.initial });
            }
            nodes.push({
                instance: inst, name, namespace, fqn: fqnOf(inst), module: `${pkg}.nodes.${moduleName}`, moduleName,
                file: `${pkg}/${pkg}/nodes/${moduleName}.py`, component: c, inputs, outputs, parameters,
                platformSubscribes: platform.subscribes, platformPublishes: platform.publishes, gates
            });
            for (const [m, names] of imports) {
                let all = pyImports.get(`${moduleName}|${m}`);
                if (!all) pyImports.set(`${moduleName}|${m}`, (all = new Set()));
                names.forEach((x) => all!.add(x));
            }
        }

        const managers: ManagerSpec[] = [];
        for (const inst of arch.instances.filter((i) => i.component.modes)) {
            const c = inst.component;
            const m = c.modes!;
            const imports = new Map<string, Set<string>>();
            const inputs: NodePort[] = [];
            for (const p of c.ports.filter((x) => x.direction === 'in')) {
                const topic = sourceTopic(inst, p.name);
                if (topic) inputs.push({ port: p.name, topic, ...portType(p, imports), delayed: false, node: p.node });
            }
            const relays: ManagerSpec['relays'] = [];
            for (const mode of m.modes) {
                for (const k of mode.connectors) {
                    const source = resolveSource(inst, k.source.subcomponent, k.source.port, 0);
                    if (!source) continue;
                    for (const t of k.targets) {
                        const port = t.subcomponent ? byPath.get([...inst.path, t.subcomponent].join('.'))?.component.ports.find((x) => x.name === t.port) : c.ports.find((x) => x.name === t.port);
                        if (!port) continue;
                        const target = relayTopic(inst, t.subcomponent, t.port);
                        const known = relays.find((r) => r.source === source && r.target === target);
                        if (known) known.modes.push(mode.name);
                        else relays.push({ source, target, ...portType(port, imports), modes: [mode.name], ...(t.subcomponent ? {} : { port: t.port }) });
                    }
                }
            }
            // The parameters as the regular nodes take them (enums by ordinal, converted back for the guards).
            const parameters = c.parameters.map((p) => parameterSpec(p, instanceParams.get(inst)!.get(p.name)!, imports));
            const base = inst.path.length === 0 ? '' : `${inst.path.map(rosName).join('__')}__`;
            const moduleName = `${base}maa_modes`;
            managers.push({
                instance: inst, name: 'maa_modes', namespace: fqnOf(inst), fqn: managerFqn(inst), module: `${pkg}.nodes.${moduleName}`, moduleName,
                file: `${pkg}/${pkg}/nodes/${moduleName}.py`, modeTopic: modeTopic(inst), inputs, relays, parameters, imports
            });
        }

        // Every topic has exactly one type and at most one publisher.
        const publishers = new Map<string, { fqn: string; node: AstNode }>();
        const types = new Map<string, string>();
        for (const mg of managers) {
            for (const topic of [mg.modeTopic, ...new Set(mg.relays.map((r) => r.target))]) {
                const other = publishers.get(topic);
                if (other) throw new GenerationError(`topic ${topic} would have two publishers, ${other.fqn} and ${mg.fqn}; a topic has exactly one publisher`, mg.instance.component.node);
                publishers.set(topic, { fqn: mg.fqn, node: mg.instance.component.node });
            }
        }
        for (const n of nodes) {
            const pubs = [...n.outputs.map((o) => ({ topic: o.topic, type: o.rosType, node: o.node })), ...n.platformPublishes.map((t) => ({ ...t, node: n.component.node as AstNode }))];
            for (const p of pubs) {
                const other = publishers.get(p.topic);
                if (other) throw new GenerationError(`topic ${p.topic} would have two publishers, ${other.fqn} and ${n.fqn}; a topic has exactly one publisher`, p.node);
                publishers.set(p.topic, { fqn: n.fqn, node: p.node });
            }
            const all = [...pubs, ...n.inputs.map((i) => ({ topic: i.topic, type: i.rosType, node: i.node })), ...n.platformSubscribes.map((t) => ({ ...t, node: n.component.node as AstNode }))];
            for (const t of all) {
                const known = types.get(t.topic);
                if (known && known !== t.type) throw new GenerationError(`topic ${t.topic} would carry two types, ${known} and ${t.type}`, t.node);
                types.set(t.topic, t.type);
            }
        }
        for (const n of nodes) {
            for (const i of n.inputs) {
                if (!publishers.has(i.topic) && !i.topic.startsWith(`${rootNs}/`)) {
                    throw new GenerationError(`in port '${i.port}' of ${n.fqn} reads topic ${i.topic}, which has no publisher`, i.node);
                }
            }
        }

        // ---- files ---------------------------------------------------------------------------
        for (const n of nodes) {
            const own = new Map([...pyImports].filter(([k]) => k.startsWith(`${n.moduleName}|`)).map(([k, names]) => [k.slice(n.moduleName.length + 1), new Set(names)] as const));
            const maa = ['ComponentNode', 'InPort', 'OutPort', 'run_node', ...new Set([...n.inputs, ...n.outputs].map((p) => p.codec.replace(/\(.*$/, '')))];
            if (n.gates.length > 0) maa.push('ModeGate');
            own.set('maa_ros2', new Set([...(own.get('maa_ros2') ?? []), ...maa]));
            const b = behaviors.get(n.component)!;
            const text = ctx.templates.render('node.py.njk', {
                n,
                pkg,
                behavior: b,
                instance: [rootInstance, ...n.instance.path].join('.'),
                imports: importLines(own),
                params: n.parameters.map((p) => ({ name: p.name, literal: pyLiteral(p.value, p.float), enumType: p.enumType })),
                enumParams: n.parameters.filter((p) => p.enumType),
                gates: n.gates.map((g) => ({ topic: g.topic, initial: g.initial, modes: pyTuple(g.modes) }))
            });
            files.add(n.file);
            ctx.out.file(n.file).write(text, n.instance.node ?? n.component.node);
        }
        for (const mg of managers) {
            const c = mg.instance.component;
            const guards = new Imports();
            const body = modeTransitionBody(c, dt, guards, 'maa_ros2.modes');
            guards.add('collections.abc', 'Mapping');
            for (const name of ['InPort', 'ModeManagerNode', 'Relay', 'run_node', ...new Set([...mg.inputs, ...mg.relays].map((p) => p.codec.replace(/\(.*$/, '')))]) guards.add('maa_ros2', name);
            for (const [module, names] of mg.imports) for (const name of names) guards.add(module, name);
            const instance = [rootInstance, ...mg.instance.path].join('.');
            const enumParams = mg.parameters.filter((p) => p.enumType);
            const lines = [
                `"""ROS 2 mode manager of instance ${instance} (${c.qualifiedName}).`,
                '',
                `Generated by ros2.Components. Node ${mg.fqn}: takes the mode transitions, publishes the current mode on`,
                `${mg.modeTopic} (latched) and relays the connectors of the current mode; run it with`,
                `\`ros2 run ${pkg} ${mg.moduleName}\` or \`python -m ${mg.module}\`.`,
                '"""',
                '',
                'from __future__ import annotations',
                '',
                ...guards.lines(),
                '',
                mg.inputs.length ? 'INPUTS = (' : 'INPUTS: tuple[InPort, ...] = ()',
                ...mg.inputs.map((p) => `    InPort(${JSON.stringify(p.port)}, ${JSON.stringify(p.topic)}, ${p.codec}, sampled=${p.sampled ? 'True' : 'False'}),`),
                ...(mg.inputs.length ? [')'] : []),
                '#: The connectors declared in modes: source topic, target topic, the modes that forward.',
                mg.relays.length ? 'RELAYS = (' : 'RELAYS: tuple[Relay, ...] = ()',
                ...mg.relays.map((r) => `    Relay(${JSON.stringify(r.source)}, ${JSON.stringify(r.target)}, ${r.codec}, ${pyTuple(r.modes)}),`),
                ...(mg.relays.length ? [')'] : []),
                ...(mg.parameters.length ? [
                    'PARAMETERS: dict[str, bool | int | float | str] = {',
                    ...mg.parameters.map((p) => `    ${JSON.stringify(p.name)}: ${pyLiteral(p.value, p.float)},`),
                    '}'
                ] : ['PARAMETERS: dict[str, bool | int | float | str] = {}']),
                ...(enumParams.length ? [
                    '',
                    '',
                    'def convert_parameters(values: dict[str, object]) -> dict[str, object]:',
                    '    """Enum parameters travel as their literal\'s ordinal, as for every node."""',
                    ...enumParams.map((p) => `    values[${JSON.stringify(p.name)}] = list(${p.enumType})[int(values[${JSON.stringify(p.name)}])]  # type: ignore[call-overload]`),
                    '    return values'
                ] : []),
                '',
                '',
                'def mode_transition(',
                '    mode: str, trigger: str | None, inputs: Mapping[str, object], params: Mapping[str, object]',
                ') -> str | None:',
                `    """The target of the first enabled transition of ${c.qualifiedName}'s mode automaton from \`mode\`, if any."""`,
                ...body.map((l) => `    ${l}`),
                '',
                '',
                'def create_node() -> ModeManagerNode:',
                '    return ModeManagerNode(',
                `        ${JSON.stringify(mg.name)}, ${JSON.stringify(mg.modeTopic)}, ${JSON.stringify(c.modes!.initial)}, ${JSON.stringify(c.modes!.timing)},`,
                `        mode_transition, INPUTS, RELAYS, PARAMETERS,${enumParams.length ? ' convert_parameters=convert_parameters,' : ''}`,
                '    )',
                '',
                '',
                'def main() -> None:',
                '    run_node(create_node)',
                '',
                '',
                'if __name__ == "__main__":',
                '    main()',
                ''
            ];
            write(mg.file, lines.join('\n'), c.modes!.node);
        }

        // __init__.py of every Python package of the ament package (behavior generators wrote their modules).
        const pyFiles = [...files, ...[...behaviorFiles].map((f) => `${pkg}/${pkg}/${MODEL_PACKAGE}/${f}`)];
        const packages = new Set<string>([`${pkg}/${pkg}`, `${pkg}/${pkg}/nodes`, `${pkg}/${pkg}/${MODEL_PACKAGE}`]);
        if (handwritten.size > 0) packages.add(`${pkg}/${pkg}/handwritten`);
        for (const type of Object.values(dt.types ?? {})) {
            if (type.module) pyFiles.push(`${type.module.replace(/\./g, '/')}.py`.replace(new RegExp(`^${pkg}/`), `${pkg}/${pkg}/`));
        }
        for (const f of pyFiles) {
            const parts = f.split('/');
            for (let i = 3; i < parts.length; i++) packages.add(parts.slice(0, i).join('/'));
        }
        const written = new Set([...behaviorFiles].map((f) => `${pkg}/${pkg}/${MODEL_PACKAGE}/${f}`));
        const pyPackages = [...packages].filter((p) => p.startsWith(`${pkg}/${pkg}`)).sort(compare);
        for (const p of pyPackages) {
            if (written.has(`${p}/__init__.py`)) continue;
            const doc = p === `${pkg}/${pkg}` ? `The ROS 2 nodes of application ${ctx.platform.application} (${arch.root.qualifiedName}), generated by ros2.Components.` : 'Generated package.';
            write(`${p}/__init__.py`, `"""${doc}"""\n`);
        }
        for (const rte of ['maa_behavior', 'maa_ros2']) {
            for (const { file, text } of rteFiles(packageDir, rte)) write(`${pkg}/${file}`, text);
        }

        const pythonPackages = [...pyPackages.map((p) => p.slice(pkg.length + 1).replace(/\//g, '.')), 'maa_behavior', 'maa_ros2'].sort(compare);
        const scripts = [...nodes, ...managers].map((n) => ({ name: n.moduleName, module: n.module }));
        const info = { pkg, ifacePkg, app: ctx.platform.application, root: arch.root.qualifiedName, launch: `${rosName(ctx.platform.application)}.launch.py` };
        write(`${pkg}/package.xml`, ctx.templates.render('package.xml.njk', info), arch.root.node);
        write(`${pkg}/setup.py`, ctx.templates.render('setup.py.njk', { ...info, packages: pythonPackages, scripts }), arch.root.node);
        write(`${pkg}/setup.cfg`, ctx.templates.render('setup.cfg.njk', info));
        write(`${pkg}/resource/${pkg}`, '');
        write(`${pkg}/launch/${info.launch}`, ctx.templates.render('launch.py.njk', {
            ...info,
            nodes: [...nodes, ...managers].map((n) => ({ ...n, executable: n.moduleName, params: n.parameters.map((p) => ({ name: p.name, literal: pyLiteral(p.value, p.float) })) }))
        }), arch.root.node);
        const deployment = {
            format: 'maa-deployment/1',
            application: arch.root.qualifiedName,
            package: pkg,
            python_path: ['.'],
            env: {},
            nodes: [...nodes.map((n) => ({
                name: n.name,
                namespace: n.namespace,
                instance: [rootInstance, ...n.instance.path].join('.'),
                component: n.component.qualifiedName,
                module: n.module,
                args: [],
                parameters: Object.fromEntries(n.parameters.map((p) => [p.name, p.float && typeof p.value === 'number' && Number.isInteger(p.value) ? `${FLOAT_MARK}${p.value}.0` : p.value])),
                subscribes: [
                    ...n.inputs.map((i) => ({ port: i.port, topic: i.topic, type: i.rosType })),
                    ...n.platformSubscribes.map((t) => ({ topic: t.topic, type: t.type })),
                    ...n.gates.map((g) => ({ topic: g.topic, type: 'std_msgs/msg/String' }))
                ],
                publishes: [
                    ...n.outputs.map((o) => ({ port: o.port, topic: o.topic, type: o.rosType })),
                    ...n.platformPublishes.map((t) => ({ topic: t.topic, type: t.type }))
                ]
            })), ...managers.map((mg) => ({
                name: mg.name,
                namespace: mg.namespace,
                instance: [rootInstance, ...mg.instance.path].join('.'),
                component: mg.instance.component.qualifiedName,
                module: mg.module,
                args: [],
                parameters: Object.fromEntries(mg.parameters.map((p) => [p.name, p.float && typeof p.value === 'number' && Number.isInteger(p.value) ? `${FLOAT_MARK}${p.value}.0` : p.value])),
                subscribes: [
                    ...mg.inputs.map((i) => ({ port: i.port, topic: i.topic, type: i.rosType })),
                    ...[...new Map(mg.relays.map((r) => [r.source, r.rosType])).entries()].filter(([t]) => !mg.inputs.some((i) => i.topic === t)).map(([topic, type]) => ({ topic, type }))
                ],
                publishes: [
                    { topic: mg.modeTopic, type: 'std_msgs/msg/String' },
                    ...[...new Map(mg.relays.map((r) => [r.target, r])).values()].map((r) => ({ ...(r.port ? { port: r.port } : {}), topic: r.target, type: r.rosType }))
                ]
            }))]
        };
        // A double parameter keeps its decimal point (`1.0`): rcl would read `1` as an integer and
        // reject it for a parameter the node declares as double.
        const json = JSON.stringify(deployment, null, 2).replace(new RegExp(`"${FLOAT_MARK}(-?\\d+\\.0)"`, 'g'), '$1');
        write(`${pkg}/deployment.json`, `${json}\n`, arch.root.node);
    }
});

export default create;
