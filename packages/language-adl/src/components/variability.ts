import type { AstNode } from 'langium';
import type { ComponentType, ConstraintDeclaration, Expression, Parameter, Subcomponent, VarIf } from '../generated/ast.js';
import { parentsOf, subcomponentType } from './component-model.js';
import { allFeatures, subcomponentFeature } from './features.js';
import { variationPoints, type VariantEnv } from './variant-context.js';

/**
 * The configuration space of a variable component (MontiArc's `feature`, `constraint`,
 * `varif`), decided by exhaustive search.
 *
 * Variables: the component's features (own and inherited), its boolean parameters, and, one
 * instance level down and deeper, the features and unbound parameters of its subcomponents
 * (`sub.f`, `sub.inner.f`); a subcomponent's parameters bound by instantiation arguments take
 * the argument's value. A condition outside propositional logic over these (`p > 0`,
 * `mode == Mode.ON`) is an opaque atom: a variable of its own, shared by equal texts; atoms
 * `x == T.C` with the same left side are mutually exclusive (enum constants). This
 * over-approximates the configurations MontiArc's SMT encoding admits (atoms over the same
 * integer are not related), so a configuration check may report a configuration that integer
 * arithmetic would exclude, never miss one.
 *
 * Bound: at most MAX_VARIABLES variables (2^16 = 65,536 assignments, each evaluating every
 * constraint: a few milliseconds per component); beyond it the component gets one
 * `variability/too-many-features` warning and is checked in its union view only.
 */
export const MAX_VARIABLES = 16;

/**
 * At most this many distinct selections of variation points are checked one by one (each runs
 * the structural checks once); a component with more is checked in its union view, with the
 * `variability/too-many-features` warning.
 */
export const MAX_VARIANTS = 256;

/** How deep subcomponent constraints are followed (instances of instances of ...). */
const MAX_DEPTH = 6;

/** A configuration: bit i is the value of the i-th variable (ConfigurationSpace.variables). */
export type Assignment = number;
type Formula = (a: Assignment) => boolean;

export interface VariableInfo {
    readonly key: string;
    readonly kind: 'feature' | 'parameter' | 'atom';
    /** The subcomponent path (empty for the component's own variables). */
    readonly path: readonly Subcomponent[];
}

/** One instance in the tree below the checked component. */
interface Instance {
    readonly decl: ComponentType;
    readonly prefix: string;
    readonly path: readonly Subcomponent[];
    readonly bindings: ReadonlyMap<string, { expr: Expression; outer: Instance }>;
}

export interface ConfigurationSpace {
    readonly variables: ReadonlyMap<string, VariableInfo>;
    /** Whether the space has more variables than MAX_VARIABLES (then nothing was enumerated). */
    readonly tooLarge: boolean;
    /** The assignments that satisfy every constraint of the instance tree. */
    readonly configurations: readonly Assignment[];
    /** One configuration per distinct selection of variation points (at most MAX_VARIANTS + 1). */
    readonly variants: readonly Assignment[];
    /** The configuration of the checked component for an assignment (for withVariant). */
    env(a: Assignment): VariantEnv;
    /**
     * The configuration for generation, per instance: the root's configuration, whose `sub(s)`
     * is the configuration of instance `s` (its variation points decided and its features valued
     * as in that instance). Instances of one type in different configurations become variants of
     * the generated type (generator-core's buildArchitecture).
     */
    generationEnv(a: Assignment): VariantEnv;
    /** The value of a variable in a configuration. */
    value(a: Assignment, key: string): boolean;
    /** A key telling configurations apart that select different variation points anywhere in the tree. */
    signature(a: Assignment): string;
}

class Compiler {
    readonly variables = new Map<string, VariableInfo>();
    private readonly index = new Map<string, number>();
    readonly exclusive = new Map<string, string[]>();

    compile(e: Expression | undefined, inst: Instance): Formula {
        return this.bool(e, inst) ?? this.atom(e, inst);
    }

    /** The formula of a boolean expression in propositional form, else undefined. */
    private bool(e: Expression | undefined, inst: Instance): Formula | undefined {
        if (!e) return () => true;
        switch (e.$type) {
            case 'BooleanLiteral': {
                const v = e.value === 'true';
                return () => v;
            }
            case 'PrefixExpression': {
                if (e.op !== '!') return undefined;
                const f = this.compile(e.operand, inst);
                return (a) => !f(a);
            }
            case 'ConditionalExpression': {
                const c = this.compile(e.condition, inst);
                const t = this.bool(e.then, inst);
                const f = this.bool(e.else, inst);
                if (!t || !f) return undefined;
                return (a) => (c(a) ? t(a) : f(a));
            }
            case 'BinaryExpression': {
                const op = e.op;
                if (op === '&&' || op === '||') {
                    const l = this.compile(e.left, inst);
                    const r = this.compile(e.right, inst);
                    return op === '&&' ? (a) => l(a) && r(a) : (a) => l(a) || r(a);
                }
                if (op === '==' || op === '!=' || op === '^' || op === '&' || op === '|') {
                    const l = this.bool(e.left, inst);
                    const r = this.bool(e.right, inst);
                    if (!l || !r) return undefined;
                    switch (op) {
                        case '==':
                            return (a) => l(a) === r(a);
                        case '&':
                            return (a) => l(a) && r(a);
                        case '|':
                            return (a) => l(a) || r(a);
                        default:
                            return (a) => l(a) !== r(a);
                    }
                }
                return undefined;
            }
            case 'NameExpression': {
                const target = e.ref?.ref;
                if (target?.$type === 'Feature') return this.variable(inst.prefix + target.name, 'feature', inst.path);
                if (target?.$type === 'Parameter') return this.parameter(target, inst);
                return undefined;
            }
            case 'FieldAccessExpression': {
                const feature = subcomponentFeature(e.receiver, e.member);
                if (!feature || e.receiver.$type !== 'NameExpression') return undefined;
                const sub = e.receiver.ref?.ref as Subcomponent;
                return this.variable(`${inst.prefix}${sub.name}.${feature.name}`, 'feature', [...inst.path, sub]);
            }
            default:
                return undefined;
        }
    }

    private parameter(p: Parameter, inst: Instance): Formula | undefined {
        const bound = inst.bindings.get(p.name);
        if (bound) return this.bool(bound.expr, bound.outer);
        const type = p.type?.$cstNode?.text;
        if (type !== 'boolean' && type !== 'Boolean') return undefined;
        return this.variable(inst.prefix + p.name, 'parameter', inst.path);
    }

    private atom(e: Expression | undefined, inst: Instance): Formula {
        const text = (e?.$cstNode?.text ?? '').replace(/\s+/g, ' ');
        const key = `${inst.prefix}#${text}`;
        const f = this.variable(key, 'atom', inst.path);
        // `x == T.C`: x equals at most one enum constant.
        if (e?.$type === 'BinaryExpression' && e.op === '==' && isConstantAccess(e.right)) {
            const group = `${inst.prefix}${(e.left.$cstNode?.text ?? '').replace(/\s+/g, '')}`;
            const members = this.exclusive.get(group) ?? [];
            if (!members.includes(key)) members.push(key);
            this.exclusive.set(group, members);
        }
        return f;
    }

    variable(key: string, kind: VariableInfo['kind'], path: readonly Subcomponent[]): Formula {
        let i = this.index.get(key);
        if (i === undefined) {
            i = this.index.size;
            this.index.set(key, i);
            this.variables.set(key, { key, kind, path });
        }
        const bit = 2 ** i;
        return (a) => Math.floor(a / bit) % 2 === 1;
    }
}

/** `Type.CONSTANT`: a name starting with an upper-case letter, then a member. */
function isConstantAccess(e: Expression | undefined): boolean {
    return e?.$type === 'FieldAccessExpression' && e.receiver.$type === 'NameExpression' && /^[A-Z]/.test(e.receiver.ref?.$refText ?? '');
}

/** Own and inherited constraints and variation points of a component type, with the type that declares them. */
function declarationsOf(
    c: ComponentType,
    seen = new Set<ComponentType>(),
): { constraints: Array<{ node: ConstraintDeclaration; guards: VarIf[] }>; points: VarIf[] } {
    const constraints: Array<{ node: ConstraintDeclaration; guards: VarIf[] }> = [];
    const points: VarIf[] = [];
    if (seen.has(c)) return { constraints, points };
    seen.add(c);
    const walk = (elements: ComponentType['body']['elements'], guards: VarIf[]): void => {
        for (const e of elements) {
            if (e.$type === 'ConstraintDeclaration') constraints.push({ node: e, guards });
            else if (e.$type === 'VarIf') {
                for (let v: VarIf | undefined = e; v; v = v.elseIf) {
                    walk(v.then?.elements ?? [], [...guards, v]);
                    if (v.else) walk(v.else.elements, guards);
                }
            }
        }
    };
    walk(c.body?.elements ?? [], []);
    points.push(...variationPoints(c.body?.elements ?? []));
    for (const p of parentsOf(c)) {
        const inherited = declarationsOf(p.decl, seen);
        constraints.push(...inherited.constraints);
        points.push(...inherited.points);
    }
    return { constraints, points };
}

/** Subcomponents of a type in every variation point (own, then inherited). */
function allSubcomponents(c: ComponentType, seen = new Set<ComponentType>()): Subcomponent[] {
    if (seen.has(c)) return [];
    seen.add(c);
    const result: Subcomponent[] = [];
    const walk = (elements: ComponentType['body']['elements']): void => {
        for (const e of elements) {
            if (e.$type === 'ComponentInstantiation' || e.$type === 'ComponentType') result.push(...e.instances);
            else if (e.$type === 'VarIf') {
                for (let v: VarIf | undefined = e; v; v = v.elseIf) {
                    walk(v.then?.elements ?? []);
                    if (v.else) walk(v.else.elements);
                }
            }
        }
    };
    walk(c.body?.elements ?? []);
    for (const p of parentsOf(c)) result.push(...allSubcomponents(p.decl, seen));
    return result;
}

function bindingsOf(sub: Subcomponent, decl: ComponentType, outer: Instance): Map<string, { expr: Expression; outer: Instance }> {
    const result = new Map<string, { expr: Expression; outer: Instance }>();
    let positional = 0;
    for (const arg of sub.args) {
        if (arg.$type === 'AssignmentExpression' && arg.op === '=' && arg.left.$type === 'NameExpression') {
            const key = arg.left.ref?.$refText;
            if (key) result.set(key, { expr: arg.right, outer });
            continue;
        }
        if (arg.$type === 'AssignmentExpression') continue; // another key form: not a parameter value
        const p = decl.params[positional++];
        if (p) result.set(p.name, { expr: arg, outer });
    }
    return result;
}

/**
 * Whether a component type has anything variable: features, constraints, variation points, or
 * subcomponents that do. `memo` (e.g. a workspace cache) answers for types asked before, so
 * asking every type of a large model walks each type once.
 */
export function isVariable(
    c: ComponentType,
    memo?: Map<ComponentType, boolean> | { get(c: ComponentType): boolean | undefined; set(c: ComponentType, v: boolean): void },
    active = new Set<ComponentType>(),
): boolean {
    const known = memo?.get(c);
    if (known !== undefined) return known;
    if (active.has(c)) return false; // a cycle (reported elsewhere)
    active.add(c);
    let result = allFeatures(c).length > 0;
    if (!result) {
        const d = declarationsOf(c);
        result = d.constraints.length > 0 || d.points.length > 0;
    }
    if (!result) {
        result = allSubcomponents(c).some((s) => {
            const decl = subcomponentType(s).decl;
            return decl !== undefined && isVariable(decl, memo, active);
        });
    }
    active.delete(c);
    memo?.set(c, result);
    return result;
}

/** A variation point of one instance, with its condition compiled for that instance. */
interface InstancePoint {
    readonly point: VarIf;
    readonly inst: Instance;
    readonly formula: Formula;
}

/** The variables, constraints and variation points of an instance tree, compiled. */
interface CompiledTree {
    readonly compiler: Compiler;
    readonly constraints: readonly Formula[];
    readonly points: readonly InstancePoint[];
}

/** Variation points and constraints of the instance tree of `c` (for diagnostics on a component's own ones). */
export function configurationSpace(c: ComponentType): ConfigurationSpace {
    const tree = compileInstanceTree(c);
    const keys = [...tree.compiler.variables.keys()];
    const tooLarge = keys.length > MAX_VARIABLES;
    const configurations = tooLarge ? [] : validConfigurations(tree, keys);
    const signature = (a: Assignment): string => tree.points.map((p) => (p.formula(a) ? '1' : '0')).join('');
    const variants = distinctVariants(configurations, signature);
    const formulaOf = formulasByInstance(tree.points);
    const value = (a: Assignment, key: string): boolean => {
        const i = keys.indexOf(key);
        return i >= 0 && Math.floor(a / 2 ** i) % 2 === 1;
    };
    return {
        variables: tree.compiler.variables,
        tooLarge: tooLarge || variants.length > MAX_VARIANTS,
        configurations,
        variants,
        env: (a) => analysisEnv(a, formulaOf),
        generationEnv: (a) => generationEnv(a, formulaOf, tree.points, value),
        value,
        signature,
    };
}

/** Walks the instance tree of `c` (to MAX_DEPTH, no type twice on a path) and compiles its features, constraints and variation points. */
function compileInstanceTree(c: ComponentType): CompiledTree {
    const compiler = new Compiler();
    const constraints: Formula[] = [];
    const points: InstancePoint[] = [];
    const visit = (inst: Instance, depth: number, active: ReadonlySet<ComponentType>): void => {
        // Every own and inherited feature is a variable even when no constraint names it.
        for (const f of allFeatures(inst.decl)) compiler.variable(inst.prefix + f.name, 'feature', inst.path);
        const d = declarationsOf(inst.decl);
        for (const { node, guards } of d.constraints) {
            const f = compiler.compile(node.expression, inst);
            const gs = guards.map((g) => compiler.compile(g.condition, inst));
            constraints.push(gs.length === 0 ? f : (a) => !gs.every((g) => g(a)) || f(a));
        }
        for (const point of d.points) points.push({ point, inst, formula: compiler.compile(point.condition, inst) });
        if (depth >= MAX_DEPTH) return;
        for (const s of allSubcomponents(inst.decl)) {
            const decl = subcomponentType(s).decl;
            if (!decl || active.has(decl)) continue;
            const child: Instance = {
                decl,
                prefix: `${inst.prefix}${s.name}.`,
                path: [...inst.path, s],
                bindings: bindingsOf(s, decl, inst),
            };
            constraints.push(...featureBindings(compiler, s, inst, child));
            visit(child, depth + 1, new Set([...active, decl]));
        }
    };
    visit({ decl: c, prefix: '', path: [], bindings: new Map() }, 0, new Set([c]));
    return { compiler, constraints, points };
}

/** Feature bindings of an instantiation (`sub(f = true)`) fix the subcomponent's features: one constraint each. */
function featureBindings(compiler: Compiler, s: Subcomponent, inst: Instance, child: Instance): Formula[] {
    const bound: Formula[] = [];
    for (const arg of s.args) {
        if (arg.$type !== 'AssignmentExpression' || arg.op !== '=' || arg.left.$type !== 'NameExpression') continue;
        const target = arg.left.ref?.ref;
        if (target?.$type !== 'Feature') continue;
        const feature = compiler.variable(child.prefix + target.name, 'feature', child.path);
        const value = compiler.compile(arg.right, inst);
        bound.push((a) => feature(a) === value(a));
    }
    return bound;
}

/** Every assignment of the variables that keeps the constraints, with at most one variable of each exclusive group set. */
function validConfigurations(tree: CompiledTree, keys: readonly string[]): Assignment[] {
    const groups = [...tree.compiler.exclusive.values()].filter((g) => g.length > 1).map((g) => g.map((k) => 2 ** keys.indexOf(k)));
    const configurations: Assignment[] = [];
    for (let a = 0; a < 2 ** keys.length; a++) {
        if (groups.some((g) => g.filter((bit) => Math.floor(a / bit) % 2 === 1).length > 1)) continue;
        if (tree.constraints.every((f) => f(a))) configurations.push(a);
    }
    return configurations;
}

/** One configuration per distinct decision of the variation points (up to one more than MAX_VARIANTS, to tell "too many"). */
function distinctVariants(configurations: readonly Assignment[], signature: (a: Assignment) => string): Assignment[] {
    const variants: Assignment[] = [];
    const seen = new Set<string>();
    for (const a of configurations) {
        const sig = signature(a);
        if (seen.has(sig)) continue;
        seen.add(sig);
        variants.push(a);
        if (variants.length > MAX_VARIANTS) break;
    }
    return variants;
}

/** Instance prefix -> the compiled condition of each of its variation points. */
function formulasByInstance(points: readonly InstancePoint[]): Map<string, Map<VarIf, Formula>> {
    const formulaOf = new Map<string, Map<VarIf, Formula>>();
    for (const p of points) {
        const m = formulaOf.get(p.inst.prefix) ?? new Map<VarIf, Formula>();
        m.set(p.point, p.formula);
        formulaOf.set(p.inst.prefix, m);
    }
    return formulaOf;
}

/** The decisions of configuration `a` for the checks, instance by instance. */
function analysisEnv(a: Assignment, formulaOf: ReadonlyMap<string, ReadonlyMap<VarIf, Formula>>): VariantEnv {
    const cache = new Map<string, VariantEnv>();
    const envFor = (prefix: string): VariantEnv => {
        const cached = cache.get(prefix);
        if (cached) return cached;
        const env: VariantEnv = {
            // A variation point outside the analysed tree (deeper than MAX_DEPTH): all of it.
            decide: (v) => formulaOf.get(prefix)?.get(v)?.(a) ?? true,
            sub: (s) => envFor(`${prefix}${s.name}.`),
        };
        cache.set(prefix, env);
        return env;
    };
    return envFor('');
}

/** The decisions of configuration `a` for the generators: as for the checks, plus each instance's feature values. */
function generationEnv(
    a: Assignment,
    formulaOf: ReadonlyMap<string, ReadonlyMap<VarIf, Formula>>,
    points: readonly InstancePoint[],
    value: (a: Assignment, key: string) => boolean,
): VariantEnv {
    // Deeper than MAX_DEPTH an instance has no formulas of its own: it follows the first instance of its type.
    const first = new Map<VarIf, Formula>();
    for (const p of points) if (!first.has(p.point)) first.set(p.point, p.formula);
    const cache = new Map<string, VariantEnv>();
    const instanceEnv = (prefix: string): VariantEnv => {
        const cached = cache.get(prefix);
        if (cached) return cached;
        const own = formulaOf.get(prefix);
        const env: VariantEnv = {
            decide: (v) => (own?.get(v) ?? first.get(v))?.(a) ?? true,
            sub: (s) => instanceEnv(`${prefix}${s.name}.`),
            featureValues: (c) => {
                const features = allFeatures(c);
                if (features.length === 0) return undefined;
                return Object.fromEntries(features.map((f) => [f.name, value(a, prefix + f.name)]));
            },
        };
        cache.set(prefix, env);
        return env;
    };
    return instanceEnv('');
}

/** The node a diagnostic about a variable of a subcomponent is reported on. */
export function variableNode(v: VariableInfo, fallback: AstNode): AstNode {
    return v.path[0] ?? fallback;
}
