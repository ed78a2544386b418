import { Ajv, type ErrorObject, type ValidateFunction } from 'ajv';
import { GENERATOR_MANIFEST_SCHEMA } from './schema.js';

/** The three kinds of generators of a generator family (ARCHITECTURE.md section 6). */
export type GeneratorKind = 'component' | 'behavior' | 'datatype';
export const GENERATOR_KINDS: readonly GeneratorKind[] = ['component', 'behavior', 'datatype'];

/**
 * What a generator produces: the general-purpose language of its output and the run-time
 * environment the output is written against (e.g. `python` + `maa-python-behavior`). A data
 * type generator's output needs no RTE.
 */
export interface GeneratorOutput {
    readonly gpl: string;
    readonly rte?: string;
}

/**
 * Generation context a generator may require (besides the model element it translates):
 * - `ports`: the component's ports with resolved types, timing and direction;
 * - `parameters`, `fields`: the component's configuration parameters and fields;
 * - `component`: the whole component view (name, package, subcomponents, connectors);
 * - `package`: the model package of the translated element;
 * - `platform`: the selected platform and application name;
 * - `datatypes`: what the data type generator produced (type names per class-diagram type).
 */
export type ContextRequirement = 'ports' | 'parameters' | 'fields' | 'component' | 'package' | 'platform' | 'datatypes';
export const CONTEXT_REQUIREMENTS: readonly ContextRequirement[] = [
    'ports',
    'parameters',
    'fields',
    'component',
    'package',
    'platform',
    'datatypes',
];

interface ManifestBase {
    /** Qualified name, e.g. `ros2.Components`: what application configurations refer to. */
    readonly name: string;
    readonly kind: GeneratorKind;
    readonly description?: string;
    readonly output: GeneratorOutput;
    /** Names of well-formedness rules the translated models must satisfy (e.g. `datatypes.NoGenerics`). */
    readonly checks: readonly string[];
    /** Module implementing the generator, relative to the package folder (execution information). */
    readonly entry: string;
    /** Name of the module's export that creates the generator (default: `default`). */
    readonly export?: string;
    /** Folder of the generator's templates, relative to the package folder. */
    readonly templates?: string;
    /** Generation context the generator needs (see ContextRequirement). */
    readonly requires: readonly ContextRequirement[];
}

export interface ComponentGeneratorManifest extends ManifestBase {
    readonly kind: 'component';
    /** Behavior languages the component generator translates itself (e.g. `compute`). */
    readonly supports: readonly string[];
}

export interface BehaviorGeneratorManifest extends ManifestBase {
    readonly kind: 'behavior';
    /** The one embedded behavior language translated: the keyword of its block (e.g. `automaton`). */
    readonly language: string;
}

export interface DataTypeGeneratorManifest extends ManifestBase {
    readonly kind: 'datatype';
}

export type GeneratorManifest = ComponentGeneratorManifest | BehaviorGeneratorManifest | DataTypeGeneratorManifest;

/** Where a manifest was declared: the package, its folder and the JSON field (for messages). */
export interface ManifestSource {
    readonly packageName: string;
    readonly packageVersion: string;
    /** Absolute folder of the package (paths in the manifest are relative to it). */
    readonly packageDir: string;
    /** The file that holds the manifest: the package.json, or a JSON file it names. */
    readonly file: string;
    /** The JSON path of the manifest, e.g. `maa.generators[1]` (or `` for a manifest file). */
    readonly field: string;
}

/** An invalid manifest or package declaration, naming the package and the field. */
export class ManifestError extends Error {
    constructor(
        readonly packageName: string,
        readonly file: string,
        readonly field: string,
        readonly problem: string,
    ) {
        super(`generator package ${packageName} (${file}): ${field ? `${field}: ` : ''}${problem}`);
        this.name = 'ManifestError';
    }
}

let validator: ValidateFunction | undefined;

function compiled(): ValidateFunction {
    // Compiled on first use: tools that never read a manifest do not pay for it.
    return (validator ??= new Ajv({ allErrors: true, strict: true, strictRequired: false }).compile(GENERATOR_MANIFEST_SCHEMA));
}

/**
 * Validates a manifest (JSON, as read from a package) against the manifest schema and returns
 * it with defaults applied (`checks`, `requires`, `supports` empty). Throws a ManifestError
 * naming the package and the first offending field (`field` is the manifest's own JSON path).
 */
export function validateManifest(json: unknown, where: { packageName: string; file: string; field: string }): GeneratorManifest {
    const validate = compiled();
    if (!validate(json)) {
        const error = mostSpecific(validate.errors ?? []);
        throw new ManifestError(where.packageName, where.file, joinPath(where.field, error?.instancePath ?? ''), describe(error, json));
    }
    const m = json as Record<string, unknown>;
    const base = {
        ...m,
        checks: (m['checks'] as string[] | undefined) ?? [],
        requires: (m['requires'] as ContextRequirement[] | undefined) ?? [],
    };
    if (m['kind'] === 'component')
        return { ...base, supports: (m['supports'] as string[] | undefined) ?? [] } as unknown as ComponentGeneratorManifest;
    return base as unknown as GeneratorManifest;
}

/**
 * Ajv reports every failed keyword; a user needs the one that names the problem: errors of
 * `if`/`oneOf` wrappers are dropped, and the deepest remaining error wins.
 */
function mostSpecific(errors: readonly ErrorObject[]): ErrorObject | undefined {
    const real = errors.filter((e) => !['if', 'oneOf', 'anyOf', 'allOf', 'not'].includes(e.keyword));
    const pool = real.length > 0 ? real : errors;
    return [...pool].sort((a, b) => depth(b) - depth(a))[0];
}

function depth(e: ErrorObject): number {
    return e.instancePath.split('/').length + (e.keyword === 'required' || e.keyword === 'additionalProperties' ? 1 : 0);
}

function describe(e: ErrorObject | undefined, json: unknown): string {
    if (!e) return 'invalid manifest';
    if (e.keyword === 'false schema') {
        const kind = (json as { kind?: unknown }).kind;
        return `is not allowed for a ${String(kind)} generator`;
    }
    const p = e.params as Record<string, unknown>;
    switch (e.keyword) {
        case 'required':
            return `missing required field '${String(p['missingProperty'])}'`;
        case 'additionalProperties':
            return `unknown field '${String(p['additionalProperty'])}'`;
        case 'enum':
            return `must be one of ${(p['allowedValues'] as unknown[]).map((v) => JSON.stringify(v)).join(', ')}`;
        case 'pattern':
            return `${e.message ?? 'does not match'}${patternHint(e.instancePath)}`;
        default:
            return e.message ?? 'invalid';
    }
}

function patternHint(path: string): string {
    if (path === '/name') return ' (a qualified name such as "ros2.Components")';
    if (path.startsWith('/checks')) return ' (a qualified rule name such as "datatypes.NoGenerics")';
    return '';
}

/** `maa.generators[1]` + `/output/gpl` -> `maa.generators[1].output.gpl` (array items as `[i]`). */
export function joinPath(base: string, pointer: string): string {
    let out = base;
    for (const seg of pointer.split('/').slice(1)) {
        const s = seg.replace(/~1/g, '/').replace(/~0/g, '~');
        out += /^\d+$/.test(s) ? `[${s}]` : out ? `.${s}` : s;
    }
    return out;
}
