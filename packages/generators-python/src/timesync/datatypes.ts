import type { DataTypeGenerationContext, DataTypeGeneratorFactory, DataTypeView, TypeMapping } from '@maa/generator-core';
import { Imports, modulePath, PRIMITIVE_PY, snake } from '../behavior/common.js';
import { pyName } from '../python/expressions.js';
import { methodViews } from '../python/cd-methods.js';
import { renderPython } from '../python/templates.js';
import type { DataTypeView as DataTypeChunkView } from './views.js';

const PRIMITIVES: Record<string, string> = {
    ...PRIMITIVE_PY,
    List: 'list',
    Set: 'set',
    Map: 'dict',
    Optional: 'Optional',
};

const DEFAULTS: Record<string, string> = { int: '0', float: '0.0', bool: 'False', str: '""' };

/** The module of a class diagram's types (one module per diagram). */
export function diagramModule(t: Pick<DataTypeView, 'packageName' | 'diagram'>): { module: string; file: string } {
    return modulePath(t.packageName, snake(t.diagram));
}

/** A Python annotation for a class-diagram attribute type (generics kept). */
function annotation(typeName: string, local: Map<string, string>, typeParams: readonly string[]): string {
    const m = /^([\w.]+)\s*(?:<(.*)>)?$/.exec(typeName.trim());
    if (!m) return typeName.endsWith('[]') ? `list[${annotation(typeName.slice(0, -2), local, typeParams)}]` : 'object';
    const base = m[1];
    const args = m[2] ? splitArgs(m[2]).map((a) => annotation(a, local, typeParams)) : [];
    const simple = base.split('.').pop()!;
    if (typeParams.includes(simple)) return simple;
    const py = PRIMITIVES[simple] ?? local.get(simple) ?? 'object';
    if (py === 'Optional') return `${args[0] ?? 'object'} | None`;
    return args.length ? `${py}[${args.join(', ')}]` : py;
}

function splitArgs(text: string): string[] {
    const out: string[] = [];
    let depth = 0;
    let cur = '';
    for (const ch of text) {
        if (ch === '<') depth++;
        if (ch === '>') depth--;
        if (ch === ',' && depth === 0) {
            out.push(cur.trim());
            cur = '';
        } else cur += ch;
    }
    if (cur.trim()) out.push(cur.trim());
    return out;
}

/** timesync.DataTypes: class diagrams to dataclasses and enum.Enum (generics as typing.Generic). */
const create: DataTypeGeneratorFactory = () => ({
    kind: 'datatype',
    generate(ctx) {
        const { byModule, types } = groupByModule(ctx.dataTypes);
        for (const [module, list] of [...byModule].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))) {
            writeDiagramModule(ctx, module, list);
        }
        return { types };
    },
});

export default create;

/** The types by the module of their diagram, and where each one lives (the generator's result). */
function groupByModule(dataTypes: readonly DataTypeView[]): { byModule: Map<string, DataTypeView[]>; types: Record<string, TypeMapping> } {
    const byModule = new Map<string, DataTypeView[]>();
    const types: Record<string, TypeMapping> = {};
    for (const t of dataTypes) {
        const { module } = diagramModule(t);
        let list = byModule.get(module);
        if (!list) byModule.set(module, (list = []));
        list.push(t);
        types[t.qualifiedName] = { module, name: pyName(t.name) };
    }
    return { byModule, types };
}

/** The module of one diagram (or of the diagrams sharing a module): its enums first, then its classes. */
function writeDiagramModule(ctx: DataTypeGenerationContext, module: string, list: readonly DataTypeView[]): void {
    const out = ctx.out.file(diagramModule(list[0]).file);
    const imports = new Imports();
    const local = new Map(list.map((t) => [t.name, pyName(t.name)]));
    // Types of other diagrams referenced by attributes.
    for (const t of ctx.dataTypes) {
        if (!local.has(t.name) && diagramModule(t).module !== module) local.set(t.name, pyName(t.name));
    }
    const order = [...list.filter((t) => t.kind === 'enum'), ...list.filter((t) => t.kind !== 'enum')];
    const chunks = order.map((t) => ({
        t,
        view: t.kind === 'enum' ? enumView(t, local, imports) : dataClassView(t, local, imports, ctx.dataTypes),
    }));
    const diagrams = [...new Set(list.map((t) => `${t.packageName ? `${t.packageName}.` : ''}${t.diagram}`))].join(', ');
    out.write(renderPython('timesync/datatypes-module.njk', { diagrams, imports: imports.lines() }));
    for (const { t, view } of chunks) {
        out.write('\n\n');
        out.write(renderPython('timesync/datatype.njk', view), t.node);
    }
}

/** An enum.Enum of the enum's constants (and its methods). */
function enumView(t: DataTypeView, local: Map<string, string>, imports: Imports): DataTypeChunkView {
    imports.add('enum', 'Enum');
    const methods = methodViews(t, (n) => annotation(n, local, []));
    return {
        name: pyName(t.name),
        qualifiedName: t.qualifiedName,
        enum: { constants: t.constants.map(pyName) },
        data: undefined,
        empty: t.constants.length === 0 && methods.length === 0,
        methods,
    };
}

/** A dataclass of a class or interface: its bases, attributes with defaults, methods. */
function dataClassView(
    t: DataTypeView,
    local: Map<string, string>,
    imports: Imports,
    dataTypes: readonly DataTypeView[],
): DataTypeChunkView {
    imports.add('dataclasses', 'dataclass');
    const bases = baseClasses(t, local, imports);
    const attributes = t.attributes.map((a) => attributeView(a, annotation(a.typeName, local, t.typeParameters), dataTypes));
    const methods = methodViews(t, (n) => annotation(n, local, t.typeParameters));
    return {
        name: pyName(t.name),
        qualifiedName: t.qualifiedName,
        enum: undefined,
        data: { kind: t.kind === 'interface' ? 'Interface' : 'Class', typeParameters: t.typeParameters, bases, attributes },
        empty: t.attributes.length === 0 && methods.length === 0,
        methods,
    };
}

/** The super types the build knows (in front), then `Generic[...]` for a generic type. */
function baseClasses(t: DataTypeView, local: Map<string, string>, imports: Imports): string[] {
    const bases: string[] = [];
    if (t.typeParameters.length) {
        imports.add('typing', 'Generic');
        imports.add('typing', 'TypeVar');
        bases.push(`Generic[${t.typeParameters.join(', ')}]`);
    }
    for (const s of t.superTypes) {
        const simple = s.split('.').pop()!.replace(/<.*$/, '');
        if (local.has(simple)) bases.unshift(local.get(simple)!);
    }
    return bases;
}

/**
 * An attribute with its default: the primitive's zero, an enum's first constant, else `None`
 * (and the annotation made optional for it).
 */
function attributeView(
    a: DataTypeView['attributes'][number],
    ann: string,
    dataTypes: readonly DataTypeView[],
): NonNullable<DataTypeChunkView['data']>['attributes'][number] {
    const enumType = dataTypes.find((d) => d.name === a.typeName && d.kind === 'enum');
    const value = DEFAULTS[ann] ?? (enumType?.constants.length ? `${pyName(enumType.name)}.${pyName(enumType.constants[0])}` : undefined);
    if (value === undefined) return { name: pyName(a.name), annotation: ann.endsWith('| None') ? ann : `${ann} | None`, value: 'None' };
    return { name: pyName(a.name), annotation: ann, value };
}
