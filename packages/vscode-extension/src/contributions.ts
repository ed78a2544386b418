/**
 * The extension's manifest contributions derived from the family's language facts: a language,
 * a language configuration and a generated TextMate grammar per file language, and the settings
 * and commands of the extension. bin/build.mjs writes them into the packaged manifest.
 */
import type { LanguageFacts } from '@maa/language-server/language-facts';
import {
    DIAGRAM_COMMANDS,
    DIAGRAM_PALETTE,
    DIAGRAM_SETTINGS,
    DIAGRAM_TITLE_MENU,
    iconFiles,
    languageIconOf,
} from './diagram/contributions.js';
import { SETTINGS } from './settings.js';
import { SIMULATE_COMMANDS, SIMULATE_SETTINGS } from './simulate/contributions.js';
import { TEST_SETTINGS } from './testing/test-settings.js';
import { fileLanguages, type TmGrammar, textMateGrammar } from './textmate.js';

/** The language configuration of every language of the family (C-like comments and brackets). */
export const LANGUAGE_CONFIGURATION = {
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
        { open: '"', close: '"', notIn: ['string', 'comment'] },
        { open: '/*', close: ' */', notIn: ['string'] },
    ],
    surroundingPairs: [
        ['{', '}'],
        ['[', ']'],
        ['(', ')'],
        ['"', '"'],
    ],
    indentationRules: { increaseIndentPattern: '\\{[^}]*$', decreaseIndentPattern: '^\\s*\\}' },
} as const;

export const COMMANDS = [
    { command: 'maa.generate', title: 'MontiArc: Generate', category: 'MontiArc' },
    { command: 'maa.showGeneratedCode', title: 'MontiArc: Show Generated Code', category: 'MontiArc' },
    { command: 'maa.showModelElement', title: 'MontiArc: Show Model Element', category: 'MontiArc' },
    ...SIMULATE_COMMANDS,
] as const;

/** A file the build writes next to the manifest (path relative to the extension folder). */
export interface ContributedFile {
    readonly path: string;
    readonly content: unknown;
}

export interface Contributions {
    /** The manifest's `contributes`. */
    readonly contributes: Record<string, unknown>;
    /** The generated grammars and configurations the manifest points at. */
    readonly files: ContributedFile[];
    /** When the extension activates. */
    readonly activationEvents: string[];
    /** The manifest's `capabilities`. */
    readonly capabilities: Record<string, unknown>;
}

/**
 * Restricted mode: the language server only reads the models, so it runs in untrusted workspaces;
 * Generate runs `maa-gen` (possibly the workspace's own `node_modules/.bin/maa-gen`), so it waits for trust.
 */
export const CAPABILITIES = {
    untrustedWorkspaces: {
        supported: 'limited',
        description: 'MontiArc: Generate runs maa-gen, possibly from the workspace, and is available in trusted workspaces only.',
        restrictedConfigurations: ['maa.generate.command', 'maa.server.nodeArgs', ...Object.keys(SIMULATE_SETTINGS), 'maa.test.python'],
    },
    virtualWorkspaces: false,
} as const;

/** Snippet files shipped in `snippets/` (hand-written: templates of a component, an automaton and an application). */
export const SNIPPET_FILES: Readonly<Record<string, string>> = { arc: 'snippets/arc.json', arcapp: 'snippets/arcapp.json' };

/** Everything the manifest contributes, from the family's language facts. */
export function contributions(facts: LanguageFacts): Contributions {
    const languages = fileLanguages(facts);
    const files: ContributedFile[] = [{ path: 'language-configuration.json', content: LANGUAGE_CONFIGURATION }];
    const grammars: Array<{ language: string; scopeName: string; path: string }> = [];
    for (const lang of languages) {
        const grammar: TmGrammar = textMateGrammar(lang, facts);
        const file = `syntaxes/${lang.id}.tmLanguage.json`;
        files.push({ path: file, content: grammar });
        grammars.push({ language: lang.id, scopeName: grammar.scopeName, path: `./${file}` });
    }
    for (const icon of iconFiles(languages)) files.push(icon);
    const snippets = languages
        .filter((l) => SNIPPET_FILES[l.id] !== undefined)
        .map((l) => ({ language: l.id, path: `./${SNIPPET_FILES[l.id]}` }));
    return {
        contributes: {
            languages: languages.map((l) => ({
                id: l.id,
                aliases: l.aliases,
                extensions: l.fileExtensions,
                configuration: './language-configuration.json',
                icon: languageIconOf(l),
            })),
            grammars,
            snippets,
            commands: [...COMMANDS, ...DIAGRAM_COMMANDS],
            menus: {
                'editor/title': [...DIAGRAM_TITLE_MENU],
                commandPalette: [
                    ...DIAGRAM_PALETTE,
                    { command: 'maa.showGeneratedCode', when: `editorLangId in maa.modelLanguages` },
                    { command: 'maa.showModelElement', when: 'editorIsOpen' },
                ],
            },
            configuration: {
                title: 'MontiArcAutomaton',
                properties: { ...SETTINGS, ...DIAGRAM_SETTINGS, ...TEST_SETTINGS, ...SIMULATE_SETTINGS },
            },
        },
        files,
        capabilities: CAPABILITIES,
        activationEvents: [
            ...languages.map((l) => `onLanguage:${l.id}`),
            'workspaceContains:**/*.arcapp',
            'workspaceContains:**/maa.json',
            'workspaceContains:**/*.stream',
        ],
    };
}
