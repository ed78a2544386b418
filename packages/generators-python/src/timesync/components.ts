import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { AstUtils } from 'langium';
import path from 'node:path';
import type { ComponentGeneratorFactory, ComponentView, DataTypeResult, PortView } from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import { Imports, modulePath, pyType, snake, typeBySimpleName, typeRef } from '../behavior/common.js';
import { computeClassView } from '../behavior/compute.js';
import { moduleTextOf } from '../behavior/automata.js';
import { PythonTranslator, isTypeDecl, pyName, type Node } from '../python/expressions.js';
import { renderPython, type PythonTemplates } from '../python/templates.js';
import { primitiveOf, rosName } from '../ros2/naming.js';
import { connectorTuple, modesView } from './modes.js';
import type { AppModuleView, ComponentClassesView, SubcomponentView } from './views.js';

/** A rendered class template without its final newline (the module template places it). */
function renderClass<T extends 'behavior/compute.njk' | 'timesync/component.njk'>(template: T, view: PythonTemplates[T]): string {
    return renderPython(template, view).replace(/\n$/, '');
}

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
            if (target.$type === 'CDEnumConstant')
                return `${typeRef(datatypes, imports, target.$container as Node)}.${pyName(target.name)}`;
            if (isTypeDecl(target)) return typeRef(datatypes, imports, target);
            throw new GenerationError(`'${target.name}' cannot be used in a configuration argument`, ref);
        },
        type: (decl) => typeRef(datatypes, imports, decl),
        typeBySimpleName: (name) => typeBySimpleName(datatypes, imports, name),
    });
}

/** The class-level declarations every component type has (templates/timesync/component.njk). */
function typeHeader(
    c: ComponentView,
    datatypes: DataTypeResult,
    imports: Imports,
): Pick<
    ComponentClassesView,
    'className' | 'qualifiedName' | 'inPorts' | 'outPorts' | 'portTypes' | 'parameters' | 'typeParameters' | 'features'
> {
    const header = {
        className: pyName(c.name),
        qualifiedName: c.qualifiedName,
        inPorts: c.ports.filter((p) => p.direction === 'in').map((p) => p.name),
        outPorts: c.ports.filter((p) => p.direction === 'out').map((p) => p.name),
        portTypes: c.ports.map((p) => ({ key: str(p.name), value: portType(p, datatypes, imports) })),
        parameters: c.parameters.map((p) => p.name),
        // Generic components name their type parameters: stream tests bind them (`type_args`).
        typeParameters: c.typeParameters,
        // A variable component records the feature configuration it was generated in (stream tests check it).
        features: c.features ? Object.entries(c.features).map(([k, v]) => ({ key: str(k), value: v ? 'True' : 'False' })) : undefined,
    };
    imports.add('typing', 'ClassVar');
    imports.add('collections.abc', 'Mapping');
    return header;
}

/** The `defaults` classmethod's entries: parameters with a default value. */
function parameterDefaults(c: ComponentView, datatypes: DataTypeResult, imports: Imports): ComponentClassesView['defaults'] {
    const tr = configTranslator(datatypes, imports);
    return c.parameters.flatMap((p) => (p.default ? [{ name: p.name, value: tr.expr(p.default) }] : []));
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
            let view: ComponentClassesView;
            if (c.atomic) {
                imports.add('maa_timesync', 'AtomicComponent');
                const delegated = await ctx.behavior(c);
                let behaviorClass: string | undefined;
                let handwritten: ComponentClassesView['handwritten'];
                let behavior: string;
                if (delegated?.handledBy === 'behavior-generator') {
                    const module = String(delegated.result.module);
                    behavior = String(delegated.result.class);
                    imports.add(module, behavior);
                } else if (c.handwritten && !delegated) {
                    // A generated base class plus a user file created once.
                    const base = `${c.name}BehaviorBase`;
                    behaviorClass = renderClass('behavior/compute.njk', computeClassView(c, datatypes, imports, base));
                    const impl = modulePath(c.packageName, `${snake(c.name)}_impl`);
                    handwritten = { base, module: impl.module, cls: `${c.name}Behavior` };
                    const source = handwrittenSource(c);
                    if (source !== undefined) ctx.out.file(impl.file).write(source, c.node);
                    else
                        ctx.out.file(impl.file, { userFile: true }).write(
                            renderPython('timesync/handwritten.py.njk', {
                                qualifiedName: c.qualifiedName,
                                module: componentModule(c).module,
                                base,
                                className: handwritten.cls,
                            }),
                            c.node,
                        );
                    behavior = '_behavior()';
                } else {
                    behavior = `${c.name}Behavior`;
                    behaviorClass = renderClass('behavior/compute.njk', computeClassView(c, datatypes, imports));
                }
                const header = typeHeader(c, datatypes, imports);
                view = {
                    ...header,
                    behaviorClass,
                    handwritten,
                    base: 'AtomicComponent',
                    atomic: { behavior },
                    composed: undefined,
                    defaults: parameterDefaults(c, datatypes, imports),
                };
            } else {
                // A mode automaton makes it a ModeComponent (modes.ts).
                const modes = modesView(c, datatypes, imports);
                if (!modes) imports.add('maa_timesync', 'ComposedComponent');
                imports.add('maa_timesync', 'ComponentType');
                const tr = configTranslator(datatypes, imports);
                const subcomponents: SubcomponentView[] = [];
                for (const s of c.subcomponents) {
                    const sub = ctx.architecture.component(s.type);
                    if (!sub) throw new GenerationError(`unknown component type ${s.type}`, s.node);
                    const subModule = componentModule(sub);
                    const alias = pyName(sub.name);
                    if (subModule.module !== componentModule(c).module) imports.add(subModule.module, alias);
                    const args = s.args.map((a, i) => {
                        const arg: Node = a;
                        // A named argument `p = value` (MontiArc's keyword arguments).
                        if (arg.$type === 'AssignmentExpression' && arg.op === '=' && arg.left.$type === 'NameExpression') {
                            const name = String(arg.left.ref?.$refText);
                            if (!sub.parameters.some((p) => p.name === name))
                                throw new GenerationError(`${sub.qualifiedName} has no parameter '${name}'`, arg);
                            return { key: str(name), value: tr.expr(arg.right) };
                        }
                        const param = sub.parameters[i];
                        if (!param) throw new GenerationError(`too many arguments for ${sub.qualifiedName}`, a);
                        return { key: str(param.name), value: tr.expr(arg) };
                    });
                    subcomponents.push({ name: s.name, alias, args });
                }
                const usesParams = subcomponents.some((x) => x.args.some((a) => a.value.includes('params[')));
                const header = typeHeader(c, datatypes, imports);
                view = {
                    ...header,
                    behaviorClass: undefined,
                    handwritten: undefined,
                    base: modes ? 'ModeComponent' : 'ComposedComponent',
                    atomic: undefined,
                    composed: { connectors: c.connectors.map(connectorTuple), modes, usesParams, subcomponents },
                    defaults: parameterDefaults(c, datatypes, imports),
                };
            }
            const out = ctx.out.file(file);
            const classes = renderClass('timesync/component.njk', view);
            out.traced(c.node, () =>
                out.write(moduleTextOf(`Component ${c.qualifiedName} for the python-timesync platform (generated).`, imports, classes)),
            );
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
            return { name: c.qualifiedName, alias };
        });
        const enums = ctx.architecture.dataTypes
            .filter((t) => t.kind === 'enum')
            .map((t) => ({ name: t.name, type: typeRef(datatypes, imports, t.node) }));
        // Live values in the simulator's lock-step mode: every port value under its ROS 2 topic name
        // (the ros2 generator's rule), so the IDE sees the same topics in both modes. Primitives travel
        // as their std_msgs type; enums as their constant name and classes as JSON, both in std_msgs/String.
        const rootNs = `/${rosName(root.name)}`;
        const topicType = (p: PortView): string => `std_msgs/msg/${primitiveOf(p.type)?.std ?? 'String'}`;
        const portTopics: AppModuleView['portTopics'][number][] = [];
        const nodeNames: AppModuleView['nodeNames'][number][] = [];
        for (const p of root.ports.filter((x) => x.direction === 'in')) {
            portTopics.push({ key: p.name, topic: `${rootNs}/${rosName(p.name)}`, type: topicType(p) });
        }
        // Mode components have a live state too, their mode (under their instance's node path, as on ROS 2).
        for (const inst of ctx.architecture.instances.filter((i) => i.component.atomic || i.component.modes)) {
            const node = [rootNs, ...inst.path.map(rosName)].join('/');
            nodeNames.push({ path: inst.path.join('.'), node });
            if (!inst.component.atomic) continue;
            for (const p of inst.component.ports.filter((x) => x.direction === 'out')) {
                portTopics.push({ key: `${inst.path.join('.')}.${p.name}`, topic: `${node}/${rosName(p.name)}`, type: topicType(p) });
            }
        }
        ctx.out.file('maa_app.py').write(
            renderPython('timesync/app.py.njk', {
                application: ctx.platform.application,
                rootQualifiedName: root.qualifiedName,
                imports: imports.lines(),
                rootAlias: `_${rootModule.module.replace(/\./g, '_')}`,
                components,
                enums,
                portTopics,
                nodeNames,
            }),
            root.node,
        );
        ctx.out.file('lockstep.json').write(
            `${JSON.stringify(
                {
                    format: 'maa-lockstep/1',
                    factory: 'maa_app:create_controller',
                    python_path: ['.'],
                    period: 0.02,
                    parameters: {},
                },
                null,
                2,
            )}\n`,
        );
    },
});

export default create;
