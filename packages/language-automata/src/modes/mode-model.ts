import { AstUtils, type AstNode } from 'langium';
import { behaviorsOf, elementsOf, subcomponentsOf, DEFAULT_TIMING, TIMINGS, type Timing, type ast as adl } from '@maa/language-adl';
import type { ComponentType, Connector, Mode, ModeAutomaton, ModeTransition, Subcomponent } from '../generated/ast.js';
import { isBehaviorDeclaration, isMode, isModeAutomaton } from '../generated/ast.js';

/**
 * Derived facts about mode automata (MontiArc's ArcMode) that the checks, the scopes, the
 * editor services and the generators share. Pure functions over the AST; they only read
 * `$type`, so they work on the AST of any language family build that composes this grammar.
 */

/**
 * A component of this package's AST or of the host's: a family build's AST is the host's with
 * more alternatives (modes), so the two types differ only in what may contain what.
 */
export type AnyComponentType = ComponentType | adl.ComponentType;

function host(c: AnyComponentType): adl.ComponentType {
    return c as adl.ComponentType;
}

/** The mode automata a component declares, in declaration order. */
export function modeAutomataOf(c: AnyComponentType): ModeAutomaton[] {
    return behaviorsOf(host(c))
        .map((b) => b.behavior as AstNode | undefined)
        .filter((b): b is ModeAutomaton => isModeAutomaton(b));
}

/** The mode automaton of a component (the first one; more than one is an error). */
export function modeAutomatonOf(c: AnyComponentType): ModeAutomaton | undefined {
    return modeAutomataOf(c)[0];
}

/** The modes of a mode automaton, in declaration order. */
export function modesOf(a: ModeAutomaton): Mode[] {
    return (a.elements as AstNode[]).filter(isMode);
}

/** The modes declared `initial`. */
export function initialModes(a: ModeAutomaton): Mode[] {
    return modesOf(a).filter((m) => m.initial);
}

/** The mode a mode automaton starts in: its (first) initial mode. */
export function startMode(a: ModeAutomaton): Mode | undefined {
    return initialModes(a)[0];
}

/** The transitions between the modes of a mode automaton, in declaration order. */
export function modeTransitionsOf(a: ModeAutomaton): ModeTransition[] {
    return (a.elements as AstNode[]).filter((e): e is ModeTransition => e.$type === 'ModeTransition');
}

/** The subcomponents a mode declares (active only in that mode). */
export function modeSubcomponents(m: Mode): Subcomponent[] {
    const result: Subcomponent[] = [];
    for (const e of m.elements) {
        if (e.$type === 'ComponentInstantiation' || e.$type === 'ComponentType') result.push(...e.instances);
    }
    return result;
}

/** The connectors a mode declares (active only in that mode). */
export function modeConnectors(m: Mode): Connector[] {
    return m.elements.filter((e): e is Connector => e.$type === 'Connector');
}

/** The subcomponents declared in any mode of a component's mode automata. */
export function allModeSubcomponents(c: AnyComponentType): Subcomponent[] {
    return modeAutomataOf(c).flatMap((a) => modesOf(a).flatMap(modeSubcomponents));
}

/**
 * Whether a component is decomposed for the mode rules: it has subcomponents, declared in its
 * body or in one of its modes.
 */
export function isDecomposedWithModes(c: AnyComponentType): boolean {
    return subcomponentsOf(host(c)).length > 0 || allModeSubcomponents(c).length > 0;
}

/** The mode a node lies in, if any. */
export function enclosingMode(node: AstNode): Mode | undefined {
    return AstUtils.getContainerOfType(node, isMode);
}

/** The mode automaton a node belongs to. */
export function enclosingModeAutomaton(node: AstNode): ModeAutomaton | undefined {
    return AstUtils.getContainerOfType(node, isModeAutomaton);
}

/** The component that declares a mode automaton (the component of its behavior declaration). */
export function modeAutomatonComponent(a: ModeAutomaton): ComponentType | undefined {
    return AstUtils.getContainerOfType(a, (n): n is ComponentType => n.$type === 'ComponentType');
}

/**
 * The timing of a mode automaton: the timing stereotype of its behavior declaration
 * (`<<sync>> mode automaton { }`), else `timed` (event-based, as in MontiArc).
 */
export function modeAutomatonTiming(a: ModeAutomaton): Timing {
    const decl = a.$container;
    const names = isBehaviorDeclaration(decl) ? (decl.stereotype?.values.map((v) => v.name) ?? []) : [];
    return names.find((n): n is Timing => (TIMINGS as readonly string[]).includes(n)) ?? DEFAULT_TIMING;
}

/** The elements of a component body other than its mode automata (the part every mode shares). */
export function sharedElements(c: AnyComponentType): adl.ComponentElement[] {
    return elementsOf(host(c)).filter((e) => !(e.$type === 'BehaviorDeclaration' && isModeAutomaton(e.behavior)));
}
