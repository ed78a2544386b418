import { AstUtils, type AstNode } from 'langium';
import type { RuleViolation, WellFormednessRule } from '../generators/types.js';

/**
 * The standard library of generator well-formedness rules: a generator names them in its
 * manifest's `checks`, and they are checked in the editor (on the application configuration)
 * and before generation (on the model elements) without running generator code.
 */
export const STANDARD_RULES: readonly WellFormednessRule[] = [
    {
        name: 'datatypes.NoGenerics',
        description: 'Class-diagram types used by the architecture have no type parameters.',
        *check({ dataTypes }) {
            for (const t of dataTypes) {
                if (t.typeParameters.length > 0) {
                    yield { node: t.node, message: `type '${t.qualifiedName}' is generic (<${t.typeParameters.join(', ')}>)` };
                }
            }
        },
    },
    {
        name: 'datatypes.NoInheritance',
        description: 'Class-diagram types used by the architecture extend or implement no other type.',
        *check({ dataTypes }) {
            for (const t of dataTypes) {
                if (t.superTypes.length > 0) {
                    yield { node: t.node, message: `type '${t.qualifiedName}' extends or implements ${t.superTypes.join(', ')}` };
                }
            }
        },
    },
    {
        name: 'components.NoGenerics',
        description: 'Component types have no type parameters.',
        *check({ components }) {
            for (const c of components) {
                if (c.typeParameters.length > 0) {
                    yield { node: c.node, message: `component type '${c.qualifiedName}' is generic (<${c.typeParameters.join(', ')}>)` };
                }
            }
        },
    },
    {
        name: 'components.NoInheritance',
        description: 'Component types extend no other component type.',
        *check({ components }) {
            for (const c of components) {
                if (c.parents.length > 0) {
                    yield { node: c.node, message: `component type '${c.qualifiedName}' extends ${c.parents.join(', ')}` };
                }
            }
        },
    },
    {
        name: 'components.NoModes',
        description: 'Decomposed component types have no mode automaton (a platform that wires subcomponents once cannot switch them).',
        *check({ components }) {
            for (const c of components) {
                if (c.modes) {
                    yield {
                        node: c.modes.node,
                        message: `component type '${c.qualifiedName}' has a mode automaton (modes ${c.modes.modes.map((m) => m.name).join(', ')})`,
                    };
                }
            }
        },
    },
    {
        name: 'components.BehaviorOrHandwritten',
        description: 'Every atomic component type has a behavior or is marked <<handwritten>>.',
        *check({ components }) {
            for (const c of components) {
                if (c.atomic && !c.behavior && !c.init && !c.handwritten) {
                    yield {
                        node: c.node,
                        message: `atomic component type '${c.qualifiedName}' has no behavior and is not <<handwritten>>`,
                    };
                }
            }
        },
    },
    {
        name: 'automata.Flat',
        description: 'Automata have no hierarchical states.',
        *check({ behaviors }) {
            for (const b of behaviors) {
                if (b.language !== 'automaton') continue;
                for (const s of AstUtils.streamAllContents(b.node)) {
                    if (
                        s.$type === 'State' &&
                        ((s as AstNode & { elements?: AstNode[] }).elements ?? []).some((e) => e.$type === 'State')
                    ) {
                        yield {
                            node: s,
                            message: `state '${(s as AstNode & { name?: string }).name}' of '${b.component}' is hierarchical`,
                        };
                    }
                }
            }
        },
    },
];

const BY_NAME = new Map(STANDARD_RULES.map((r) => [r.name, r]));

export function standardRule(name: string): WellFormednessRule | undefined {
    return BY_NAME.get(name);
}

export type { RuleViolation };
