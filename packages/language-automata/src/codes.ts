/**
 * The stable diagnostic codes of the automaton language (ARCHITECTURE.md section 5). Codes are
 * released API: never rename one. docs/diagnostics.md documents each with examples.
 */
export const AutomatonCodes = {
    NoInitialState: 'automaton/no-initial-state',
    MultipleInitialStates: 'automaton/multiple-initial-states',
    DuplicateState: 'automaton/duplicate-state',
    MissingState: 'automaton/missing-state',
    MissingEvent: 'automaton/missing-event',
    GuardNotBoolean: 'automaton/guard-not-boolean',
    EventInSync: 'automaton/event-in-sync',
    TickInUntimed: 'automaton/tick-in-untimed',
    UntimedNoEvent: 'automaton/untimed-no-event',
    InputInInitial: 'automaton/input-in-initial',
    Nondeterministic: 'automaton/nondeterministic',
    UnsupportedElement: 'automaton/unsupported-element',
} as const;

export type AutomatonCode = (typeof AutomatonCodes)[keyof typeof AutomatonCodes];
