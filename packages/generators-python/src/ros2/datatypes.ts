import type { SymType } from '@maa/language-adl';
import type { AstNode } from 'langium';
import { GenerationError } from '@maa/generator-core/node';
import type {
    DataTypeGenerationContext,
    DataTypeGeneratorFactory,
    DataTypeGeneratorManifest,
    DataTypeView,
    GeneratorInstantiation,
    TypeMapping,
} from '@maa/generator-core';
import {
    MODEL_PACKAGE,
    constantName,
    describe,
    fieldName,
    interfacePackageName,
    isBuiltinDecl,
    messageNameOf,
    primitiveOf,
    rosPackageName,
    typeKey,
    type RosDataTypeResult,
    type RosMessage,
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
        const catalog = new MessageCatalog(pkg, ctx);
        catalog.collect();
        const sorted = catalog.sorted();
        for (const d of sorted) {
            ctx.out.file(`${pkg}/msg/${d.name}.msg`).write(`${d.lines.join('\n')}\n`, d.view.node);
        }
        ctx.out.file(`${pkg}/CMakeLists.txt`).render('interfaces/CMakeLists.txt.njk', { pkg, messages: sorted.map((d) => d.name) });
        ctx.out.file(`${pkg}/package.xml`).render('interfaces/package.xml.njk', {
            pkg,
            app: ctx.platform.application,
            root: ctx.platform.rootComponent,
            ament: rosPackageName(ctx.platform),
        });
        const messages: Record<string, RosMessage> = {};
        for (const d of sorted) messages[d.key] = { type: `${pkg}/msg/${d.name}`, module: `${pkg}.msg`, name: d.name, kind: d.kind };
        return { interfacePackage: pkg, messages, types: await pythonTypes(instantiation, ctx) };
    },
});

/**
 * The behavior classes work with Python values (docs/runtime.md): the Python data types of
 * timesync.DataTypes, placed inside the ament_python package (`<pkg>.model.<diagram module>`).
 */
async function pythonTypes(
    instantiation: GeneratorInstantiation<DataTypeGeneratorManifest>,
    ctx: DataTypeGenerationContext,
): Promise<Record<string, TypeMapping>> {
    const ament = rosPackageName(ctx.platform);
    const python =
        (await (
            await createPythonTypes(instantiation)
        ).generate({
            ...ctx,
            out: { file: (path, options) => ctx.out.file(`${ament}/${ament}/${MODEL_PACKAGE}/${path}`, options) },
        })) ?? {};
    const types: Record<string, TypeMapping> = {};
    for (const [name, mapping] of Object.entries(python.types ?? {})) {
        types[name] = { ...mapping, module: `${ament}.${MODEL_PACKAGE}.${mapping.module}` };
    }
    return types;
}

/** The messages of the types used: every non-generic type and every concrete use of a generic one, transitively through fields. */
class MessageCatalog {
    private readonly defs = new Map<string, MessageDef>();
    private readonly byName = new Map<string, string>();
    private readonly pending: Array<{ t: SymType; where: AstNode }> = [];

    constructor(
        private readonly pkg: string,
        private readonly ctx: DataTypeGenerationContext,
    ) {}

    /** Every non-generic type used, and every concrete use of a generic type by ports, parameters and fields. */
    collect(): void {
        for (const v of this.ctx.dataTypes) {
            if (v.typeParameters.length === 0) this.pending.push({ t: { kind: 'object', decl: v.node, args: [] }, where: v.node });
        }
        for (const c of this.ctx.architecture.components) {
            for (const p of [...c.ports, ...c.parameters, ...c.fields]) {
                if (!hasTypeVar(p.type)) this.pending.push({ t: p.type, where: p.node });
            }
        }
        while (this.pending.length > 0) {
            const { t, where } = this.pending.shift()!;
            for (const u of collectUses(t)) this.define(u, where);
        }
    }

    sorted(): MessageDef[] {
        return [...this.defs.values()].sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
    }

    private define(t: SymType, where: AstNode): void {
        if (t.kind === 'array') {
            this.define(t.component, where);
            return;
        }
        if (t.kind !== 'object' || isBuiltinDecl(t.decl)) return;
        const key = typeKey(t);
        if (this.defs.has(key)) return;
        const view = this.ctx.architecture.dataType(typeKey({ kind: 'object', decl: t.decl, args: [] }));
        if (!view) throw new GenerationError(`type ${describe(t)} is not part of the architecture's data types`, where);
        if (view.typeParameters.length !== t.args.length) {
            throw new GenerationError(
                `type ${describe(t)} is used without its type arguments; a ROS 2 message needs concrete types`,
                where,
            );
        }
        const name = messageNameOf(t, where);
        const clash = this.byName.get(name);
        if (clash && clash !== key) throw new GenerationError(`types ${clash} and ${key} both map to the message name ${name}`, view.node);
        this.byName.set(name, key);
        const lines: string[] = [
            `# ${key}${view.kind === 'enum' ? " (enum: the constants are the literals' ordinals, `value` holds one of them)" : ''}`,
        ];
        this.defs.set(key, { name, key, view, kind: view.kind === 'enum' ? 'enum' : 'class', lines });
        lines.push(...(view.kind === 'enum' ? enumFields(view) : this.classFields(view, t)));
    }

    /** One field per attribute, type arguments substituted. */
    private classFields(view: DataTypeView, t: SymType & { kind: 'object' }): string[] {
        if (view.superTypes.length > 0) {
            throw new GenerationError(
                `type ${view.qualifiedName} extends ${view.superTypes.join(', ')}: ROS 2 messages have no inheritance`,
                view.node,
            );
        }
        const subst = new Map(view.typeParameters.map((p, i) => [p, t.args[i]!] as const));
        const seen = new Set<string>();
        const lines: string[] = [];
        for (const a of view.attributes) {
            const f = fieldName(a.name);
            if (seen.has(f)) throw new GenerationError(`attributes of ${view.qualifiedName} clash as message field ${f}`, a.node);
            seen.add(f);
            lines.push(`${this.fieldType(a.type, a.node, subst)} ${f}`);
        }
        if (view.attributes.length === 0) lines.push('# (no attributes)');
        return lines;
    }

    /** The rosidl type of a field (a message type used here is defined too). */
    private fieldType(t: SymType, where: AstNode, subst: ReadonlyMap<string, SymType>): string {
        if (t.kind === 'typevar') return this.fieldType(bound(t.decl.name, subst, where), where, new Map());
        const prim = primitiveOf(t);
        if (prim) return prim.field;
        if (t.kind === 'array') return `${this.fieldType(t.component, where, subst)}[]`;
        if (t.kind === 'object' && !isBuiltinDecl(t.decl)) {
            const concrete: SymType = { kind: 'object', decl: t.decl, args: t.args.map((a) => resolve(a, subst, where)) };
            this.pending.push({ t: concrete, where });
            return `${this.pkg}/${messageNameOf(concrete, where)}`;
        }
        throw new GenerationError(`type ${describe(t)} cannot be translated to a ROS 2 message field`, where);
    }
}

/** An enum: one `uint8` constant per literal (its ordinal) and the `value` field. */
function enumFields(view: DataTypeView): string[] {
    if (view.constants.length > 256) throw new GenerationError(`enum ${view.qualifiedName} has more than 256 literals`, view.node);
    return [...view.constants.map((c, i) => `uint8 ${constantName(c)}=${i}`), '', 'uint8 value'];
}

function bound(name: string, subst: ReadonlyMap<string, SymType>, where: AstNode): SymType {
    const t = subst.get(name);
    if (!t) throw new GenerationError(`type parameter ${name} is not bound here`, where);
    return t;
}

/** A type with the type parameters bound by `subst` substituted. */
function resolve(t: SymType, subst: ReadonlyMap<string, SymType>, where: AstNode): SymType {
    if (t.kind === 'typevar') return bound(t.decl.name, subst, where);
    if (t.kind === 'object') return { kind: 'object', decl: t.decl, args: t.args.map((a) => resolve(a, subst, where)) };
    if (t.kind === 'array') return { kind: 'array', component: resolve(t.component, subst, where) };
    return t;
}

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
