/**
 * The family's languages in Monaco: ids and file extensions (from the packages'
 * `maa.language.languages`), Monarch grammars for the lexical highlighting (embedded
 * `automaton { }` / `robotarm { }` blocks get their own keyword sets) and the language
 * configurations (comments, brackets). The server's semantic tokens refine the colours.
 */
import * as monaco from '@codingame/monaco-vscode-editor-api';

export interface FamilyLanguage {
    id: string;
    extensions: string[];
    aliases: string[];
}

export const FAMILY_LANGUAGES: readonly FamilyLanguage[] = [
    { id: 'arc', extensions: ['.arc'], aliases: ['MontiArc', 'arc'] },
    { id: 'cd', extensions: ['.cd'], aliases: ['Class diagram', 'cd'] },
    { id: 'ra', extensions: ['.ra'], aliases: ['RobotArm', 'ra'] },
    { id: 'arcapp', extensions: ['.arcapp'], aliases: ['Application configuration', 'arcapp'] },
];

/** Languages of plain files the workspace may hold (read-only highlighting). */
const OTHER_LANGUAGES: Record<string, string> = {
    '.py': 'python', '.json': 'json', '.md': 'markdown', '.stream': 'maa-stream', '.launch': 'python',
    '.xml': 'xml', '.txt': 'plaintext', '.cmake': 'plaintext', '.cfg': 'plaintext', '.toml': 'plaintext',
};

export const MODEL_LANGUAGE_IDS: readonly string[] = FAMILY_LANGUAGES.map((l) => l.id);

/** The Monaco language id of a workspace path. */
export function languageOf(path: string): string {
    const dot = path.lastIndexOf('.');
    const ext = dot >= 0 ? path.slice(dot) : '';
    const family = FAMILY_LANGUAGES.find((l) => l.extensions.includes(ext));
    if (family) return family.id;
    if (path.endsWith('CMakeLists.txt')) return 'plaintext';
    return OTHER_LANGUAGES[ext] ?? 'plaintext';
}

export function isModelFile(path: string): boolean {
    return MODEL_LANGUAGE_IDS.includes(languageOf(path));
}

const TYPES = ['boolean', 'byte', 'char', 'double', 'float', 'int', 'long', 'short', 'void', 'String'];
const ARC_KEYWORDS = ['package', 'import', 'component', 'extends', 'port', 'in', 'out', 'compute', 'init', 'automaton', 'robotarm',
    'if', 'else', 'for', 'while', 'return', 'true', 'false', 'null'];
// The words of `.stream` files (maa_timesync/streamtest.py; `run`, `empty`, `transform` and
// `features` are soft there: ports may be called so, but they are highlighted as statements).
const STREAM_KEYWORDS = ['component', 'test', 'state', 'ticks', 'Tk', 'run', 'empty', 'transform', 'features', 'true', 'false'];
const AUTOMATON_KEYWORDS = ['initial', 'state', 'entry', 'exit', 'do', 'Tick', 'if', 'else', 'for', 'while', 'true', 'false', 'null'];
const ROBOTARM_KEYWORDS = ['location', 'program', 'move', 'open', 'close', 'input', 'robotarm', 'package'];
const ROBOTARM_CONSTANTS = ['top', 'bottom'];
const ROBOTARM_UNITS = ['deg', 'rad', 'cm', 'mm', 'm'];
const CD_KEYWORDS = ['package', 'import', 'classdiagram', 'class', 'interface', 'enum', 'abstract', 'association', 'composition',
    'extends', 'implements', 'final', 'private', 'protected', 'public', 'static'];
const ARCAPP_KEYWORDS = ['application', 'for', 'platform', 'import', 'package'];

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
    comment: [[/[^/*]+/, 'comment'], [/\*\//, 'comment', '@pop'], [/[/*]/, 'comment']],
    string: [[/[^\\"]+/, 'string'], [/\\./, 'string.escape'], [/"/, 'string', '@pop']],
};

function arcGrammar(): monaco.languages.IMonarchLanguage {
    const word = (keywords: string, extra: Record<string, string> = {}): Rule => [/[A-Za-z_][\w]*/, {
        cases: { ...extra, [`@${keywords}`]: 'keyword', '@types': 'type', '[A-Z][\\w]*': 'type.identifier', '@default': 'identifier' },
    }];
    return {
        defaultToken: '',
        keywords: ARC_KEYWORDS,
        automatonKeywords: AUTOMATON_KEYWORDS,
        robotarmKeywords: ROBOTARM_KEYWORDS,
        robotarmConstants: ROBOTARM_CONSTANTS,
        units: ROBOTARM_UNITS,
        types: TYPES,
        tokenizer: {
            root: [
                [/(automaton)(\s*)(\{)/, ['keyword', '', { token: 'delimiter.bracket', next: '@automaton' }]],
                [/(robotarm)(\s*)(\{)/, ['keyword', '', { token: 'delimiter.bracket', next: '@robotarm' }]],
                ...common(),
                [/[{}()[\]]/, '@brackets'],
                word('keywords'),
            ],
            // An embedded automaton: nested braces (actions, blocks) stay in the automaton.
            automaton: [
                [/\{/, 'delimiter.bracket', '@automaton'],
                [/\}/, 'delimiter.bracket', '@pop'],
                ...common(),
                [/[()[\]]/, '@brackets'],
                word('automatonKeywords'),
            ],
            robotarm: [
                [/\{/, 'delimiter.bracket', '@robotarm'],
                [/\}/, 'delimiter.bracket', '@pop'],
                [/(\d+(?:\.\d*)?)(deg|rad|cm|mm|m)\b/, ['number', 'keyword.unit']],
                ...common(),
                [/[()[\]]/, '@brackets'],
                word('robotarmKeywords', { '@robotarmConstants': 'constant', '@units': 'keyword.unit' }),
            ],
            ...sharedStates,
        },
    } as monaco.languages.IMonarchLanguage;
}

function simpleGrammar(keywords: string[], extraRoot: Rule[] = [], constants: string[] = []): monaco.languages.IMonarchLanguage {
    return {
        defaultToken: '',
        keywords,
        constants,
        types: TYPES,
        units: ROBOTARM_UNITS,
        tokenizer: {
            root: [
                ...extraRoot,
                ...common(),
                [/[{}()[\]]/, '@brackets'],
                [/[A-Za-z_][\w]*/, {
                    cases: { '@keywords': 'keyword', '@constants': 'constant', '@types': 'type', '[A-Z][\\w]*': 'type.identifier', '@default': 'identifier' },
                }],
            ],
            ...sharedStates,
        },
    } as monaco.languages.IMonarchLanguage;
}

function pythonGrammar(): monaco.languages.IMonarchLanguage {
    return {
        defaultToken: '',
        keywords: ['False', 'None', 'True', 'and', 'as', 'assert', 'async', 'await', 'break', 'class', 'continue', 'def', 'del', 'elif',
            'else', 'except', 'finally', 'for', 'from', 'global', 'if', 'import', 'in', 'is', 'lambda', 'nonlocal', 'not', 'or', 'pass',
            'raise', 'return', 'try', 'while', 'with', 'yield', 'match', 'case'],
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
                [/[A-Za-z_]\w*/, { cases: { '@keywords': 'keyword', '@builtins': 'type', '[A-Z][\\w]*': 'type.identifier', '@default': 'identifier' } }],
                [/[{}()[\]]/, '@brackets'],
                [/[-+*/%=<>!&|^~:]+/, 'operator'],
            ],
            tripleDouble: [[/"""/, 'string', '@pop'], [/[^"]+/, 'string'], [/"/, 'string']],
            tripleSingle: [[/'''/, 'string', '@pop'], [/[^']+/, 'string'], [/'/, 'string']],
        },
    } as monaco.languages.IMonarchLanguage;
}

const braces: monaco.languages.LanguageConfiguration = {
    comments: { lineComment: '//', blockComment: ['/*', '*/'] },
    brackets: [['{', '}'], ['[', ']'], ['(', ')']],
    autoClosingPairs: [{ open: '{', close: '}' }, { open: '[', close: ']' }, { open: '(', close: ')' }, { open: '"', close: '"' }],
    surroundingPairs: [{ open: '{', close: '}' }, { open: '[', close: ']' }, { open: '(', close: ')' }, { open: '"', close: '"' }],
    indentationRules: { increaseIndentPattern: /\{[^}]*$/, decreaseIndentPattern: /^\s*\}/ },
};

/** Registers every language with Monaco (before any model of it is created). */
export function registerLanguages(): void {
    for (const lang of FAMILY_LANGUAGES) {
        monaco.languages.register({ id: lang.id, extensions: lang.extensions, aliases: lang.aliases });
        monaco.languages.setLanguageConfiguration(lang.id, braces);
    }
    monaco.languages.setMonarchTokensProvider('arc', arcGrammar());
    monaco.languages.setMonarchTokensProvider('cd', simpleGrammar(CD_KEYWORDS));
    monaco.languages.setMonarchTokensProvider('ra', simpleGrammar([...ROBOTARM_KEYWORDS, 'package'], [
        [/(\d+(?:\.\d*)?)(deg|rad|cm|mm|m)\b/, ['number', 'keyword.unit']],
    ], [...ROBOTARM_CONSTANTS, ...ROBOTARM_UNITS]));
    monaco.languages.setMonarchTokensProvider('arcapp', simpleGrammar(ARCAPP_KEYWORDS));

    for (const [id, config] of [['python', pythonGrammar()], ['maa-stream', simpleGrammar(STREAM_KEYWORDS)]] as const) {
        monaco.languages.register({ id });
        monaco.languages.setMonarchTokensProvider(id, config);
    }
    monaco.languages.setLanguageConfiguration('python', { comments: { lineComment: '#' } });
    for (const id of ['json', 'markdown', 'xml']) monaco.languages.register({ id });
}
