/**
 * The stable diagnostic codes of mode automata (ARCHITECTURE.md section 5, `mode/*`). Codes are
 * released API: never rename one. docs/diagnostics.md documents each with examples. Mode
 * automata also report `automaton/no-initial-state`, `automaton/multiple-initial-states`,
 * `automaton/duplicate-state`, `automaton/missing-state`, `automaton/guard-not-boolean` and
 * `automaton/event-in-sync` for their modes and transitions.
 */
export const ModeCodes = {
    MultipleModeAutomata: 'mode/multiple-mode-automata',
    ModeAutomatonInAtomic: 'mode/mode-automaton-in-atomic',
    StateInModeAutomaton: 'mode/state-in-mode-automaton',
    ModeInStatechart: 'mode/mode-in-statechart',
    PortInMode: 'mode/port-in-mode',
} as const;

export type ModeCode = (typeof ModeCodes)[keyof typeof ModeCodes];
