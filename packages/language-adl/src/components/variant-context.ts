import type { AstNode } from 'langium';
import type { ComponentBody, ComponentType, Subcomponent, VarIf } from '../generated/ast.js';

/**
 * The configuration that component-model.ts reads a component in (MontiArc's variable
 * architectures). Without one (`current === undefined`, the default for scoping, the LSP and
 * every check of a component without variability) the elements of a variation point are all
 * part of the component: both branches of a `varif`. With one, a `varif` contributes only the
 * branch its condition selects. The variability checks set a configuration while they run the
 * structural checks of a variable component once per configuration (variability.ts).
 */
export interface VariantEnv {
    /** Whether the condition of a variation point holds in this configuration. */
    decide(v: VarIf): boolean;
    /** The configuration of a subcomponent's type (its features, bound parameters). */
    sub(s: Subcomponent): VariantEnv;
    /** The values of a component type's features in this configuration, if known (generation). */
    featureValues?(c: ComponentType): Readonly<Record<string, boolean>> | undefined;
}

let current: VariantEnv | undefined;

/** The configuration being checked, if any. */
export function currentVariant(): VariantEnv | undefined {
    return current;
}

/** Runs `fn` with the model read in the configuration `env`. */
export function withVariant<T>(env: VariantEnv | undefined, fn: () => T): T {
    const saved = current;
    current = env;
    try {
        return fn();
    } finally {
        current = saved;
    }
}

/**
 * Runs `fn` (which reads the type of subcomponent `s`) in the configuration of that
 * subcomponent: its own features, not the enclosing component's.
 */
export function inSubcomponent<T>(s: Subcomponent, fn: () => T): T {
    return current ? withVariant(current.sub(s), fn) : fn();
}

type Element = ComponentBody['elements'][number];

const hasVariationPoint = new WeakMap<ComponentBody, boolean>();
const union = new WeakMap<ComponentBody, Element[]>();

/** The elements of a component body in the current configuration (see VariantEnv). */
export function configuredElements(body: ComponentBody | undefined): Element[] {
    if (!body) return [];
    let has = hasVariationPoint.get(body);
    if (has === undefined) {
        has = body.elements.some((e) => e.$type === 'VarIf');
        hasVariationPoint.set(body, has);
    }
    if (!has) return body.elements;
    const env = current;
    if (!env) {
        let all = union.get(body);
        if (!all) {
            all = [];
            flatten(body.elements, undefined, all);
            union.set(body, all);
        }
        return all;
    }
    const result: Element[] = [];
    flatten(body.elements, env, result);
    return result;
}

function flatten(elements: readonly Element[], env: VariantEnv | undefined, out: Element[]): void {
    for (const e of elements) {
        if (e.$type !== 'VarIf') {
            out.push(e);
            continue;
        }
        for (let v: VarIf | undefined = e; v; v = v.elseIf) {
            if (!env) {
                flatten(v.then?.elements ?? [], env, out);
                if (v.else) flatten(v.else.elements, env, out);
                continue;
            }
            if (env.decide(v)) {
                flatten(v.then?.elements ?? [], env, out);
                break;
            }
            if (v.else) flatten(v.else.elements, env, out);
        }
    }
}

/** The variation points of a body, nested ones included (with their else-if chains). */
export function variationPoints(elements: readonly Element[], out: VarIf[] = []): VarIf[] {
    for (const e of elements) {
        if (e.$type !== 'VarIf') continue;
        for (let v: VarIf | undefined = e; v; v = v.elseIf) {
            out.push(v);
            variationPoints(v.then?.elements ?? [], out);
            if (v.else) variationPoints(v.else.elements, out);
        }
    }
    return out;
}

/**
 * Candidates for a name used at `at`, those in `at`'s own variation branches (or in none) first:
 * branches exclude each other, so `varif (f) { A sub; } else { B sub; }` declares `sub` twice.
 */
export function sameBranchFirst<T extends AstNode>(at: AstNode, candidates: readonly T[]): T[] {
    const branches = new Set<AstNode>();
    for (let n: AstNode | undefined = at.$container; n; n = n.$container) if (n.$type === 'VarBody') branches.add(n);
    const visible = (node: AstNode): boolean => {
        for (let n: AstNode | undefined = node.$container; n; n = n.$container) {
            if (n.$type === 'VarBody' && !branches.has(n)) return false;
        }
        return true;
    };
    return [...candidates.filter(visible), ...candidates.filter((x) => !visible(x))];
}

/**
 * Sets the configuration for everything that follows, until set again (for asynchronous work
 * such as a generator run, which withVariant cannot span); returns the previous one.
 */
export function setVariant(env: VariantEnv | undefined): VariantEnv | undefined {
    const saved = current;
    current = env;
    return saved;
}

/**
 * The condition under which an element of a variation point is part of a configuration, as
 * text (`fast`, `!(fast) && safe`), or undefined outside variation points (the diagram shows it).
 */
export function variationCondition(node: AstNode | undefined): string | undefined {
    const parts: string[] = [];
    let child: AstNode | undefined = node;
    for (let n: AstNode | undefined = node?.$container; n; child = n, n = n.$container) {
        if (n.$type !== 'VarIf' || !child || child.$type !== 'VarBody') continue;
        const v = n as VarIf;
        const text = v.condition?.$cstNode?.text ?? '?';
        parts.unshift(v.then === child ? text : `!(${text})`);
        // An `else varif`: the earlier conditions of its chain are false too.
        for (let up: AstNode | undefined = v.$container; up?.$type === 'VarIf' && (up as VarIf).elseIf === n; n = up, up = up.$container) {
            parts.unshift(`!(${(up as VarIf).condition?.$cstNode?.text ?? '?'})`);
        }
    }
    return parts.length > 0 ? parts.join(' && ') : undefined;
}
