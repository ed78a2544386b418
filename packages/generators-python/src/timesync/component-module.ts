/**
 * One Python module per component type of the python-timesync build: its behavior class (compute
 * blocks, a handwritten implementation, or the class a behavior generator wrote) and its component
 * type (maa_timesync `AtomicComponent`, `ComposedComponent` or `ModeComponent`).
 */
import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { AstUtils } from 'langium';
import type {
    ArchitectureModel,
    BehaviorResult,
    ComponentGenerationContext,
    ComponentView,
    DataTypeResult,
    PortView,
    SubcomponentView as SubcomponentDecl,
} from '@maa/generator-core';
import { GenerationError } from '@maa/generator-core/node';
import { Imports, modulePath, pyType, snake, typeBySimpleName, typeRef } from '../behavior/common.js';
import { computeClassView } from '../behavior/compute.js';
import { moduleTextOf } from '../behavior/automata.js';
import { PythonTranslator, isTypeDecl, pyName, type Node } from '../python/expressions.js';
import { renderPython, type PythonTemplates } from '../python/templates.js';
import { connectorTuple, modesView } from './modes.js';
import type { ComponentClassesView, SubcomponentView } from './views.js';

/** A rendered class template without its final newline (the module template places it). */
function renderClass<T extends 'behavior/compute.njk' | 'timesync/component.njk'>(template: T, view: PythonTemplates[T]): string {
    return renderPython(template, view).replace(/\n$/, '');
}

const str = (s: string): string => JSON.stringify(s);

export function componentModule(c: Pick<ComponentView, 'packageName' | 'name'>): { module: string; file: string } {
    return modulePath(c.packageName, snake(c.name));
}

/** Writes the module of component type `c` (and, for a handwritten one, its implementation file). */
export async function writeComponentModule(ctx: ComponentGenerationContext, c: ComponentView): Promise<void> {
    const imports = new Imports();
    const view = c.atomic ? await atomicView(ctx, c, imports) : composedView(ctx, c, imports);
    const out = ctx.out.file(componentModule(c).file);
    const classes = renderClass('timesync/component.njk', view);
    out.traced(c.node, () =>
        out.write(moduleTextOf(`Component ${c.qualifiedName} for the python-timesync platform (generated).`, imports, classes)),
    );
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

// ---- atomic components ----

/** How an atomic component gets its behavior: the class it instantiates and the classes its module defines. */
type AtomicBehavior = Pick<ComponentClassesView, 'behaviorClass' | 'handwritten'> & { readonly behavior: string };

/** The view of an atomic component: an `AtomicComponent` running its behavior class. */
async function atomicView(ctx: ComponentGenerationContext, c: ComponentView, imports: Imports): Promise<ComponentClassesView> {
    imports.add('maa_timesync', 'AtomicComponent');
    const { behaviorClass, handwritten, behavior } = await atomicBehavior(ctx, c, imports);
    const header = typeHeader(c, ctx.datatypes, imports);
    return {
        ...header,
        behaviorClass,
        handwritten,
        base: 'AtomicComponent',
        atomic: { behavior },
        composed: undefined,
        defaults: parameterDefaults(c, ctx.datatypes, imports),
    };
}

async function atomicBehavior(ctx: ComponentGenerationContext, c: ComponentView, imports: Imports): Promise<AtomicBehavior> {
    const delegated = await ctx.behavior(c);
    if (delegated?.handledBy === 'behavior-generator') return generatedBehavior(delegated.result, imports);
    if (c.handwritten && !delegated) return handwrittenBehavior(ctx, c, imports);
    return {
        behaviorClass: renderClass('behavior/compute.njk', computeClassView(c, ctx.datatypes, imports)),
        handwritten: undefined,
        behavior: `${c.name}Behavior`,
    };
}

/** A behavior class a behavior generator wrote in its own module (it returned `module` and `class`). */
function generatedBehavior(result: BehaviorResult, imports: Imports): AtomicBehavior {
    const module = String(result.module);
    const behavior = String(result.class);
    imports.add(module, behavior);
    return { behaviorClass: undefined, handwritten: undefined, behavior };
}

/** A generated base class plus the user's implementation, loaded at run time (`_behavior()`). */
function handwrittenBehavior(ctx: ComponentGenerationContext, c: ComponentView, imports: Imports): AtomicBehavior {
    const base = `${c.name}BehaviorBase`;
    const behaviorClass = renderClass('behavior/compute.njk', computeClassView(c, ctx.datatypes, imports, base));
    const impl = modulePath(c.packageName, `${snake(c.name)}_impl`);
    const handwritten = { base, module: impl.module, cls: `${c.name}Behavior` };
    writeImplementation(ctx, c, impl.file, handwritten);
    return { behaviorClass, handwritten, behavior: '_behavior()' };
}

/**
 * The implementation file of a handwritten component: the one kept next to the model (copied on
 * every generation), or else a user file created once.
 */
function writeImplementation(
    ctx: ComponentGenerationContext,
    c: ComponentView,
    file: string,
    handwritten: { base: string; cls: string },
): void {
    const source = handwrittenSource(c);
    if (source !== undefined) {
        ctx.out.file(file).write(source, c.node);
        return;
    }
    ctx.out.file(file, { userFile: true }).write(
        renderPython('timesync/handwritten.py.njk', {
            qualifiedName: c.qualifiedName,
            module: componentModule(c).module,
            base: handwritten.base,
            className: handwritten.cls,
        }),
        c.node,
    );
}

/** The handwritten implementation kept next to the model (`<Name>.timesync.py` beside `<Name>.arc`), if any. */
function handwrittenSource(c: ComponentView): string | undefined {
    const uri = AstUtils.getDocument(c.node).uri;
    if (uri.scheme !== 'file') return undefined;
    const file = path.join(path.dirname(uri.fsPath), `${c.name}.timesync.py`);
    return existsSync(file) ? readFileSync(file, 'utf8') : undefined;
}

// ---- composed components ----

/** The view of a composed component: its subcomponents, connectors and (a ModeComponent) its modes. */
function composedView(ctx: ComponentGenerationContext, c: ComponentView, imports: Imports): ComponentClassesView {
    // A mode automaton makes it a ModeComponent (modes.ts).
    const modes = modesView(c, ctx.datatypes, imports);
    if (!modes) imports.add('maa_timesync', 'ComposedComponent');
    imports.add('maa_timesync', 'ComponentType');
    const tr = configTranslator(ctx.datatypes, imports);
    const subcomponents = c.subcomponents.map((s) => subcomponentView(ctx.architecture, c, s, tr, imports));
    const usesParams = subcomponents.some((x) => x.args.some((a) => a.value.includes('params[')));
    const header = typeHeader(c, ctx.datatypes, imports);
    return {
        ...header,
        behaviorClass: undefined,
        handwritten: undefined,
        base: modes ? 'ModeComponent' : 'ComposedComponent',
        atomic: undefined,
        composed: { connectors: c.connectors.map(connectorTuple), modes, usesParams, subcomponents },
        defaults: parameterDefaults(c, ctx.datatypes, imports),
    };
}

/** A subcomponent: its type's class (imported unless it lives in the same module) and its arguments. */
function subcomponentView(
    architecture: ArchitectureModel,
    parent: ComponentView,
    s: SubcomponentDecl,
    tr: PythonTranslator,
    imports: Imports,
): SubcomponentView {
    const sub = architecture.component(s.type);
    if (!sub) throw new GenerationError(`unknown component type ${s.type}`, s.node);
    const subModule = componentModule(sub);
    const alias = pyName(sub.name);
    if (subModule.module !== componentModule(parent).module) imports.add(subModule.module, alias);
    return { name: s.name, alias, args: subcomponentArgs(sub, s, tr) };
}

/** The arguments of a subcomponent by parameter name, positional or named (`p = value`, MontiArc's keyword arguments). */
function subcomponentArgs(sub: ComponentView, s: SubcomponentDecl, tr: PythonTranslator): SubcomponentView['args'] {
    return s.args.map((a, i) => {
        const arg: Node = a;
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
}
