import type { AstNode } from 'langium';
import { type ast, behaviorsOf, timingsOf, DEFAULT_TIMING, type Timing } from '@maa/language-adl';
import type { ConnectorView, PortRef } from './architecture.js';

/**
 * Mode automata (language-automata's `mode automaton { }`) as the generators see them. The
 * generator core depends on the host language only, so it reads the mode automaton's AST by
 * `$type` and property names (`ModeAutomaton.elements`, `Mode.name/initial/elements`,
 * `ModeTransition.source/target/guard/event/tick`), the shape the automaton grammar declares.
 */

/** A mode: the subcomponents and connectors active (besides the component's own) while in it. */
export interface ModeView {
    readonly name: string;
    readonly initial: boolean;
    /** The names of the subcomponents the mode declares (the component view lists them all). */
    readonly subcomponents: readonly string[];
    readonly connectors: readonly ConnectorView[];
    readonly node: AstNode;
}

/** A transition between modes: taken when its trigger arrives and its guard holds. */
export interface ModeTransitionView {
    readonly source: string;
    readonly target: string;
    readonly guard?: AstNode;
    /** The incoming port that triggers it, `Tick`, or none (sync: every slice; event-based: the tick). */
    readonly trigger: { readonly kind: 'none' } | { readonly kind: 'tick' } | { readonly kind: 'port'; readonly port: string };
    readonly node: AstNode;
}

export interface ModeAutomatonView {
    readonly timing: Timing;
    /** The initial mode (the first one marked `initial`; the checks require exactly one). */
    readonly initial: string;
    readonly modes: readonly ModeView[];
    readonly transitions: readonly ModeTransitionView[];
    readonly node: AstNode;
}

interface ModeNode extends AstNode {
    name: string;
    initial: boolean;
    elements: ast.ComponentElement[];
}

interface ModeTransitionNode extends AstNode {
    source?: { $refText: string };
    target?: { $refText: string };
    guard?: AstNode;
    event?: { $refText: string };
    tick: boolean;
}

function isModeAutomatonNode(n: AstNode | undefined): n is AstNode & { elements: AstNode[] } {
    return n?.$type === 'ModeAutomaton';
}

/** The behavior declarations of a component that are mode automata. */
export function modeAutomatonDeclarations(c: ast.ComponentType): ast.BehaviorDeclaration[] {
    return behaviorsOf(c).filter((b) => isModeAutomatonNode(b.behavior as AstNode | undefined));
}

/** Whether a behavior block is a mode automaton (no behavior of its own: it configures subcomponents). */
export function isModeAutomatonBlock(node: AstNode | undefined): boolean {
    return isModeAutomatonNode(node);
}

/** The subcomponents declared in the modes of a component's mode automata. */
export function modeSubcomponentsOf(c: ast.ComponentType): ast.Subcomponent[] {
    return modeAutomatonDeclarations(c).flatMap((b) =>
        modesOf(b.behavior as unknown as AstNode & { elements: AstNode[] }).flatMap((m) => subcomponentsIn(m.elements)),
    );
}

function modesOf(a: AstNode & { elements: AstNode[] }): ModeNode[] {
    return a.elements.filter((e): e is ModeNode => e.$type === 'Mode');
}

function subcomponentsIn(elements: readonly ast.ComponentElement[]): ast.Subcomponent[] {
    const out: ast.Subcomponent[] = [];
    for (const e of elements) {
        if (e.$type === 'ComponentInstantiation' || e.$type === 'ComponentType') out.push(...e.instances);
    }
    return out;
}

/** The view of a component's mode automaton (the first one; the checks allow one), if it has one. */
export function modeAutomatonView(c: ast.ComponentType): ModeAutomatonView | undefined {
    const decl = modeAutomatonDeclarations(c)[0];
    if (!decl) return undefined;
    const a = decl.behavior as unknown as AstNode & { elements: AstNode[] };
    const modes = modesOf(a).map((m) => ({
        name: m.name,
        initial: m.initial,
        subcomponents: subcomponentsIn(m.elements).map((s) => s.name),
        connectors: m.elements
            .filter((e): e is ast.Connector => e.$type === 'Connector')
            .map((e) => ({ source: portRef(e.source), targets: e.targets.map(portRef), node: e })),
        node: m,
    }));
    const transitions = a.elements
        .filter((e) => e.$type === 'ModeTransition')
        .map((e) => {
            const t = e as ModeTransitionNode;
            const trigger: ModeTransitionView['trigger'] = t.tick
                ? { kind: 'tick' }
                : t.event
                  ? { kind: 'port', port: t.event.$refText }
                  : { kind: 'none' };
            return { source: t.source?.$refText ?? '', target: t.target?.$refText ?? '', guard: t.guard, trigger, node: t };
        });
    return {
        timing: timingsOf(decl.stereotype)[0] ?? DEFAULT_TIMING,
        initial: (modes.find((m) => m.initial) ?? modes[0])?.name ?? '',
        modes,
        transitions,
        node: a,
    };
}

function portRef(p: ast.PortAccess): PortRef {
    return p.subcomponent ? { subcomponent: p.subcomponent.$refText, port: p.port?.$refText ?? '' } : { port: p.port?.$refText ?? '' };
}
