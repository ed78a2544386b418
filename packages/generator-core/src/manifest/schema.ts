/**
 * The JSON schema of a generator manifest (draft-07). Published as
 * `@maa/generator-core/generator-manifest.schema.json` (dist/, written at build time), so editors can
 * validate manifest files; the registry validates every manifest against it.
 */
const QUALIFIED = '^[A-Za-z_][A-Za-z0-9_]*(\\.[A-Za-z_][A-Za-z0-9_]*)*$';
const WORD = '^[A-Za-z_][A-Za-z0-9_-]*$';

export const GENERATOR_MANIFEST_SCHEMA = {
    $schema: 'http://json-schema.org/draft-07/schema#',
    $id: 'https://maa.invalid/schemas/generator-manifest.schema.json',
    title: 'MontiArcAutomaton generator manifest',
    description: 'Describes one generator of a generator family: what it translates, what it produces and how to run it.',
    type: 'object',
    required: ['name', 'kind', 'output', 'entry'],
    additionalProperties: false,
    properties: {
        name: {
            type: 'string',
            pattern: QUALIFIED,
            description: 'Qualified name used in application configurations, e.g. "ros2.Components".',
        },
        kind: { type: 'string', enum: ['component', 'behavior', 'datatype'] },
        description: { type: 'string' },
        language: {
            type: 'string',
            pattern: WORD,
            description: 'Behavior generators: the behavior language translated (the keyword of its block, e.g. "automaton").',
        },
        supports: {
            type: 'array',
            items: { type: 'string', pattern: WORD },
            uniqueItems: true,
            description: 'Component generators: behavior languages the component generator translates itself (e.g. "compute").',
        },
        output: {
            type: 'object',
            required: ['gpl'],
            additionalProperties: false,
            properties: {
                gpl: { type: 'string', minLength: 1, description: 'General-purpose language of the output, e.g. "python".' },
                rte: {
                    type: 'string',
                    minLength: 1,
                    description: 'Run-time environment the output is written against, e.g. "maa-python-behavior".',
                },
            },
        },
        checks: {
            type: 'array',
            items: { type: 'string', pattern: QUALIFIED },
            uniqueItems: true,
            description: 'Well-formedness rules the translated models must satisfy, e.g. "datatypes.NoGenerics".',
        },
        entry: { type: 'string', minLength: 1, description: 'Module implementing the generator, relative to the package folder.' },
        export: {
            type: 'string',
            pattern: '^[A-Za-z_$][A-Za-z0-9_$]*$',
            description: 'Export of the entry module that creates the generator (default: "default").',
        },
        templates: { type: 'string', minLength: 1, description: 'Folder of the templates, relative to the package folder.' },
        requires: {
            type: 'array',
            items: { type: 'string', enum: ['ports', 'parameters', 'fields', 'component', 'package', 'platform', 'datatypes'] },
            uniqueItems: true,
            description: 'Generation context the generator needs.',
        },
    },
    allOf: [
        {
            if: { type: 'object', properties: { kind: { const: 'behavior' } }, required: ['kind'] },
            then: {
                type: 'object',
                required: ['language'],
                properties: { supports: false, output: { type: 'object', required: ['rte'] } },
            },
        },
        {
            if: { type: 'object', properties: { kind: { const: 'component' } }, required: ['kind'] },
            then: { type: 'object', properties: { language: false, output: { type: 'object', required: ['rte'] } } },
        },
        {
            if: { type: 'object', properties: { kind: { const: 'datatype' } }, required: ['kind'] },
            then: { type: 'object', properties: { language: false, supports: false } },
        },
    ],
} as const;
