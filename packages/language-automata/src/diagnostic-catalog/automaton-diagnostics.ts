import type { DiagnosticCatalog } from '@maa/language-adl';
import { MODE_DIAGNOSTIC_ENTRIES } from './mode-diagnostics.js';

/** The automaton language's diagnostics (`automaton/*`, and `arc/reserved-name` for state names). */
export const AUTOMATON_DIAGNOSTICS: DiagnosticCatalog = {
    title: 'Automata',
    intro:
        "Checks of embedded `automaton { }` blocks, after MontiArc's automaton context conditions. " +
        'An automaton without timing stereotype is `<<timed>>`. Statements in actions and initial blocks are checked like all statements (`expr/*`).',
    entries: [
        {
            code: 'automaton/no-initial-state',
            severity: 'error',
            rule:
                'An automaton has exactly one initial state among its top-level states (`initial state S;`). ' +
                'Inside a hierarchical state a missing initial substate is a warning: the state is then entered in its first substate, as in MontiArc.',
            invalid: {
                files: { 'Lamp.arc': 'component Lamp {\n  port out boolean light;\n  automaton {\n    state Off;\n    state On;\n  }\n}' },
                at: 'automaton',
            },
            valid: {
                files: {
                    'Lamp.arc': 'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    state On;\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/multiple-initial-states',
            severity: 'error',
            rule: 'At most one top-level state is `initial`. Inside a hierarchical state several initial substates are a warning: the first one is entered.',
            invalid: {
                files: {
                    'Lamp.arc':
                        'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    initial state On;\n  }\n}',
                },
                at: 'initial',
            },
            valid: {
                files: {
                    'Lamp.arc': 'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    state On;\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/duplicate-state',
            severity: 'error',
            rule: 'State names are unique in the whole automaton, substates included (transitions name states without qualification).',
            invalid: {
                files: {
                    'Door.arc':
                        'component Door {\n  port out boolean locked;\n  automaton {\n    initial state Closed {\n      initial state Open;\n    };\n    state Open;\n  }\n}',
                },
                at: 'Open',
            },
            valid: {
                files: {
                    'Door.arc':
                        'component Door {\n  port out boolean locked;\n  automaton {\n    initial state Closed {\n      initial state Latched;\n    };\n    state Open;\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/missing-state',
            severity: 'error',
            rule: 'The source and the target of a transition are states of the same automaton (at any depth).',
            invalid: {
                files: {
                    'Lamp.arc':
                        'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    Off -> On / { light = true; };\n  }\n}',
                },
                at: 'On',
            },
            valid: {
                files: {
                    'Lamp.arc':
                        'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    state On;\n    Off -> On / { light = true; };\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/missing-event',
            severity: 'error',
            rule: 'The event of a transition is an incoming port of the component (inherited ports included) or `Tick`.',
            invalid: {
                files: {
                    'Lamp.arc':
                        'component Lamp {\n  port in boolean button;\n  port out boolean light;\n  <<timed>> automaton {\n    initial state Off;\n    Off -> Off light / { light = false; };\n  }\n}',
                },
                at: 'light',
            },
            valid: {
                files: {
                    'Lamp.arc':
                        'component Lamp {\n  port in boolean button;\n  port out boolean light;\n  <<timed>> automaton {\n    initial state Off;\n    Off -> Off button / { light = button; };\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/guard-not-boolean',
            severity: 'error',
            rule: "A guard (`[ ... ]`) is an expression of type `boolean` (or `Boolean`) over the component's ports, fields and parameters.",
            invalid: {
                files: {
                    'Alarm.arc':
                        'component Alarm(int limit) {\n  port in int level;\n  port out boolean alarm;\n  <<sync>> automaton {\n    initial state Ok;\n    Ok -> Ok [level - limit] / { alarm = true; };\n  }\n}',
                },
                at: 'level - limit',
            },
            valid: {
                files: {
                    'Alarm.arc':
                        'component Alarm(int limit) {\n  port in int level;\n  port out boolean alarm;\n  <<sync>> automaton {\n    initial state Ok;\n    Ok -> Ok [level > limit] / { alarm = true; };\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/event-in-sync',
            severity: 'error',
            rule: 'A `<<sync>>` automaton fires once per time slice with all inputs of the slice, so its transitions name no event (no port, no `Tick`); test inputs in guards instead.',
            invalid: {
                files: {
                    'Relay.arc':
                        'component Relay {\n  port in int i;\n  port out int o;\n  <<sync>> automaton {\n    initial state S;\n    S -> S i / { o = i; };\n  }\n}',
                },
                at: 'i',
            },
            valid: {
                files: {
                    'Relay.arc':
                        'component Relay {\n  port in int i;\n  port out int o;\n  <<sync>> automaton {\n    initial state S;\n    S -> S / { o = i; };\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/tick-in-untimed',
            severity: 'error',
            rule: 'An `<<untimed>>` automaton does not observe time: no transition is triggered by `Tick`.',
            invalid: {
                files: {
                    'Relay.arc':
                        'component Relay {\n  port in int i;\n  port out int o;\n  <<untimed>> automaton {\n    initial state S;\n    S -> S Tick / { o = 0; };\n  }\n}',
                },
                at: 'Tick',
            },
            valid: {
                files: {
                    'Relay.arc':
                        'component Relay {\n  port in int i;\n  port out int o;\n  <<untimed>> automaton {\n    initial state S;\n    S -> S i / { o = 0; };\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/untimed-no-event',
            severity: 'error',
            rule: 'An `<<untimed>>` automaton reacts to messages only, so every transition (internal ones included) names the incoming port that triggers it.',
            invalid: {
                files: {
                    'Relay.arc':
                        'component Relay {\n  port in int i;\n  port out int o;\n  <<untimed>> automaton {\n    initial state S;\n    S -> S / { o = i; };\n  }\n}',
                },
                at: 'S -> S',
            },
            valid: {
                files: {
                    'Relay.arc':
                        'component Relay {\n  port in int i;\n  port out int o;\n  <<untimed>> automaton {\n    initial state S;\n    S -> S i / { o = i; };\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/input-in-initial',
            severity: 'error',
            rule: 'An initial block (`initial { ... } state S;`) runs before any input arrives: it may write outgoing ports and fields but not read incoming ports.',
            invalid: {
                files: {
                    'Delay.arc':
                        'component Delay {\n  port in int i;\n  port <<delayed>> out int o;\n  <<sync>> automaton {\n    initial { o = i; } state S;\n    S -> S / { o = i; };\n  }\n}',
                },
                at: 'i',
            },
            valid: {
                files: {
                    'Delay.arc':
                        'component Delay {\n  port in int i;\n  port <<delayed>> out int o;\n  <<sync>> automaton {\n    initial { o = 0; } state S;\n    S -> S / { o = i; };\n  }\n}',
                },
            },
        },
        {
            code: 'automaton/nondeterministic',
            severity: 'warning',
            rule:
                'Two transitions that start in the same state with the same trigger (the same incoming port; or the tick, i.e. `Tick` or no event, in a timed automaton; or any two transitions of a sync automaton) ' +
                'may be enabled at once when neither has a guard, when one of them has none, or when their guards are the same expression. ' +
                'The first declared transition fires then. The check is conservative: guards that differ in any other way are assumed to exclude each other, and transitions of a superstate are not compared with those of its substates.',
            invalid: {
                files: {
                    'Switch.arc':
                        'component Switch {\n  port in int i;\n  port out int o;\n  <<sync>> automaton {\n    initial state S;\n    state T;\n    S -> T [i > 0] / { o = 1; };\n    S -> S [i > 0] / { o = 2; };\n  }\n}',
                },
                at: 'S -> S [i > 0]',
            },
            valid: {
                files: {
                    'Switch.arc':
                        'component Switch {\n  port in int i;\n  port out int o;\n  <<sync>> automaton {\n    initial state S;\n    state T;\n    S -> T [i > 0] / { o = 1; };\n    S -> S [i <= 0] / { o = 2; };\n  }\n}',
                },
            },
        },
        {
            code: 'arc/reserved-name',
            severity: 'error',
            rule: "A state name is no reserved word (`Tick`, Java and Python keywords, and names a model root's `maa.json` reserves for states or for all kinds).",
            invalid: {
                files: { 'Gate.arc': 'component Gate {\n  port out boolean open;\n  automaton {\n    initial state pass;\n  }\n}' },
                at: 'pass',
            },
            valid: {
                files: { 'Gate.arc': 'component Gate {\n  port out boolean open;\n  automaton {\n    initial state Passing;\n  }\n}' },
            },
        },
        ...MODE_DIAGNOSTIC_ENTRIES,
    ],
};
