import type { AstNode } from 'langium';
import type { ComponentType, Feature, Subcomponent } from '../generated/ast.js';
import { parentsOf, subcomponentType } from './component-model.js';

type Element = ComponentType['body']['elements'][number];

/** The features a component type declares itself, in every variation point. */
export function ownFeatures(c: ComponentType): Feature[] {
    const result: Feature[] = [];
    const walk = (elements: readonly Element[]): void => {
        for (const e of elements) {
            if (e.$type === 'FeatureDeclaration') result.push(...e.features);
            else if (e.$type === 'VarIf') {
                for (let v: typeof e | undefined = e; v; v = v.elseIf) {
                    walk(v.then?.elements ?? []);
                    if (v.else) walk(v.else.elements);
                }
            }
        }
    };
    walk(c.body?.elements ?? []);
    return result;
}

/** Own and inherited features (an own feature hides an inherited one of the same name). */
export function allFeatures(c: ComponentType, seen = new Set<ComponentType>()): Feature[] {
    if (seen.has(c)) return [];
    seen.add(c);
    const own = ownFeatures(c);
    const names = new Set(own.map((f) => f.name));
    const result = [...own];
    for (const p of parentsOf(c)) {
        for (const f of allFeatures(p.decl, seen)) {
            if (!names.has(f.name)) {
                names.add(f.name);
                result.push(f);
            }
        }
    }
    return result;
}

/** The feature `member` of the subcomponent that `receiver` names (`sub.f`), if it is one. */
export function subcomponentFeature(receiver: AstNode | undefined, member: string): Feature | undefined {
    if (receiver?.$type !== 'NameExpression') return undefined;
    const target = (receiver as { ref?: { ref?: AstNode } }).ref?.ref;
    if (target?.$type !== 'Subcomponent') return undefined;
    const decl = subcomponentType(target as Subcomponent).decl;
    return decl ? allFeatures(decl).find((f) => f.name === member) : undefined;
}

/** Whether an instantiation argument binds a feature (`sub(f = true)`) rather than a parameter. */
export function isFeatureBinding(arg: AstNode): boolean {
    if (arg.$type !== 'AssignmentExpression') return false;
    const left = (arg as { left?: AstNode }).left;
    return left?.$type === 'NameExpression' && (left as { ref?: { ref?: AstNode } }).ref?.ref?.$type === 'Feature';
}
