import type { DataTypeGeneratorFactory, DataTypeView, TypeMapping } from '@maa/generator-core';
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
        const byModule = new Map<string, DataTypeView[]>();
        const types: Record<string, TypeMapping> = {};
        for (const t of ctx.dataTypes) {
            const { module } = diagramModule(t);
            let list = byModule.get(module);
            if (!list) byModule.set(module, (list = []));
            list.push(t);
            types[t.qualifiedName] = { module, name: pyName(t.name) };
        }
        for (const [module, list] of [...byModule].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))) {
            const first = list[0];
            const { file } = diagramModule(first);
            const out = ctx.out.file(file);
            const imports = new Imports();
            const local = new Map(list.map((t) => [t.name, pyName(t.name)]));
            // Types of other diagrams referenced by attributes.
            for (const t of ctx.dataTypes) {
                if (!local.has(t.name) && diagramModule(t).module !== module) local.set(t.name, pyName(t.name));
            }
            const chunks: Array<{ t: DataTypeView; view: DataTypeChunkView }> = [];
            const order = [...list.filter((t) => t.kind === 'enum'), ...list.filter((t) => t.kind !== 'enum')];
            for (const t of order) {
                if (t.kind === 'enum') {
                    imports.add('enum', 'Enum');
                    const methods = methodViews(t, (n) => annotation(n, local, []));
                    chunks.push({
                        t,
                        view: {
                            name: pyName(t.name),
                            qualifiedName: t.qualifiedName,
                            enum: { constants: t.constants.map(pyName) },
                            data: undefined,
                            empty: t.constants.length === 0 && methods.length === 0,
                            methods,
                        },
                    });
                    continue;
                }
                imports.add('dataclasses', 'dataclass');
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
                const attributes = t.attributes.map((a) => {
                    const ann = annotation(a.typeName, local, t.typeParameters);
                    const enumType = ctx.dataTypes.find((d) => d.name === a.typeName && d.kind === 'enum');
                    const value =
                        DEFAULTS[ann] ??
                        (enumType?.constants.length ? `${pyName(enumType.name)}.${pyName(enumType.constants[0])}` : undefined);
                    if (value === undefined)
                        return { name: pyName(a.name), annotation: ann.endsWith('| None') ? ann : `${ann} | None`, value: 'None' };
                    return { name: pyName(a.name), annotation: ann, value };
                });
                const methods = methodViews(t, (n) => annotation(n, local, t.typeParameters));
                chunks.push({
                    t,
                    view: {
                        name: pyName(t.name),
                        qualifiedName: t.qualifiedName,
                        enum: undefined,
                        data: { kind: t.kind === 'interface' ? 'Interface' : 'Class', typeParameters: t.typeParameters, bases, attributes },
                        empty: t.attributes.length === 0 && methods.length === 0,
                        methods,
                    },
                });
            }
            const diagrams = [...new Set(list.map((t) => `${t.packageName ? `${t.packageName}.` : ''}${t.diagram}`))].join(', ');
            out.write(renderPython('timesync/datatypes-module.njk', { diagrams, imports: imports.lines() }));
            for (const { t, view } of chunks) {
                out.write('\n\n');
                out.write(renderPython('timesync/datatype.njk', view), t.node);
            }
        }
        return { types };
    },
});

export default create;
