import type { SymType } from '@maa/language-adl';
import type { AstNode } from 'langium';
import { GenerationError } from '@maa/generator-core/node';
import { type DataTypeGenerationContext, type DataTypeGeneratorFactory, type DataTypeView, type TypeMapping } from '@maa/generator-core';
import {
    MODEL_PACKAGE, constantName, describe, fieldName, interfacePackageName, isBuiltinDecl, messageNameOf, primitiveOf, rosPackageName, typeKey,
    type RosDataTypeResult, type RosMessage
} from './naming.js';
import createPythonTypes from '../timesync/datatypes.js';


/**
 * ros2.DataTypes: the class-diagram types the architecture uses become `.msg` files of a sibling
 * ament_cmake package `<pkg>_interfaces` (next to the ament_python package of ros2.Components):
 *
 * - an enum becomes a message with one `uint8` constant per literal (its ordinal) and a `uint8
 *   value` field;
 * - a class becomes a message with one field per attribute (snake_case names, as rosidl wants);
 * - generics are eliminated: every use `Pair<int, Color>` gets a message of its own
 *   (`PairInt32Color`) with the type arguments substituted; the generic class itself has none.
 *
 * Primitive ports need no message of their own (ros2.Components maps them to std_msgs).
 */
interface MessageDef {
    readonly name: string;
    readonly key: string;
    readonly view: DataTypeView;
    readonly kind: 'enum' | 'class';
    readonly lines: string[];
}

const create: DataTypeGeneratorFactory = (instantiation) => ({
    kind: 'datatype',
    async generate(ctx: DataTypeGenerationContext): Promise<RosDataTypeResult> {
        const pkg = interfacePackageName(ctx.platform);
        const defs = new Map<string, MessageDef>();
        const byName = new Map<string, string>();
        const pending: Array<{ t: SymType; where: AstNode }> = [];

        const fieldType = (t: SymType, where: AstNode, subst: ReadonlyMap<string, SymType>): string => {
            if (t.kind === 'typevar') {
                const bound = subst.get(t.decl.name);
                if (!bound) throw new GenerationError(`type parameter ${t.decl.name} is not bound here`, where);
                return fieldType(bound, where, new Map());
            }
            const prim = primitiveOf(t);
            if (prim) return prim.field;
            if (t.kind === 'array') return `${fieldType(t.component, where, subst)}[]`;
            if (t.kind === 'object' && !isBuiltinDecl(t.decl)) {
                const concrete: SymType = { kind: 'object', decl: t.decl, args: t.args.map((a) => resolve(a, subst, where)) };
                pending.push({ t: concrete, where });
                return `${pkg}/${messageNameOf(concrete, where)}`;
            }
            throw new GenerationError(`type ${describe(t)} cannot be translated to a ROS 2 message field`, where);
        };

        const resolve = (t: SymType, subst: ReadonlyMap<string, SymType>, where: AstNode): SymType => {
            if (t.kind === 'typevar') {
                const bound = subst.get(t.decl.name);
                if (!bound) throw new GenerationError(`type parameter ${t.decl.name} is not bound here`, where);
                return bound;
            }
            if (t.kind === 'object') return { kind: 'object', decl: t.decl, args: t.args.map((a) => resolve(a, subst, where)) };
            if (t.kind === 'array') return { kind: 'array', component: resolve(t.component, subst, where) };
            return t;
        };

        const define = (t: SymType, where: AstNode): void => {
            if (t.kind === 'array') return define(t.component, where);
            if (t.kind !== 'object' || isBuiltinDecl(t.decl)) return;
            const key = typeKey(t);
            if (defs.has(key)) return;
            const view = ctx.architecture.dataType(typeKey({ kind: 'object', decl: t.decl, args: [] }));
            if (!view) throw new GenerationError(`type ${describe(t)} is not part of the architecture's data types`, where);
            if (view.typeParameters.length !== t.args.length) {
                throw new GenerationError(`type ${describe(t)} is used without its type arguments; a ROS 2 message needs concrete types`, where);
            }
            const name = messageNameOf(t, where);
            const clash = byName.get(name);
            if (clash && clash !== key) throw new GenerationError(`types ${clash} and ${key} both map to the message name ${name}`, view.node);
            byName.set(name, key);
            const lines: string[] = [`# ${key}${view.kind === 'enum' ? ' (enum: the constants are the literals\' ordinals, `value` holds one of them)' : ''}`];
            const def: MessageDef = { name, key, view, kind: view.kind === 'enum' ? 'enum' : 'class', lines };
            defs.set(key, def);
            if (view.kind === 'enum') {
                if (view.constants.length > 256) throw new GenerationError(`enum ${view.qualifiedName} has more than 256 literals`, view.node);
                view.constants.forEach((c, i) => lines.push(`uint8 ${constantName(c)}=${i}`));
                lines.push('', 'uint8 value');
                return;
            }
            if (view.superTypes.length > 0) {
                throw new GenerationError(`type ${view.qualifiedName} extends ${view.superTypes.join(', ')}: ROS 2 messages have no inheritance`, view.node);
            }
            const subst = new Map(view.typeParameters.map((p, i) => [p, t.args[i]!] as const));
            const seen = new Set<string>();
            for (const a of view.attributes) {
                const f = fieldName(a.name);
                if (seen.has(f)) throw new GenerationError(`attributes of ${view.qualifiedName} clash as message field ${f}`, a.node);
                seen.add(f);
                lines.push(`${fieldType(a.type, a.node, subst)} ${f}`);
            }
            if (view.attributes.length === 0) lines.push('# (no attributes)');
        };

        // Every non-generic type used, and every concrete use of a generic type by ports, parameters and fields.
        for (const v of ctx.dataTypes) {
            if (v.typeParameters.length === 0) pending.push({ t: { kind: 'object', decl: v.node, args: [] }, where: v.node });
        }
        for (const c of ctx.architecture.components) {
            for (const p of [...c.ports, ...c.parameters, ...c.fields]) {
                if (!hasTypeVar(p.type)) pending.push({ t: p.type, where: p.node });
            }
        }
        while (pending.length > 0) {
            const { t, where } = pending.shift()!;
            collectUses(t).forEach((u) => define(u, where));
        }

        const sorted = [...defs.values()].sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
        const root = `${pkg}`;
        for (const d of sorted) {
            ctx.out.file(`${root}/msg/${d.name}.msg`).write(`${d.lines.join('\n')}\n`, d.view.node);
        }
        ctx.out.file(`${root}/CMakeLists.txt`).render('interfaces/CMakeLists.txt.njk', { pkg, messages: sorted.map((d) => d.name) });
        ctx.out.file(`${root}/package.xml`).render('interfaces/package.xml.njk', { pkg, app: ctx.platform.application, root: ctx.platform.rootComponent, ament: rosPackageName(ctx.platform) });

        const messages: Record<string, RosMessage> = {};
        for (const d of sorted) messages[d.key] = { type: `${pkg}/msg/${d.name}`, module: `${pkg}.msg`, name: d.name, kind: d.kind };

        // The behavior classes work with Python values (docs/runtime.md): the Python data types of
        // timesync.DataTypes, placed inside the ament_python package (`<pkg>.model.<diagram module>`).
        const ament = rosPackageName(ctx.platform);
        const python = (await (await createPythonTypes(instantiation)).generate({
            ...ctx,
            out: { file: (path, options) => ctx.out.file(`${ament}/${ament}/${MODEL_PACKAGE}/${path}`, options) }
        })) ?? {};
        const types: Record<string, TypeMapping> = {};
        for (const [name, mapping] of Object.entries(python.types ?? {})) {
            types[name] = { ...mapping, module: `${ament}.${MODEL_PACKAGE}.${mapping.module}` };
        }
        return { interfacePackage: pkg, messages, types };
    }
});

function hasTypeVar(t: SymType): boolean {
    if (t.kind === 'typevar') return true;
    if (t.kind === 'object') return t.args.some(hasTypeVar);
    if (t.kind === 'array') return hasTypeVar(t.component);
    return false;
}

/** The class-diagram type uses in a type (`Pair<Color, int>[]` -> Pair<Color, int>, Color). */
function collectUses(t: SymType): SymType[] {
    if (t.kind === 'array') return collectUses(t.component);
    if (t.kind === 'object') return [t, ...t.args.flatMap(collectUses)];
    return [];
}

export default create;
