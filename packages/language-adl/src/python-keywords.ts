/**
 * The `@maa/language-adl/python-keywords` subpath export: this file imports nothing, so the
 * browser IDE's Python highlighting reads the lists without loading Langium.
 */

/**
 * Python's keywords: names the Python generators cannot emit as identifiers (the one list; the
 * generators rename them, the reserved-name check reports them).
 */
export const PYTHON_KEYWORDS: readonly string[] = [
    'False',
    'None',
    'True',
    'and',
    'as',
    'assert',
    'async',
    'await',
    'break',
    'class',
    'continue',
    'def',
    'del',
    'elif',
    'else',
    'except',
    'finally',
    'for',
    'from',
    'global',
    'if',
    'import',
    'in',
    'is',
    'lambda',
    'nonlocal',
    'not',
    'or',
    'pass',
    'raise',
    'return',
    'try',
    'while',
    'with',
    'yield',
];

/** Python's soft keywords: valid identifiers, but the generators rename them too (a model may use `type`). */
export const PYTHON_SOFT_KEYWORDS: readonly string[] = ['match', 'case', 'type'];
