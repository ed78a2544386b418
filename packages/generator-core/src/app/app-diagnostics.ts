import type { DiagnosticCatalog } from '@maa/language-adl';

/**
 * The generators the examples below assume to be installed (the catalog tests configure
 * exactly these): a Python family (`py.*`) plus a few generators that do not fit it.
 */
export const DEMO_GENERATOR_MANIFESTS = [
    {
        name: 'py.Components',
        kind: 'component',
        supports: ['compute'],
        output: { gpl: 'python', rte: 'py-rte' },
        checks: ['components.BehaviorOrHandwritten'],
        entry: 'components.js',
    },
    { name: 'py.TracingComponents', kind: 'component', output: { gpl: 'python', rte: 'py-rte' }, entry: 'tracing.js' },
    { name: 'py.Automata', kind: 'behavior', language: 'automaton', output: { gpl: 'python', rte: 'py-rte' }, entry: 'automata.js' },
    {
        name: 'py.FlatAutomata',
        kind: 'behavior',
        language: 'automaton',
        output: { gpl: 'python', rte: 'py-rte' },
        checks: ['automata.Flat'],
        entry: 'flat.js',
    },
    {
        name: 'py.LegacyAutomata',
        kind: 'behavior',
        language: 'automaton',
        output: { gpl: 'python', rte: 'legacy-rte' },
        entry: 'legacy.js',
    },
    { name: 'py.DataTypes', kind: 'datatype', output: { gpl: 'python' }, checks: ['datatypes.NoGenerics'], entry: 'datatypes.js' },
    { name: 'py.Dataclasses', kind: 'datatype', output: { gpl: 'python' }, entry: 'dataclasses.js' },
    { name: 'java.Automata', kind: 'behavior', language: 'automaton', output: { gpl: 'java', rte: 'java-rte' }, entry: 'java.js' },
] as const;

const ROBOT = [
    'package robot;',
    '',
    'component Robot {',
    '  port in int distance;',
    '  port out boolean stop;',
    '',
    '  <<sync>> automaton {',
    '    initial { stop = false; } state Driving;',
    '    state Stopped;',
    '    Driving -> Stopped [distance < 10] / { stop = true; };',
    '  }',
    '}',
].join('\n');

const COMPUTED = [
    'package robot;',
    '',
    'component Robot {',
    '  port in int distance;',
    '  port out boolean stop;',
    '',
    '  compute {',
    '    stop = distance < 10;',
    '  }',
    '}',
].join('\n');

const HIERARCHICAL = [
    'package robot;',
    '',
    'component Robot {',
    '  port in int distance;',
    '  port out boolean stop;',
    '',
    '  <<sync>> automaton {',
    '    initial { stop = false; } state Driving {',
    '      initial state Fast;',
    '      state Slow;',
    '    };',
    '    state Stopped;',
    '    Driving -> Stopped [distance < 10] / { stop = true; };',
    '  }',
    '}',
].join('\n');

const VARIABLE = [
    'package robot;',
    '',
    'component Robot {',
    '  feature cautious;',
    '  port in int distance;',
    '  port out boolean stop;',
    '',
    '  varif (cautious) {',
    '    compute {',
    '      stop = distance < 20;',
    '    }',
    '  } else {',
    '    compute {',
    '      stop = distance < 10;',
    '    }',
    '  }',
    '}',
].join('\n');

function app(...platforms: string[]): string {
    return ['application App for robot.Robot {', ...platforms, '}'].join('\n');
}

function platform(name: string, ...generators: string[]): string {
    return [`  platform ${name} {`, ...generators.map((g) => `    ${g};`), '  }'].join('\n');
}

const FAMILY = ['py.Components', 'py.Automata', 'py.DataTypes'];

function example(appText: string, robot = ROBOT): Record<string, string> {
    return { 'robot/Robot.arc': robot, 'App.arcapp': appText };
}

/** The diagnostics of application configurations (`app/`). */
export const APP_DIAGNOSTICS: DiagnosticCatalog = {
    title: 'Application configurations',
    intro: [
        'Checks of application configurations (`.arcapp`, see [generating.md](generating.md)): the generators a platform',
        'selects must exist, fill the roles of a generator family, translate every behavior language the architecture',
        'uses, fit together, and accept the models (their own well-formedness rules). The examples assume these',
        'generators to be installed:',
        '',
        '| generator | kind | language / supports | output (GPL, RTE) | checks |',
        '|---|---|---|---|---|',
        ...DEMO_GENERATOR_MANIFESTS.map((m) => {
            const lang = 'language' in m ? m.language : 'supports' in m ? m.supports.join(', ') : '';
            const rte = 'rte' in m.output ? `, ${m.output.rte}` : '';
            const checks = 'checks' in m ? m.checks.join(', ') : '';
            return `| \`${m.name}\` | ${m.kind} | ${lang} | ${m.output.gpl}${rte} | ${checks} |`;
        }),
    ].join('\n'),
    entries: [
        {
            code: 'app/unknown-component',
            severity: 'error',
            rule: "The application names its architecture's top component type by a qualified name that resolves in the model root.",
            invalid: { files: example(app(platform('python', ...FAMILY)).replace('robot.Robot', 'robot.Robt')), at: 'robot.Robt' },
            valid: { files: example(app(platform('python', ...FAMILY))) },
        },
        {
            code: 'app/unknown-feature',
            severity: 'error',
            rule: 'A feature binding of the application (`for robot.Robot(cautious = true)`) names a feature of its top component type.',
            invalid: {
                files: example(app(platform('python', ...FAMILY)).replace('robot.Robot', 'robot.Robot(careful = true)'), VARIABLE),
                at: 'careful',
            },
            valid: { files: example(app(platform('python', ...FAMILY)).replace('robot.Robot', 'robot.Robot(cautious = true)'), VARIABLE) },
        },
        {
            code: 'app/feature-configuration-excluded',
            severity: 'error',
            rule: 'The feature bindings of the application select a configuration that the constraints of the top component type (and of its subcomponents) admit (instances of one component type in different configurations are generated as variants of the type).',
            invalid: {
                files: example(
                    app(platform('python', ...FAMILY)).replace('robot.Robot', 'robot.Robot(cautious = false)'),
                    VARIABLE.replace('  feature cautious;', '  feature cautious;\n  constraint(cautious);'),
                ),
                at: 'cautious = false',
            },
            valid: {
                files: example(
                    app(platform('python', ...FAMILY)).replace('robot.Robot', 'robot.Robot(cautious = true)'),
                    VARIABLE.replace('  feature cautious;', '  feature cautious;\n  constraint(cautious);'),
                ),
            },
        },
        {
            code: 'app/unknown-generator',
            severity: 'error',
            rule: 'Every generator a platform lists is declared by an installed package (`maa-gen generators` lists them).',
            invalid: { files: example(app(platform('python', 'py.Component', 'py.Automata', 'py.DataTypes'))), at: 'py.Component' },
            valid: { files: example(app(platform('python', ...FAMILY))) },
        },
        {
            code: 'app/duplicate-platform',
            severity: 'error',
            rule: 'Platform names are unique within an application.',
            invalid: {
                files: example(
                    app(platform('python', ...FAMILY), platform('python', 'py.TracingComponents', 'py.Automata', 'py.DataTypes')),
                ),
                at: 'python',
            },
            valid: {
                files: example(
                    app(platform('python', ...FAMILY), platform('tracing', 'py.TracingComponents', 'py.Automata', 'py.DataTypes')),
                ),
            },
        },
        {
            code: 'app/repeated-generator',
            severity: 'warning',
            rule: 'A platform lists each generator once.',
            invalid: { files: example(app(platform('python', ...FAMILY, 'py.Automata'))), at: 'py.Automata' },
            valid: { files: example(app(platform('python', ...FAMILY))) },
        },
        {
            code: 'app/missing-component-generator',
            severity: 'error',
            rule: 'A platform has exactly one component generator: it translates components, ports and connectors and wraps the behaviors.',
            invalid: { files: example(app(platform('python', 'py.Automata', 'py.DataTypes'))), at: 'python' },
            valid: { files: example(app(platform('python', ...FAMILY))) },
        },
        {
            code: 'app/duplicate-component-generator',
            severity: 'error',
            rule: 'A platform has exactly one component generator.',
            invalid: { files: example(app(platform('python', ...FAMILY, 'py.TracingComponents'))), at: 'py.TracingComponents' },
            valid: { files: example(app(platform('python', 'py.TracingComponents', 'py.Automata', 'py.DataTypes'))) },
        },
        {
            code: 'app/missing-datatype-generator',
            severity: 'error',
            rule: 'A platform has exactly one data type generator: it translates the class diagrams.',
            invalid: { files: example(app(platform('python', 'py.Components', 'py.Automata'))), at: 'python' },
            valid: { files: example(app(platform('python', ...FAMILY))) },
        },
        {
            code: 'app/duplicate-datatype-generator',
            severity: 'error',
            rule: 'A platform has exactly one data type generator.',
            invalid: { files: example(app(platform('python', ...FAMILY, 'py.Dataclasses'))), at: 'py.Dataclasses' },
            valid: { files: example(app(platform('python', 'py.Components', 'py.Automata', 'py.Dataclasses'))) },
        },
        {
            code: 'app/uncovered-behavior-language',
            severity: 'error',
            rule: 'Every behavior language used anywhere in the architecture is translated by a behavior generator of the platform, or by its component generator (manifest `supports`).',
            invalid: { files: example(app(platform('python', 'py.Components', 'py.DataTypes'))), at: 'python' },
            valid: { files: example(app(platform('python', 'py.Components', 'py.DataTypes')), COMPUTED) },
        },
        {
            code: 'app/duplicate-behavior-generator',
            severity: 'error',
            rule: 'A platform has at most one behavior generator per behavior language.',
            invalid: { files: example(app(platform('python', ...FAMILY, 'py.FlatAutomata'))), at: 'py.FlatAutomata' },
            valid: { files: example(app(platform('python', 'py.Components', 'py.FlatAutomata', 'py.DataTypes'))) },
        },
        {
            code: 'app/gpl-mismatch',
            severity: 'error',
            rule: 'All generators of a platform produce the same general-purpose language (that of the component generator).',
            invalid: { files: example(app(platform('python', 'py.Components', 'java.Automata', 'py.DataTypes'))), at: 'java.Automata' },
            valid: { files: example(app(platform('python', ...FAMILY))) },
        },
        {
            code: 'app/rte-mismatch',
            severity: 'error',
            rule: 'Behavior generators write against the run-time environment the component generator wraps.',
            invalid: {
                files: example(app(platform('python', 'py.Components', 'py.LegacyAutomata', 'py.DataTypes'))),
                at: 'py.LegacyAutomata',
            },
            valid: { files: example(app(platform('python', ...FAMILY))) },
        },
        {
            code: 'app/generator-rule-violated',
            severity: 'error',
            rule: 'The models a generator translates satisfy the well-formedness rules its manifest declares (`checks`). Reported on the generator in the configuration, naming the rule and the model element; `maa-gen generate` reports it on the model element.',
            invalid: {
                files: example(app(platform('python', 'py.Components', 'py.FlatAutomata', 'py.DataTypes')), HIERARCHICAL),
                at: 'py.FlatAutomata',
            },
            valid: { files: example(app(platform('python', ...FAMILY)), HIERARCHICAL) },
        },
    ],
};
