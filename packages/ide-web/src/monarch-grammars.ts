/**
 * The Monarch grammars of the IDE's lexical highlighting (no Monaco import at run time, so the
 * test can compile them with Monaco's Monarch compiler): the family's languages from their
 * language facts (see languages.ts), plain `.stream` word lists and Python.
 */
import type * as monaco from '@codingame/monaco-vscode-editor-api';
import { PYTHON_KEYWORDS, PYTHON_SOFT_KEYWORDS } from '@maa/language-adl/python-keywords';
import type { LanguageFact } from '@maa/language-server/language-facts';
import { highlightWords, LANGUAGE_FACT_BY_ID, TYPES } from './language-table.js';

type Rule = monaco.languages.IMonarchLanguageRule;

/** Comments, strings, numbers, stereotypes, operators: shared by every grammar. */
function common(): Rule[] {
    return [
        [/\/\*/, 'comment', '@comment'],
        [/\/\/.*$/, 'comment'],
        [/"([^"\\]|\\.)*$/, 'string.invalid'],
        [/"/, 'string', '@string'],
        [/'([^'\\]|\\.)'/, 'string'],
        [/<<\s*[A-Za-z_][\w]*\s*>>/, 'annotation'],
        [/\d+\.\d*([eE][-+]?\d+)?/, 'number.float'],
        [/\d+/, 'number'],
        [/->/, 'keyword.operator'],
        [/[=<>!]=|&&|\|\||\+\+|--|[-+*/%<>!=]/, 'operator'],
        [/[;,.]/, 'delimiter'],
    ];
}

const sharedStates: Record<string, Rule[]> = {
    comment: [
        [/[^/*]+/, 'comment'],
        [/\*\//, 'comment', '@pop'],
        [/[/*]/, 'comment'],
    ],
    string: [
        [/[^\\"]+/, 'string'],
        [/\\./, 'string.escape'],
        [/"/, 'string', '@pop'],
    ],
};

/**
 * The Monarch grammar of a file language: its keywords in `root`, and for every behavior
 * language it embeds a state entered at `<blockKeyword> {` and left at the matching `}` (nested
 * braces stay inside), with that language's keywords and its own embedded blocks.
 */
export function familyGrammar(fact: LanguageFact): monaco.languages.IMonarchLanguage {
    const attributes: Record<string, readonly string[]> = { types: TYPES };
    // Monarch starts in the first state of `tokenizer` unless `start` says otherwise: `root` is
    // created first, and named as the start state too.
    const states: Record<string, Rule[]> = {};
    const stateOf = (lang: LanguageFact, root: boolean): string => {
        const key = lang.id.replace(/\W/g, '_');
        const name = root ? 'root' : `embedded_${key}`;
        if (states[name]) return name;
        states[name] = [];
        const { keywords, constants, units } = highlightWords(lang);
        const cases: Record<string, string> = { '@types': 'type' };
        for (const [kind, words, token] of [
            ['keywords', keywords, 'keyword'],
            ['constants', constants, 'constant'],
            ['units', units, 'keyword.unit'],
        ] as const) {
            if (words.length === 0) continue;
            attributes[`${kind}_${key}`] = words;
            cases[`@${kind}_${key}`] = token;
        }
        const blocks: Rule[] = [];
        for (const id of lang.embeds) {
            const embedded = LANGUAGE_FACT_BY_ID.get(id);
            if (!embedded?.blockKeyword) continue;
            blocks.push([
                new RegExp(`(${embedded.blockKeyword})(\\s*)(\\{)`),
                ['keyword', '', { token: 'delimiter.bracket', next: `@${stateOf(embedded, false)}` }],
            ]);
        }
        states[name] = [
            ...(root
                ? []
                : ([
                      [/\{/, 'delimiter.bracket', `@${name}`],
                      [/\}/, 'delimiter.bracket', '@pop'],
                  ] satisfies Rule[])),
            ...blocks,
            ...(units.length > 0
                ? [[new RegExp(`(\\d+(?:\\.\\d*)?)(${units.join('|')})\\b`), ['number', 'keyword.unit']] satisfies Rule]
                : []),
            ...common(),
            root ? [/[{}()[\]]/, '@brackets'] : [/[()[\]]/, '@brackets'],
            [/[A-Za-z_][\w]*/, { cases: { ...cases, '[A-Z][\\w]*': 'type.identifier', '@default': 'identifier' } }],
        ];
        return name;
    };
    stateOf(fact, true);
    return {
        defaultToken: '',
        start: 'root',
        ...attributes,
        tokenizer: { ...states, ...sharedStates },
    } as monaco.languages.IMonarchLanguage;
}

export function simpleGrammar(keywords: string[]): monaco.languages.IMonarchLanguage {
    return {
        defaultToken: '',
        keywords,
        types: TYPES,
        tokenizer: {
            root: [
                ...common(),
                [/[{}()[\]]/, '@brackets'],
                [
                    /[A-Za-z_][\w]*/,
                    {
                        cases: { '@keywords': 'keyword', '@types': 'type', '[A-Z][\\w]*': 'type.identifier', '@default': 'identifier' },
                    },
                ],
            ],
            ...sharedStates,
        },
    } as monaco.languages.IMonarchLanguage;
}

/**
 * Python's keywords as the highlighting shows them: language-adl's lists (the one definition),
 * less the soft keyword `type`, which generated code reads far more often as the builtin.
 */
export const PYTHON_HIGHLIGHTED_KEYWORDS: readonly string[] = [
    ...PYTHON_KEYWORDS,
    ...PYTHON_SOFT_KEYWORDS.filter((word) => word !== 'type'),
];

export function pythonGrammar(): monaco.languages.IMonarchLanguage {
    return {
        defaultToken: '',
        keywords: PYTHON_HIGHLIGHTED_KEYWORDS,
        builtins: ['self', 'print', 'len', 'range', 'int', 'float', 'str', 'bool', 'dict', 'list', 'tuple', 'set', 'super', 'isinstance'],
        tokenizer: {
            root: [
                [/#.*$/, 'comment'],
                [/@[A-Za-z_][\w.]*/, 'annotation'],
                [/[rbfu]{0,2}"""/, 'string', '@tripleDouble'],
                [/[rbfu]{0,2}'''/, 'string', '@tripleSingle'],
                [/[rbfu]{0,2}"([^"\\]|\\.)*"/, 'string'],
                [/[rbfu]{0,2}'([^'\\]|\\.)*'/, 'string'],
                [/\d+(\.\d*)?([eE][-+]?\d+)?/, 'number'],
                [
                    /[A-Za-z_]\w*/,
                    { cases: { '@keywords': 'keyword', '@builtins': 'type', '[A-Z][\\w]*': 'type.identifier', '@default': 'identifier' } },
                ],
                [/[{}()[\]]/, '@brackets'],
                [/[-+*/%=<>!&|^~:]+/, 'operator'],
            ],
            tripleDouble: [
                [/"""/, 'string', '@pop'],
                [/[^"]+/, 'string'],
                [/"/, 'string'],
            ],
            tripleSingle: [
                [/'''/, 'string', '@pop'],
                [/[^']+/, 'string'],
                [/'/, 'string'],
            ],
        },
    } as monaco.languages.IMonarchLanguage;
}
