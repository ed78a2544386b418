import { AstUtils, CstUtils, type AstNode } from 'langium';
import {
    allPorts,
    type ast,
    behaviorTiming,
    impliedConnectors,
    behaviorsOf,
    elementsOf,
    isComposed,
    stereotypeNames,
    subcomponentType,
    subcomponentsOf,
    typeOfMCType,
    printType,
    type ImpliedEnd,
    type SymType,
    type Timing,
} from '@maa/language-adl';

import { currentVariant, isFeatureBinding, variationPoints, withVariant, type VariantEnv } from '@maa/language-adl';
import { isModeAutomatonBlock, modeAutomatonView, modeSubcomponentsOf, type ModeAutomatonView } from './modes.js';

type ComponentType = ast.ComponentType;
type CDType = ast.CDType;

/**
 * The generator-facing view of an architecture: every component type an application uses
 * (the root, its subcomponent types, transitively, and their parents), the instance tree, the
 * behavior blocks with their languages, and the class-diagram types the components use.
 * Views keep their AST node, so generators can walk expressions and behaviors and the trace
 * can name model elements. Everything is sorted, so generators that follow the lists emit
 * deterministic output.
 */
export interface ArchitectureModel {
    readonly root: ComponentView;
    /** Every component type used, by qualified name (sorted). */
    readonly components: readonly ComponentView[];
    /** The instance tree, flattened in depth-first declaration order; the root instance has the path []. */
    readonly instances: readonly InstanceView[];
    /** Every behavior block of a used component type. */
    readonly behaviors: readonly BehaviorView[];
    /** The behavior languages used (sorted). */
    readonly languages: readonly string[];
    /** Class-diagram types used by ports, parameters and fields, transitively through attributes (sorted). */
    readonly dataTypes: readonly DataTypeView[];
    component(qualifiedName: string): ComponentView | undefined;
    dataType(qualifiedName: string): DataTypeView | undefined;
}

export interface ComponentView {
    readonly qualifiedName: string;
    readonly name: string;
    readonly packageName: string;
    readonly node: ComponentType;
    readonly typeParameters: readonly string[];
    readonly parents: readonly string[];
    readonly ports: readonly PortView[];
    readonly parameters: readonly ParameterView[];
    readonly fields: readonly FieldView[];
    readonly subcomponents: readonly SubcomponentView[];
    readonly connectors: readonly ConnectorView[];
    /** The behavior (other than an `init` block) of an atomic component, if it has one. */
    readonly behavior?: BehaviorView;
    /** The `init { }` block, if any. */
    readonly init?: AstNode;
    /** Marked `<<handwritten>>`: the generator emits a base class and a user file. */
    readonly handwritten: boolean;
    /** No subcomponents. */
    readonly atomic: boolean;
    /**
     * The mode automaton of a decomposed component: `subcomponents` then lists the shared ones
     * and those of every mode (all are instantiated), `connectors` only the shared ones.
     */
    readonly modes?: ModeAutomatonView;
    readonly stereotypes: readonly string[];
    /** The values of the component's features in the generated configuration (variable components only). */
    readonly features?: Readonly<Record<string, boolean>>;
}

export interface TypeView {
    readonly type: SymType;
    /** The type as written in models (`int`, `ToastColor`, `List<Data>`). */
    readonly typeName: string;
    /** The type with qualified class-diagram names (`toast.types.Types.ToastColor`). */
    readonly qualifiedTypeName: string;
}

export interface PortView extends TypeView {
    readonly name: string;
    readonly direction: 'in' | 'out';
    readonly timing: Timing;
    readonly delayed: boolean;
    readonly node: AstNode;
    /** Qualified name of the component type that declares the port (differs for inherited ports). */
    readonly owner: string;
}

export interface ParameterView extends TypeView {
    readonly name: string;
    readonly default?: AstNode;
    readonly node: AstNode;
}

export interface FieldView extends TypeView {
    readonly name: string;
    readonly init: AstNode;
    readonly node: AstNode;
}

export interface SubcomponentView {
    readonly name: string;
    /** Qualified name of the instantiated component type. */
    readonly type: string;
    readonly args: readonly AstNode[];
    readonly node: AstNode;
}

export interface PortRef {
    /** The subcomponent, or undefined for a port of the component itself. */
    readonly subcomponent?: string;
    readonly port: string;
}

export interface ConnectorView {
    readonly source: PortRef;
    readonly targets: readonly PortRef[];
    readonly node: AstNode;
}

export interface BehaviorView {
    /** The behavior language: the keyword of its block (`automaton`, `robotarm`, `compute`). */
    readonly language: string;
    /** The AST of the block (e.g. an `Automaton`). */
    readonly node: AstNode;
    /** Qualified name of the component type. */
    readonly component: string;
    readonly timing?: Timing;
}

export interface InstanceView {
    /** Subcomponent names from the root (the root instance has []). */
    readonly path: readonly string[];
    readonly component: ComponentView;
    /** The subcomponent declaration (undefined for the root). */
    readonly node?: AstNode;
    readonly args: readonly AstNode[];
}

export interface DataTypeView {
    readonly qualifiedName: string;
    readonly name: string;
    readonly packageName: string;
    readonly diagram: string;
    readonly kind: 'enum' | 'class' | 'interface';
    readonly constants: readonly string[];
    readonly attributes: ReadonlyArray<TypeView & { readonly name: string; readonly node: AstNode }>;
    readonly typeParameters: readonly string[];
    readonly superTypes: readonly string[];
    readonly node: CDType;
}

/** The behavior language of a behavior block: `compute` for the host's blocks, else its block keyword. */
export function behaviorLanguageOf(node: AstNode): string {
    if (node.$type === 'ComputeBlock' || node.$type === 'InitBlock') return 'compute';
    const first = node.$cstNode ? CstUtils.flattenCst(node.$cstNode).find((l) => !l.hidden) : undefined;
    return first?.text ?? node.$type.toLowerCase();
}

/** `pkg.Outer.Inner` for (inner) component types. */
export function componentQualifiedName(c: ComponentType): string {
    const names: string[] = [];
    for (let n: AstNode | undefined = c; n; n = n.$container) {
        if (n.$type === 'ComponentType') names.unshift((n as ComponentType).name);
    }
    const pkg = packageOf(c);
    return pkg ? `${pkg}.${names.join('.')}` : names.join('.');
}

/** `pkg.Diagram.Type` for class-diagram types. */
export function dataTypeQualifiedName(t: CDType | (AstNode & { name: string })): string {
    const diagram = t.$container as AstNode & { name?: string };
    const pkg = packageOf(t);
    const local = diagram?.name ? `${diagram.name}.${t.name}` : t.name;
    return pkg ? `${pkg}.${local}` : local;
}

export function packageOf(node: AstNode): string {
    const root = AstUtils.findRootNode(node) as AstNode & { package?: string };
    return root.package ?? '';
}

/** A type with qualified class-diagram names. */
export function printQualifiedType(t: SymType): string {
    switch (t.kind) {
        case 'object': {
            const name = dataTypeQualifiedName(t.decl);
            return t.args.length === 0 ? name : `${name}<${t.args.map(printQualifiedType).join(', ')}>`;
        }
        case 'array':
            return `${printQualifiedType(t.component)}[]`;
        default:
            return printType(t);
    }
}

function typeView(type: SymType): TypeView {
    return { type, typeName: printType(type), qualifiedTypeName: printQualifiedType(type) };
}

function isBuiltin(node: AstNode): boolean {
    return AstUtils.getDocument(node).uri.scheme === 'builtin';
}

/**
 * One configuration of a component type in the generated architecture. Without variability every
 * type has one; with a feature configuration (app-variant.ts) two instances of one type may
 * select different variation points or feature values, or contain subcomponents in different
 * configurations: each distinct configuration is a variant, generated as a type of its own.
 */
interface Variant {
    readonly id: number;
    readonly decl: ComponentType;
    /** The configuration the variant is read in (the first instance's; all instances of the variant agree). */
    readonly env: VariantEnv | undefined;
    /** The variant of each subcomponent, by name. */
    readonly subs: ReadonlyMap<string, Variant>;
    readonly parents: readonly Variant[];
    readonly features: Readonly<Record<string, boolean>> | undefined;
    /** Position of the first instance in depth-first declaration order: the first variant of a type keeps its name. */
    first: number;
    name: string;
    qualifiedName: string;
}

/**
 * The name of a variant of a component type other than its first one (in depth-first
 * declaration order of the instances, which keeps the type's name): the type's name, two
 * underscores, and the features the variant selects (`Lamp__dimmable`, `Room__dim_fast`), or
 * `no_` and the type's features when it selects none (`Lamp__no_dimmable`); a variant that
 * differs by something else (a boolean parameter bound by its instantiation, a subcomponent's
 * configuration) gets the number of the variant (`Lamp__2`). A name already taken gets `_2`, `_3`, ...
 */
export function variantName(
    typeName: string,
    features: Readonly<Record<string, boolean>> | undefined,
    index: number,
    taken: (name: string) => boolean,
): string {
    const all = Object.keys(features ?? {}).sort(compare);
    const selected = all.filter((f) => features?.[f]);
    const suffix = selected.length > 0 ? selected.join('_') : all.length > 0 ? `no_${all.join('_')}` : String(index + 1);
    let name = `${typeName}__${suffix}`;
    for (let i = 2; taken(name); i++) name = `${typeName}__${suffix}_${i}`;
    return name;
}

/** Builds the view of the architecture below a root component type (in the current feature configuration, if any). */
export function buildArchitecture(root: ComponentType): ArchitectureModel {
    const byType = new Map<ComponentType, Map<string, Variant>>();
    const variantsInOrder: Variant[] = [];
    let seq = 0;
    interface Entry {
        path: string[];
        node: AstNode | undefined;
        args: readonly AstNode[];
        variant?: Variant;
    }
    const entries: Entry[] = [];

    /** The variant of `c` in configuration `env`; `entry` is its instance (undefined for a parent type). */
    const resolve = (
        c: ComponentType,
        env: VariantEnv | undefined,
        entry: Entry | undefined,
        active: ReadonlySet<ComponentType>,
    ): Variant => {
        const position = seq++;
        if (entry) entries.push(entry);
        const inner = new Set([...active, c]);
        const subs = new Map<string, Variant>();
        for (const sub of withVariant(env, () => allSubcomponents(c))) {
            const decl = subcomponentType(sub).decl;
            if (!decl || inner.has(decl) || inner.size > 64) continue; // a cycle (reported elsewhere)
            const path = entry ? [...entry.path, sub.name] : undefined;
            const child: Entry | undefined = path ? { path, node: sub, args: sub.args.filter((a) => !isFeatureBinding(a)) } : undefined;
            subs.set(sub.name, resolve(decl, env?.sub(sub), child, inner));
        }
        const parents: Variant[] = [];
        for (const p of c.parents) {
            const decl = p.type?.ref?.ref;
            if (decl && !inner.has(decl)) parents.push(resolve(decl, env, undefined, inner));
        }
        const features = env?.featureValues?.(c);
        const decisions = env
            ? withVariant(env, () =>
                  variationPointsOf(c)
                      .map((v) => (env.decide(v) ? '1' : '0'))
                      .join(''),
              )
            : '';
        const key = [
            decisions,
            JSON.stringify(features ?? null),
            [...subs].map(([n, v]) => `${n}:${v.id}`).join(','),
            parents.map((v) => v.id).join(','),
        ].join('|');
        let variants = byType.get(c);
        if (!variants) byType.set(c, (variants = new Map()));
        let variant = variants.get(key);
        if (!variant) {
            variant = {
                id: variantsInOrder.length,
                decl: c,
                env,
                subs,
                parents,
                features,
                first: position,
                name: c.name,
                qualifiedName: componentQualifiedName(c),
            };
            variants.set(key, variant);
            variantsInOrder.push(variant);
        }
        if (entry) entry.variant = variant;
        return variant;
    };
    const rootVariant = resolve(root, currentVariant(), { path: [], node: undefined, args: [] }, new Set());

    // Names: the first variant of a type (by its first instance) keeps the type's name.
    const taken = new Set(variantsInOrder.map((v) => v.qualifiedName));
    for (const variants of byType.values()) {
        const sorted = [...variants.values()].sort((x, y) => x.first - y.first);
        sorted.forEach((v, i) => {
            if (i === 0) return;
            const outer = v.qualifiedName.slice(0, v.qualifiedName.length - v.decl.name.length);
            v.name = variantName(v.decl.name, v.features, i, (n) => taken.has(`${outer}${n}`));
            v.qualifiedName = `${outer}${v.name}`;
            taken.add(v.qualifiedName);
        });
    }
    const views = new Map<Variant, ComponentView>();
    for (const v of variantsInOrder)
        views.set(
            v,
            withVariant(v.env, () => componentView(v)),
        );

    const components = [...views.values()].sort((a, b) => compare(a.qualifiedName, b.qualifiedName));
    const byName = new Map(components.map((c) => [c.qualifiedName, c]));
    const instances: InstanceView[] = entries.flatMap((e) =>
        e.variant ? [{ path: e.path, component: views.get(e.variant)!, node: e.node, args: e.args }] : [],
    );

    const behaviors = components.flatMap((c) => (c.behavior ? [c.behavior] : []));
    const languages = [...new Set([...behaviors.map((b) => b.language), ...components.filter((c) => c.init).map(() => 'compute')])].sort(
        compare,
    );
    const dataTypes = collectDataTypes(components);
    const typeByName = new Map(dataTypes.map((t) => [t.qualifiedName, t]));
    return {
        root: views.get(rootVariant)!,
        components,
        instances,
        behaviors,
        languages,
        dataTypes,
        component: (qn) => byName.get(qn),
        dataType: (qn) => typeByName.get(qn),
    };
}

/** The variation points of a component type and of its parents (each decided in the type's configuration). */
function variationPointsOf(c: ComponentType, seen = new Set<ComponentType>()): ast.VarIf[] {
    if (seen.has(c)) return [];
    seen.add(c);
    return [
        ...variationPoints(c.body?.elements ?? []),
        ...c.parents.flatMap((p) => (p.type?.ref?.ref ? variationPointsOf(p.type.ref.ref, seen) : [])),
    ];
}

function componentView(v: Variant): ComponentView {
    const c = v.decl;
    const qualifiedName = v.qualifiedName;
    const blocks = behaviorsOf(c);
    const init = blocks.find((b) => b.behavior?.$type === 'InitBlock')?.behavior;
    // A mode automaton configures subcomponents: it is no behavior (modes below).
    const main = blocks.find((b) => b.behavior && b.behavior.$type !== 'InitBlock' && !isModeAutomatonBlock(b.behavior))?.behavior;
    const modes = modeAutomatonView(c);
    const timing = behaviorTiming(c);
    const elements = elementsOf(c);
    const features = v.features;
    return {
        qualifiedName,
        name: v.name,
        packageName: packageOf(c),
        node: c,
        typeParameters: c.typeParams.map((t) => t.name),
        parents: v.parents.map((p) => p.qualifiedName),
        ports: allPorts(c).map((p) => ({
            ...typeView(p.type),
            name: p.name,
            direction: p.direction,
            timing: p.timing,
            delayed: p.delayed,
            node: p.port,
            owner: componentQualifiedName(p.owner),
        })),
        parameters: c.params.map((p) => ({ ...typeView(typeOfMCType(p.type)), name: p.name, default: p.default, node: p })),
        fields: elements.flatMap((e) =>
            e.$type === 'FieldDeclaration'
                ? e.fields.map((f) => ({ ...typeView(typeOfMCType(e.type)), name: f.name, init: f.init, node: f }))
                : [],
        ),
        subcomponents: allSubcomponents(c).map((s) => {
            const decl = subcomponentType(s).decl;
            // Feature bindings (`sub(f = true)`) select the configuration; they are no arguments.
            return {
                name: s.name,
                type: v.subs.get(s.name)?.qualifiedName ?? (decl ? componentQualifiedName(decl) : ''),
                args: s.args.filter((a) => !isFeatureBinding(a)),
                node: s,
            };
        }),
        connectors: [
            ...elements.flatMap((e) =>
                e.$type === 'Connector' ? [{ source: portRef(e.source), targets: e.targets.map(portRef), node: e }] : [],
            ),
            // Connectors implied by `autoconnect` are connectors like any other; their node is
            // the `autoconnect` declaration.
            ...impliedConnectors(c).map((i) => ({
                source: impliedRef(i.source),
                targets: [impliedRef(i.target)],
                node: i.declaration,
            })),
        ],
        behavior: main ? { language: behaviorLanguageOf(main), node: main, component: qualifiedName, timing } : undefined,
        init,
        handwritten: stereotypeNames(c.stereotype).includes('handwritten'),
        atomic: !isComposed(c) && modeSubcomponentsOf(c).length === 0,
        ...(modes ? { modes } : {}),
        stereotypes: stereotypeNames(c.stereotype),
        // The feature configuration generated (variable architectures: app-variant.ts).
        ...(features ? { features } : {}),
    };
}

/** The subcomponents of a component and of its modes (all instantiated; modes switch connectors). */
function allSubcomponents(c: ComponentType): ast.Subcomponent[] {
    return [...subcomponentsOf(c), ...modeSubcomponentsOf(c)];
}

function impliedRef(e: ImpliedEnd): PortRef {
    return e.sub ? { subcomponent: e.sub.name, port: e.info.name } : { port: e.info.name };
}

function portRef(p: ast.PortAccess): PortRef {
    return p.subcomponent ? { subcomponent: p.subcomponent.$refText, port: p.port.$refText } : { port: p.port.$refText };
}

function collectDataTypes(components: readonly ComponentView[]): DataTypeView[] {
    const found = new Map<CDType, DataTypeView>();
    const pending: SymType[] = [];
    for (const c of components) {
        for (const t of [...c.ports, ...c.parameters, ...c.fields]) pending.push(t.type);
        // Types the behavior names: local variable types, static calls (`Rect.square(2.0)`), enum constants.
        for (const n of AstUtils.streamAst(c.node)) {
            const target =
                n.$type === 'ReferenceType' || n.$type === 'NameExpression'
                    ? (n as ast.ReferenceType | ast.NameExpression).ref?.ref
                    : undefined;
            if (target && (target.$type === 'CDClass' || target.$type === 'CDEnum'))
                pending.push({ kind: 'object', decl: target as CDType, args: [] });
            else if (target?.$type === 'CDEnumConstant') pending.push({ kind: 'object', decl: target.$container as CDType, args: [] });
        }
    }
    const add = (decl: CDType): void => {
        if (found.has(decl) || isBuiltin(decl)) return;
        const view = dataTypeView(decl);
        found.set(decl, view);
        for (const a of view.attributes) pending.push(a.type);
        if (decl.$type === 'CDClass') {
            for (const s of [...decl.superTypes, ...decl.interfaces]) pending.push(typeOfMCType(s));
        }
    };
    while (pending.length > 0) {
        const t = pending.pop()!;
        if (t.kind === 'object') {
            add(t.decl);
            pending.push(...t.args);
        } else if (t.kind === 'array') pending.push(t.component);
        else if (t.kind === 'wildcard') {
            if (t.upper) pending.push(t.upper);
            if (t.lower) pending.push(t.lower);
        }
    }
    return [...found.values()].sort((a, b) => compare(a.qualifiedName, b.qualifiedName));
}

function dataTypeView(t: CDType): DataTypeView {
    const diagram = t.$container as ast.ClassDiagram;
    const base = {
        qualifiedName: dataTypeQualifiedName(t),
        name: t.name,
        packageName: packageOf(t),
        diagram: diagram?.name ?? '',
        node: t,
    };
    if (t.$type === 'CDEnum') {
        return { ...base, kind: 'enum', constants: t.constants.map((c) => c.name), attributes: [], typeParameters: [], superTypes: [] };
    }
    return {
        ...base,
        kind: t.kind,
        constants: [],
        attributes: t.members.flatMap((m) =>
            m.$type === 'CDAttribute' ? [{ ...typeView(typeOfMCType(m.type)), name: m.name, node: m }] : [],
        ),
        typeParameters: t.typeParams.map((p) => p.name),
        superTypes: [...t.superTypes, ...t.interfaces].map((s) => printQualifiedType(typeOfMCType(s))),
    };
}

/** Code-point order: independent of the locale, so output is the same on every machine. */
export function compare(a: string, b: string): number {
    return a < b ? -1 : a > b ? 1 : 0;
}

/** The source text of a model element (e.g. an expression), whitespace as written. */
export function sourceText(node: AstNode | undefined): string {
    return node?.$cstNode?.text ?? '';
}
