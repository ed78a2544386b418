/**
 * What selecting a transition or program step reveals: its source position from the run's
 * automata table (C3) and the diagram highlight of the component's state and transition, as the
 * `reveal` message the VS Code extension acts on (host-messages.ts). Pure.
 */
import type { RevealMessage } from '../host-messages.js';
import { findTransition, type AutomatonInfo } from '../timeline/automata.js';
import type { ProgramStep, TakenTransition } from '../timeline/transitions.js';

/** The automaton of a node, `undefined` when the table has none. */
export function automatonOf(automata: readonly AutomatonInfo[], node: string): AutomatonInfo | undefined {
    return automata.find((a) => a.node === node);
}

/**
 * The reveal of a transition taken: the line of the transition (by its index, else its states);
 * the target state's line when the table lists no such transition; `undefined` when the table
 * does not know the node.
 */
export function revealTransition(automata: readonly AutomatonInfo[], taken: TakenTransition): RevealMessage | undefined {
    const a = automatonOf(automata, taken.node);
    if (!a) return undefined;
    const tr = findTransition(a, taken);
    const state = a.states.find((s) => s.path === taken.to);
    const line = tr?.line ?? state?.line;
    if (line === undefined) return undefined;
    return {
        type: 'reveal',
        file: a.file,
        line,
        ...(tr ? { column: tr.column } : {}),
        highlight: {
            component: a.component,
            instancePath: a.instancePath,
            state: taken.to,
            ...(tr ? { transition: { from: tr.from, to: tr.to, index: tr.index } } : {}),
        },
    };
}

/** The reveal of a RobotArm program step: its line in its file, when the step names the file. */
export function revealProgramStep(step: ProgramStep): RevealMessage | undefined {
    if (!step.file || step.line < 1) return undefined;
    return { type: 'reveal', file: step.file, line: step.line };
}
