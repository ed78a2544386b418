// The IDE's language table comes from the family's language facts: every file language is
// recognised by its extensions, and the highlighting keyword sets are the facts' keywords.
import { existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { describe, expect, test } from 'vitest';
import { PYTHON_KEYWORDS, PYTHON_SOFT_KEYWORDS } from '@maa/language-adl/python-keywords';
import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import {
    FAMILY_LANGUAGES,
    highlightWords,
    isModelFile,
    languageOf,
    LANGUAGE_FACT_BY_ID,
    MODEL_LANGUAGE_IDS,
    TYPES,
} from '../src/language-table.js';

describe('language table from the language facts', () => {
    test('every file language of the family is registered and recognised by its extensions', () => {
        const files = LANGUAGE_FACTS.languages.filter((l) => l.kind === 'file');
        expect(files.map((l) => l.id)).toEqual(expect.arrayContaining(['arc', 'arcapp', 'cd', 'ra']));
        expect(FAMILY_LANGUAGES.map((l) => l.id)).toEqual(files.map((l) => l.id));
        for (const l of files) {
            expect(l.fileExtensions.length, l.id).toBeGreaterThan(0);
            for (const ext of l.fileExtensions) {
                expect(languageOf(`models/pkg/Some${ext}`)).toBe(l.id);
                expect(isModelFile(`models/pkg/Some${ext}`)).toBe(true);
            }
        }
        expect(MODEL_LANGUAGE_IDS).toEqual(files.map((l) => l.id));
        // Behavior languages have no files and are not Monaco languages of their own.
        for (const l of LANGUAGE_FACTS.languages.filter((f) => f.kind === 'behavior')) expect(MODEL_LANGUAGE_IDS).not.toContain(l.id);
    });

    test('plain files keep their languages and are not model files', () => {
        expect(languageOf('gen/main.py')).toBe('python');
        expect(languageOf('toast/Controller.stream')).toBe('maa-stream');
        expect(languageOf('CMakeLists.txt')).toBe('plaintext');
        expect(isModelFile('toast/Controller.stream')).toBe(false);
        expect(isModelFile('README.md')).toBe(false);
    });

    test("the highlighting words of a language are its facts' keywords, split into keywords, types, constants and units", () => {
        for (const fact of LANGUAGE_FACTS.languages) {
            const { keywords, constants, units } = highlightWords(fact);
            const all = [...fact.keywords, ...fact.softKeywords];
            expect([...keywords, ...constants, ...units, ...all.filter((w) => TYPES.includes(w))].sort()).toEqual([...all].sort());
        }
        const robotarm = highlightWords(LANGUAGE_FACT_BY_ID.get('robotarm')!);
        expect(robotarm.constants).toEqual(['bottom', 'top']);
        expect(robotarm.units).toEqual(['cm', 'deg', 'm', 'mm', 'rad']);
        expect(robotarm.keywords).toEqual(expect.arrayContaining(['location', 'program', 'move']));
        const arc = highlightWords(LANGUAGE_FACT_BY_ID.get('arc')!);
        expect(arc.keywords).toEqual(expect.arrayContaining(['component', 'port', 'compute']));
        expect(arc.keywords).not.toContain('int');
        expect(arc.constants).toEqual([]);
    });
});

describe('Monarch grammars from the language facts', () => {
    // Monaco's own Monarch compiler: it rejects a case naming an undefined word list and a
    // `next` state that does not exist, as Monaco would when the IDE registers the grammar.
    type Compiled = { start: string | null; tokenizer: Record<string, unknown> };
    // Not in the package's `exports`: imported by file, from the nearest node_modules that has it.
    const compilerUrl = (): string => {
        const relative = join(
            'node_modules',
            '@codingame',
            'monaco-vscode-editor-api',
            'vscode',
            'src',
            'vs',
            'editor',
            'standalone',
            'common',
            'monarch',
            'monarchCompile.js',
        );
        for (let dir = dirname(fileURLToPath(import.meta.url)); dirname(dir) !== dir; dir = dirname(dir)) {
            if (existsSync(join(dir, relative))) return pathToFileURL(join(dir, relative)).href;
        }
        throw new Error(`no ${relative} above the test`);
    };
    const compile = async (id: string, json: unknown): Promise<Compiled> =>
        ((await import(/* @vite-ignore */ compilerUrl())) as { compile: (id: string, json: unknown) => Compiled }).compile(id, json);

    test("every file language's grammar compiles, with a state per embedded behavior language", async () => {
        const { familyGrammar } = await import('../src/monarch-grammars.js');
        for (const lang of FAMILY_LANGUAGES) {
            const fact = LANGUAGE_FACT_BY_ID.get(lang.id)!;
            const grammar = familyGrammar(fact) as unknown as Record<string, unknown> & { tokenizer: Record<string, unknown> };
            const compiled = await compile(lang.id, grammar);
            // Monarch starts in `start`, or else in the first state: it must be `root`, not `comment`.
            expect(compiled.start, lang.id).toBe('root');
            expect(Object.keys(grammar.tokenizer)[0], lang.id).toBe('root');
            const embedded = new Set<string>();
            const visit = (id: string): void => {
                for (const e of LANGUAGE_FACT_BY_ID.get(id)?.embeds ?? [])
                    if (!embedded.has(e)) {
                        embedded.add(e);
                        visit(e);
                    }
            };
            visit(lang.id);
            expect(Object.keys(compiled.tokenizer).sort(), lang.id).toEqual(
                ['comment', 'root', 'string', ...[...embedded].map((e) => `embedded_${e}`)].sort(),
            );
            expect(grammar[`keywords_${lang.id}`], lang.id).toEqual(highlightWords(fact).keywords);
            for (const e of embedded)
                expect(grammar[`keywords_${e}`], `${lang.id} > ${e}`).toEqual(highlightWords(LANGUAGE_FACT_BY_ID.get(e)!).keywords);
        }
    });

    test("the Python grammar compiles and highlights language-adl's Python keywords, hard and soft", async () => {
        const { pythonGrammar } = await import('../src/monarch-grammars.js');
        const grammar = pythonGrammar() as unknown as { keywords: string[] };
        await compile('python', grammar);
        expect(grammar.keywords).toEqual(expect.arrayContaining([...PYTHON_KEYWORDS, 'match', 'case']));
        expect(PYTHON_SOFT_KEYWORDS).toContain('type');
        // `type` is the builtin in generated code far more often than the soft keyword.
        expect(grammar.keywords).not.toContain('type');
        expect(grammar.keywords).toHaveLength(PYTHON_KEYWORDS.length + PYTHON_SOFT_KEYWORDS.length - 1);
    });

    test("the .arc grammar opens an automaton block at the behavior language's block keyword", async () => {
        const { familyGrammar } = await import('../src/monarch-grammars.js');
        const grammar = familyGrammar(LANGUAGE_FACT_BY_ID.get('arc')!) as unknown as {
            tokenizer: Record<string, Array<[RegExp, unknown]>>;
        };
        const openers = grammar.tokenizer.root!.map(([re]) => re).filter((re) => re instanceof RegExp && re.source.includes('\\{'));
        expect(openers.some((re) => re.test('automaton {'))).toBe(true);
        expect(openers.some((re) => re.test('robotarm {'))).toBe(true);
        expect(openers.some((re) => re.test('component {'))).toBe(false);
    });
});
