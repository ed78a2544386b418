import type { AstNode } from 'langium';
import { type ast as adl, behaviorsOf } from '@maa/language-adl';
import { allStates, allTransitions, statePath, type ast } from '@maa/language-automata';
import { isRobotArmBody, programSteps, programsOf } from '@maa/language-robotarm';
import { modeAutomatonView } from '@maa/generator-core';
import { FONTS, textWidth } from './sizes.js';

/**
 * What the C&C view says about a component's behavior besides its badge: the state paths its
 * current-state chip may show during a run (the chip's room is that of the widest), and, for an
 * atomic component shown on its own, a few lines about its automaton or RobotArm programs.
 */

/** The automaton of a component's behavior, if it has one. */
export function automatonOf(component: adl.ComponentType): ast.Automaton | undefined {
    return behaviorsOf(component)
        .map((b) => b.behavior as AstNode | undefined)
        .find((b): b is ast.Automaton => b?.$type === 'Automaton');
}

/** The state paths (`Outer.Inner`) of the component's automaton, or the names of its modes; empty without either. */
export function chipStates(component: adl.ComponentType): string[] {
    const automaton = automatonOf(component);
    if (automaton)
        return allStates(automaton).map((s) =>
            statePath(s)
                .map((p) => p.name)
                .join('.'),
        );
    return modeAutomatonView(component)?.modes.map((m) => m.name) ?? [];
}

/** The state path whose chip is widest (the chip's room is sized by it); undefined without states. */
export function widestState(states: readonly string[]): string | undefined {
    let best: string | undefined;
    for (const s of states) if (best === undefined || textWidth(s, FONTS.transition) > textWidth(best, FONTS.transition)) best = s;
    return best;
}

/** A line about the behavior; `opens` makes it a link to the component's automaton view. */
export interface BehaviorLine {
    readonly text: string;
    readonly source: AstNode;
    readonly opens?: 'automaton';
}

/** The widest a behavior line may get before its list is cut short. */
const MAX_LINE_WIDTH = 320;

/**
 * Lines for an atomic component shown on its own: its automaton (states and transitions, a link
 * to the automaton view, then its states) or its RobotArm programs (one line each, with their
 * number of steps). Empty for other behaviors.
 */
export function behaviorLines(component: adl.ComponentType): BehaviorLine[] {
    const automaton = automatonOf(component);
    if (automaton) {
        const states = chipStates(component);
        const n = allTransitions(automaton).length;
        return [
            {
                text: `automaton: ${states.length} state${states.length === 1 ? '' : 's'}, ${n} transition${n === 1 ? '' : 's'} (open ▸)`,
                source: automaton,
                opens: 'automaton',
            },
            { text: fitList('states: ', states), source: automaton },
        ];
    }
    const body = behaviorsOf(component)
        .map((b) => b.behavior as AstNode | undefined)
        .find((b) => isRobotArmBody(b));
    if (body && isRobotArmBody(body)) {
        const programs = programsOf(body);
        const lines: BehaviorLine[] = [{ text: `RobotArm programs: ${programs.length}`, source: body }];
        for (const p of programs) {
            const steps = programSteps(p).length;
            lines.push({ text: `▸ ${p.name} (${steps} step${steps === 1 ? '' : 's'})`, source: p });
        }
        return lines;
    }
    return [];
}

/** `prefix` and the items, comma separated, cut short with `…` where the line gets too wide. */
function fitList(prefix: string, items: readonly string[]): string {
    let text = prefix;
    for (const [i, item] of items.entries()) {
        const next = `${text}${i > 0 ? ', ' : ''}${item}`;
        if (textWidth(`${next}, …`, FONTS.port) > MAX_LINE_WIDTH) return `${text}${i > 0 ? ', ' : ''}…`;
        text = next;
    }
    return text;
}
