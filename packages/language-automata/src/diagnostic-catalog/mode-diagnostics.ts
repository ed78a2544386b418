import type { CatalogEntry } from '@maa/language-adl';

const pass = 'component Pass {\n  port in int i;\n  port out int o;\n  <<sync>> compute {\n    o = i;\n  }\n}';
const negate = 'component Negate {\n  port in int i;\n  port out int o;\n  <<sync>> compute {\n    o = -i;\n  }\n}';
/** A decomposed component whose mode automaton is `body`. */
const switcher = (body: string, extra = ''): Readonly<Record<string, string>> => ({
    'Pass.arc': pass,
    'Negate.arc': negate,
    'Switch.arc': `component Switch {\n  port in int i;\n  port out int o;\n${extra}  <<sync>> mode automaton {\n${body}\n  }\n}`,
});
const twoModes =
    '    initial mode Up {\n      Pass p;\n      i -> p.i;\n      p.o -> o;\n    }\n    mode Down {\n      Negate n;\n      i -> n.i;\n      n.o -> o;\n    }\n    Up -> Down [i < 0];\n    Down -> Up [i >= 0];';

/** The diagnostics of mode automata and MontiArc's unsupported automaton elements (part of the automaton catalog). */
export const MODE_DIAGNOSTIC_ENTRIES: readonly CatalogEntry[] = [
    {
        code: 'mode/mode-automaton-in-atomic',
        severity: 'error',
        rule: 'Only a decomposed component (one with subcomponents, in its body or in its modes) declares a `mode automaton`: modes switch between configurations of subcomponents and connectors.',
        invalid: {
            files: {
                'Lamp.arc':
                    'component Lamp {\n  port in int i;\n  port out int o;\n  <<sync>> mode automaton {\n    initial mode On { }\n  }\n  <<sync>> compute {\n    o = i;\n  }\n}',
            },
            at: 'mode',
        },
        valid: { files: switcher(twoModes) },
    },
    {
        code: 'mode/multiple-mode-automata',
        severity: 'error',
        rule: 'A decomposed component declares at most one `mode automaton`; all its modes go into that one.',
        invalid: {
            files: {
                ...switcher(twoModes),
                'Switch.arc': switcher(twoModes)['Switch.arc']!.replace(
                    /\n}$/,
                    '\n  <<sync>> mode automaton {\n    initial mode Other { }\n  }\n}',
                ),
            },
            at: 'mode',
        },
        valid: { files: switcher(twoModes) },
    },
    {
        code: 'mode/state-in-mode-automaton',
        severity: 'error',
        rule: 'A mode automaton contains modes (`mode M { ... }`) and transitions between them, no states.',
        invalid: { files: switcher(`${twoModes}\n    state Idle;`), at: 'state' },
        valid: { files: switcher(twoModes) },
    },
    {
        code: 'mode/mode-in-statechart',
        severity: 'error',
        rule: 'An `automaton` contains states, no modes; modes belong into the `mode automaton` of a decomposed component.',
        invalid: {
            files: {
                'Lamp.arc': 'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    mode On { }\n  }\n}',
            },
            at: 'mode',
        },
        valid: {
            files: {
                'Lamp.arc': 'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    state On;\n  }\n}',
            },
        },
    },
    {
        code: 'mode/port-in-mode',
        severity: 'error',
        rule: 'A mode declares subcomponents and connectors only: the ports of a component are the same in every mode.',
        invalid: {
            files: switcher(twoModes.replace('      Negate n;', '      port in int extra;\n      Negate n;')),
            at: 'port in int extra;',
        },
        valid: { files: switcher(twoModes) },
    },
    {
        code: 'automaton/unsupported-element',
        severity: 'warning',
        rule: 'MontiArc automaton elements without meaning for the generated components are parsed and ignored with a warning: `final` states (a component runs forever) and actions of mode transitions (a decomposed component computes nothing itself).',
        invalid: {
            files: {
                'Lamp.arc':
                    'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    final state On;\n  }\n}',
            },
            at: 'final',
        },
        valid: {
            files: {
                'Lamp.arc': 'component Lamp {\n  port out boolean light;\n  automaton {\n    initial state Off;\n    state On;\n  }\n}',
            },
        },
    },
];
