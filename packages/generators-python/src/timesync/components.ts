import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { AstUtils } from 'langium';
import path from 'node:path';
import type { ComponentGeneratorFactory, ComponentView, DataTypeResult, PortView } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import { Imports, indent, modulePath, pyType, snake, typeBySimpleName, typeRef } from '../behavior/common.js';
import { computeClass } from '../behavior/compute.js';
import { moduleText } from '../behavior/automata.js';
import { PythonTranslator, isTypeDecl, pyName, type Node } from '../python/expressions.js';
import { primitiveOf, rosName } from '../ros2/naming.js';
import { modeClassLines } from './modes.js';

const str = (s: string): string => JSON.stringify(s);

export function componentModule(c: Pick<ComponentView, 'packageName' | 'name'>): { module: string; file: string } {
    return modulePath(c.packageName, snake(c.name));
}

/** The `PORT_TYPES` entry of a port: a data type class, or the model's type name. */
function portType(p: PortView, datatypes: DataTypeResult, imports: Imports): string {
    if (p.type.kind === 'object' && p.type.args.length === 0) {
        const py = pyType(p, datatypes, imports);
        if (!['int', 'float', 'bool', 'str', 'object'].includes(py)) return py;
    }
    return str(p.typeName);
}

/** A translator for expressions evaluated outside a behavior (parameter defaults, subcomponent arguments). */
function configTranslator(datatypes: DataTypeResult, imports: Imports): PythonTranslator {
    return new PythonTranslator({
        name(target, ref) {
            if (target.$type === 'Parameter') return `params[${str(target.name)}]`;
            if (target.$type === 'CDEnumConstant') return `${typeRef(datatypes, imports, target.$container as Node)}.${pyName(target.name)}`;
            if (isTypeDecl(target as Node)) return typeRef(datatypes, imports, target as Node);
            throw new GenerationError(`'${target.name}' cannot be used in a configuration argument`, ref);
        },
        type: (decl) => typeRef(datatypes, imports, decl),
        typeBySimpleName: (name) => typeBySimpleName(datatypes, imports, name)
    });
}

function tuple(xs: readonly string[]): string {
    return xs.length === 0 ? '()' : `(${xs.join(', ')}${xs.length === 1 ? ',' : ''})`;
}

/** The class-level declarations every component type has. */
function typeHeader(c: ComponentView, datatypes: DataTypeResult, imports: Imports, extra: readonly string[] = []): string[] {
    const ins = c.ports.filter((p) => p.direction === 'in');
    const outs = c.ports.filter((p) => p.direction === 'out');
    const tr = configTranslator(datatypes, imports);
    const lines = [
        `    NAME = ${str(c.qualifiedName)}`,
        `    IN_PORTS = ${tuple(ins.map((p) => str(p.name)))}`,
        `    OUT_PORTS = ${tuple(outs.map((p) => str(p.name)))}`,
        `    PORT_TYPES: ClassVar[Mapping[str, object]] = {${c.ports.map((p) => `${str(p.name)}: ${portType(p, datatypes, imports)}`).join(', ')}}`,
        `    PARAMETERS = ${tuple(c.parameters.map((p) => str(p.name)))}`,
        // Generic components name their type parameters: stream tests bind them (`type_args`).
        ...(c.typeParameters.length > 0 ? [`    TYPE_PARAMETERS = ${tuple(c.typeParameters.map(str))}`] : []),
        // A variable component records the feature configuration it was generated in (stream tests check it).
        ...(c.features ? [`    FEATURES: ClassVar[Mapping[str, bool]] = {${Object.entries(c.features).map(([k, v]) => `${str(k)}: ${v ? 'True' : 'False'}`).join(', ')}}`] : []),
        ...extra
    ];
    imports.add('typing', 'ClassVar');
    imports.add('collections.abc', 'Mapping');
    if (c.parameters.some((p) => p.default)) {
        lines.push('', '    @classmethod', '    def defaults(cls, params: Mapping[str, object]) -> dict[str, object]:', '        params = dict(params)');
        for (const p of c.parameters) {
            if (p.default) lines.push(`        params.setdefault(${str(p.name)}, ${tr.expr(p.default as Node)})`);
        }
        lines.push('        return params');
    }
    return lines;
}

/**
 * The handwritten implementation kept next to the model (`<Name>.timesync.py` beside `<Name>.arc`),
 * if any: it is copied into the build on every generation. Without it, a user file is created once.
 */
function handwrittenSource(c: ComponentView): string | undefined {
    const uri = AstUtils.getDocument(c.node).uri;
    if (uri.scheme !== 'file') return undefined;
    const file = path.join(path.dirname(uri.fsPath), `${c.name}.timesync.py`);
    return existsSync(file) ? readFileSync(file, 'utf8') : undefined;
}

/** Reads the files of an RTE package shipped in `rte/<name>/`. */
function rteFiles(packageDir: string, name: string): Array<{ file: string; text: string }> {
    const dir = path.join(packageDir, 'rte', name);
    return readdirSync(dir)
        .filter((f) => f.endsWith('.py') || f === 'py.typed')
        .sort()
        .map((f) => ({ file: `${name}/${f}`, text: readFileSync(path.join(dir, f), 'utf8') }));
}

/** timesync.Components: the hierarchy in one process (maa_timesync), compute blocks, handwritten stubs, entry points. */
const create: ComponentGeneratorFactory = ({ packageDir }) => ({
    kind: 'component',
    async generate(ctx) {
        const datatypes = ctx.datatypes;
        for (const c of ctx.architecture.components) {
            const { file } = componentModule(c);
            const imports = new Imports();
            const classLines: string[] = [];
            if (c.atomic) {
                imports.add('maa_timesync', 'AtomicComponent');
                const delegated = await ctx.behavior(c);
                let behaviorClass: string;
                if (delegated?.handledBy === 'behavior-generator') {
                    const module = String(delegated.result.module);
                    behaviorClass = String(delegated.result.class);
                    imports.add(module, behaviorClass);
                } else if (c.handwritten && !delegated) {
                    // A generated base class plus a user file created once.
                    const base = computeClass(c, datatypes, imports, `${c.name}BehaviorBase`);
                    classLines.push(...base, '', '');
                    const impl = modulePath(c.packageName, `${snake(c.name)}_impl`);
                    behaviorClass = `${c.name}Behavior`;
                    const own = componentModule(c);
                    const source = handwrittenSource(c);
                    if (source !== undefined) ctx.out.file(impl.file).write(source, c.node);
                    else ctx.out.file(impl.file, { userFile: true }).write([
                        `"""Handwritten behavior of ${c.qualifiedName} for the python-timesync platform (written once, never overwritten)."""`,
                        '',
                        'from __future__ import annotations',
                        '',
                        'from collections.abc import Mapping',
                        '',
                        `from ${own.module} import ${c.name}BehaviorBase`,
                        '',
                        '',
                        `class ${behaviorClass}(${c.name}BehaviorBase):`,
                        `    """Implement the component here: \`step\` is called once per time slice (see docs/runtime.md)."""`,
                        '',
                        '    def step(self, inputs: Mapping[str, object]) -> None:',
                        '        super().step(inputs)',
                        ''
                    ].join('\n'), c.node);
                    classLines.push(
                        `def _behavior() -> type[${c.name}BehaviorBase]:`,
                        `    from ${impl.module} import ${behaviorClass}`,
                        '',
                        `    return ${behaviorClass}`,
                        '',
                        ''
                    );
                    behaviorClass = '_behavior()';
                } else {
                    behaviorClass = `${c.name}Behavior`;
                    classLines.push(...computeClass(c, datatypes, imports), '', '');
                }
                const header = typeHeader(c, datatypes, imports, [`    BEHAVIOR = ${behaviorClass}`]);
                classLines.push(
                    `class ${pyName(c.name)}(AtomicComponent):`,
                    `    """Component type ${c.qualifiedName} (generated)."""`,
                    '',
                    ...header
                );
            } else {
                // A mode automaton makes it a ModeComponent (modes.ts).
                const modeLines = modeClassLines(c, datatypes, imports);
                if (!modeLines) imports.add('maa_timesync', 'ComposedComponent');
                imports.add('maa_timesync', 'ComponentType');
                const tr = configTranslator(datatypes, imports);
                const subs: string[] = [];
                for (const s of c.subcomponents) {
                    const sub = ctx.architecture.component(s.type);
                    if (!sub) throw new GenerationError(`unknown component type ${s.type}`, s.node);
                    const subModule = componentModule(sub);
                    const alias = sub.qualifiedName === c.qualifiedName ? pyName(sub.name) : `${pyName(sub.name)}`;
                    if (subModule.module !== componentModule(c).module) imports.add(subModule.module, alias);
                    const args = s.args.map((a, i) => {
                        const arg = a as Node;
                        // A named argument `p = value` (MontiArc's keyword arguments).
                        if (arg.$type === 'AssignmentExpression' && arg.op === '=' && (arg.left as Node).$type === 'NameExpression') {
                            const name = String((arg.left as Node).ref?.$refText);
                            if (!sub.parameters.some((p) => p.name === name)) throw new GenerationError(`${sub.qualifiedName} has no parameter '${name}'`, arg);
                            return `${str(name)}: ${tr.expr(arg.right as Node)}`;
                        }
                        const param = sub.parameters[i];
                        if (!param) throw new GenerationError(`too many arguments for ${sub.qualifiedName}`, a);
                        return `${str(param.name)}: ${tr.expr(arg)}`;
                    });
                    subs.push(`(${str(s.name)}, ${alias}, {${args.join(', ')}}),`);
                }
                const conns = c.connectors.map((k) => {
                    const targets = k.targets.map((t) => `(${str(t.subcomponent ?? '')}, ${str(t.port)})`);
                    return `(${str(k.source.subcomponent ?? '')}, ${str(k.source.port)}, ${tuple(targets)}),`;
                });
                const usesParams = subs.some((l) => l.includes('params['));
                const header = typeHeader(c, datatypes, imports, ['    CONNECTORS = (', ...indent(conns, 8), '    )', ...(modeLines ?? [])]);
                classLines.push(
                    `class ${pyName(c.name)}(${modeLines ? 'ModeComponent' : 'ComposedComponent'}):`,
                    `    """Component type ${c.qualifiedName} (generated)."""`,
                    '',
                    ...header,
                    '',
                    '    @classmethod',
                    `    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:`,
                    ...(usesParams ? [] : ['        del params']),
                    '        return [',
                    ...indent(subs, 12),
                    '        ]'
                );
            }
            const out = ctx.out.file(file);
            out.traced(c.node, () => out.write(moduleText(`Component ${c.qualifiedName} for the python-timesync platform (generated).`, imports, classLines)));
        }

        // The run-time environments, copied so that the build runs with Python alone.
        for (const rte of ['maa_behavior', 'maa_timesync']) {
            for (const { file, text } of rteFiles(packageDir, rte)) ctx.out.file(file).write(text);
        }

        // The application module: root type, enums by name, lock-step factory, stream entry point.
        const root = ctx.architecture.root;
        const rootModule = componentModule(root);
        const imports = new Imports();
                imports.add('maa_timesync.lockstep', 'LockstepApp');
        imports.add('maa_timesync', 'ComponentType');
        imports.add('enum', 'Enum');
        imports.add('collections.abc', 'Mapping');
        const components = ctx.architecture.components.map((c) => {
            const m = componentModule(c);
            const alias = `_${m.module.replace(/\./g, '_')}`;
            imports.add(m.module, `${pyName(c.name)} as ${alias}`);
            return `${str(c.qualifiedName)}: ${alias},`;
        });
        const enums = ctx.architecture.dataTypes.filter((t) => t.kind === 'enum').map((t) => `${str(t.name)}: ${typeRef(datatypes, imports, t.node as unknown as Node)},`);
        // Live values in the simulator's lock-step mode: every port value under its ROS 2 topic name
        // (the ros2 generator's rule), so the IDE sees the same topics in both modes. Primitives travel
        // as their std_msgs type; enums as their constant name and classes as JSON, both in std_msgs/String.
        const rootNs = `/${rosName(root.name)}`;
        const topicType = (p: PortView): string => `std_msgs/msg/${primitiveOf(p.type)?.std ?? 'String'}`;
        const portTopics: string[] = [];
        const nodeNames: string[] = [];
        for (const p of root.ports.filter((x) => x.direction === 'in')) {
            portTopics.push(`${str(p.name)}: (${str(`${rootNs}/${rosName(p.name)}`)}, ${str(topicType(p))}),`);
        }
        // Mode components have a live state too, their mode (under their instance's node path, as on ROS 2).
        for (const inst of ctx.architecture.instances.filter((i) => i.component.atomic || i.component.modes)) {
            const node = [rootNs, ...inst.path.map(rosName)].join('/');
            nodeNames.push(`${str(inst.path.join('.'))}: ${str(node)},`);
            if (!inst.component.atomic) continue;
            for (const p of inst.component.ports.filter((x) => x.direction === 'out')) {
                portTopics.push(`${str(`${inst.path.join('.')}.${p.name}`)}: (${str(`${node}/${rosName(p.name)}`)}, ${str(topicType(p))}),`);
            }
        }
        const app = ctx.out.file('maa_app.py');
        app.write([
            `"""The application ${ctx.platform.application} (${root.qualifiedName}) on the python-timesync platform (generated)."""`,
            '',
            'from __future__ import annotations',
            '',
            ...imports.lines(),
            '',
            `APPLICATION = ${str(ctx.platform.application)}`,
            `ROOT = _${rootModule.module.replace(/\./g, '_')}`,
            'COMPONENTS: dict[str, type[ComponentType]] = {',
            ...indent(components, 4),
            '}',
            'ENUMS: dict[str, type[Enum]] = {',
            ...indent(enums, 4),
            '}',
            '#: Port topics of the lock-step mode (ROS 2 names): "<instance path>.<out port>" of atomic instances',
            '#: and "<in port>" of the root -> (topic, ROS 2 message type).',
            'PORT_TOPICS: dict[str, tuple[str, str]] = {',
            ...indent(portTopics, 4),
            '}',
            '#: ROS 2 node names of the atomic instances and mode components (keys of /maa/automaton_states).',
            'NODE_NAMES: dict[str, str] = {',
            ...indent(nodeNames, 4),
            '}',
            '',
            '',
            'def create_controller(parameters: Mapping[str, object]) -> LockstepApp:',
            '    """The simulator\'s lock-step factory (lockstep.json)."""',
            '    return LockstepApp(ROOT, parameters, PORT_TOPICS, NODE_NAMES)',
            ''
        ].join('\n'), root.node);
        ctx.out.file('lockstep.json').write(`${JSON.stringify({
            format: 'maa-lockstep/1', factory: 'maa_app:create_controller', python_path: ['.'], period: 0.02, parameters: {}
        }, null, 2)}\n`);
    }
});

export default create;
