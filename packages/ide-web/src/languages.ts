/**
 * The family's languages in Monaco: ids, file extensions and aliases, and the keyword sets of
 * the Monarch grammars for the lexical highlighting, all from the language facts the grammar
 * composer writes (see language-table.ts); embedded blocks (`automaton { }`, `robotarm { }`: the
 * behavior languages a file language `embeds`) get their own keyword sets from their facts
 * (the grammars are built in monarch-grammars.ts). The language configurations (comments,
 * brackets) and the `.stream` words are kept here. The server's semantic tokens refine the colours.
 */
import * as monaco from '@codingame/monaco-vscode-editor-api';
import { FAMILY_LANGUAGES, LANGUAGE_FACT_BY_ID } from './language-table.js';
import { familyGrammar, pythonGrammar, simpleGrammar } from './monarch-grammars.js';

export { FAMILY_LANGUAGES, isModelFile, languageOf, MODEL_LANGUAGE_IDS, type FamilyLanguage } from './language-table.js';

// The words of `.stream` files (maa_timesync/streamtest.py; `run`, `empty`, `transform` and
// `features` are soft there: ports may be called so, but they are highlighted as statements).
// Stream tests are not a language of the family, so their words are not in the language facts.
const STREAM_KEYWORDS = ['component', 'test', 'state', 'ticks', 'Tk', 'run', 'empty', 'transform', 'features', 'true', 'false'];

const braces: monaco.languages.LanguageConfiguration = {
    comments: { lineComment: '//', blockComment: ['/*', '*/'] },
    brackets: [
        ['{', '}'],
        ['[', ']'],
        ['(', ')'],
    ],
    autoClosingPairs: [
        { open: '{', close: '}' },
        { open: '[', close: ']' },
        { open: '(', close: ')' },
        { open: '"', close: '"' },
    ],
    surroundingPairs: [
        { open: '{', close: '}' },
        { open: '[', close: ']' },
        { open: '(', close: ')' },
        { open: '"', close: '"' },
    ],
    indentationRules: { increaseIndentPattern: /\{[^}]*$/, decreaseIndentPattern: /^\s*\}/ },
};

/** Registers every language with Monaco (before any model of it is created). */
export function registerLanguages(): void {
    for (const lang of FAMILY_LANGUAGES) {
        monaco.languages.register({ id: lang.id, extensions: lang.extensions, aliases: lang.aliases });
        monaco.languages.setLanguageConfiguration(lang.id, braces);
    }
    for (const lang of FAMILY_LANGUAGES) {
        const fact = LANGUAGE_FACT_BY_ID.get(lang.id);
        if (fact) monaco.languages.setMonarchTokensProvider(lang.id, familyGrammar(fact));
    }
    for (const [id, config] of [
        ['python', pythonGrammar()],
        ['maa-stream', simpleGrammar(STREAM_KEYWORDS)],
    ] as const) {
        monaco.languages.register({ id });
        monaco.languages.setMonarchTokensProvider(id, config);
    }
    monaco.languages.setLanguageConfiguration('python', { comments: { lineComment: '#' } });
    for (const id of ['json', 'markdown', 'xml']) monaco.languages.register({ id });
}
