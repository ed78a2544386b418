import { type URI, UriUtils } from 'langium';
import type { ModelRoots } from '../model-roots.js';
import { PYTHON_KEYWORDS } from '../python-keywords.js';

export type NamedKind = 'component' | 'port' | 'field' | 'parameter' | 'subcomponent' | 'typeParameter' | 'state';
export const NAMED_KINDS: readonly NamedKind[] = ['component', 'port', 'field', 'parameter', 'subcomponent', 'typeParameter', 'state'];

/** `Tick` is the time-slice event of the stream semantics. */
const SEMANTIC = ['Tick'];

const JAVA = [
    'abstract',
    'assert',
    'boolean',
    'break',
    'byte',
    'case',
    'catch',
    'char',
    'class',
    'const',
    'continue',
    'default',
    'do',
    'double',
    'else',
    'enum',
    'extends',
    'final',
    'finally',
    'float',
    'for',
    'goto',
    'if',
    'implements',
    'import',
    'instanceof',
    'int',
    'interface',
    'long',
    'native',
    'new',
    'package',
    'private',
    'protected',
    'public',
    'return',
    'short',
    'static',
    'strictfp',
    'super',
    'switch',
    'synchronized',
    'this',
    'throw',
    'throws',
    'transient',
    'try',
    'void',
    'volatile',
    'while',
    'true',
    'false',
    'null',
];

// Python's keyword lists live in a file of their own (no imports), so the browser IDE can read
// them through the `@maa/language-adl/python-keywords` subpath without loading Langium.
export { PYTHON_KEYWORDS, PYTHON_SOFT_KEYWORDS } from '../python-keywords.js';

/** Project configuration (`maa.json` at a model root) as far as the checks read it. */
export interface RootConfiguration {
    /** Further reserved names per kind of named element (e.g. words a target platform reserves). */
    reservedNames?: Partial<Record<NamedKind | '*', string[]>>;
}

/**
 * The reserved names of each kind of named element: `Tick`, the keywords of Java (MontiArc's
 * host language) and of Python (our generators' target), plus what a model root's `maa.json`
 * adds (MontiArc, likewise, configures its reserved-keyword checks per element kind).
 */
export class ReservedNames {
    static readonly CONFIG_FILE = 'maa.json';
    private readonly defaults = new Set([...SEMANTIC, ...JAVA, ...PYTHON_KEYWORDS]);
    private readonly perRoot = new Map<string, RootConfiguration>();

    constructor(private readonly roots: ModelRoots) {}

    configure(root: URI, config: RootConfiguration): void {
        this.perRoot.set(this.roots.rootOf(UriUtils.joinPath(root, ReservedNames.CONFIG_FILE)), config);
    }

    /** Why a name is reserved for a kind of element in a document, or undefined. */
    reason(kind: NamedKind, name: string, documentUri: URI | string): string | undefined {
        if (SEMANTIC.includes(name)) return `'${name}' is the time-slice event of the stream semantics`;
        if (this.defaults.has(name)) return `'${name}' is a keyword of ${JAVA.includes(name) ? 'Java' : 'Python'}`;
        const config = this.perRoot.get(this.roots.rootOf(documentUri));
        const extra = config?.reservedNames;
        if (extra && ((extra[kind] ?? []).includes(name) || (extra['*'] ?? []).includes(name))) {
            return `'${name}' is reserved for ${kind} names by ${ReservedNames.CONFIG_FILE}`;
        }
        return undefined;
    }
}
