// The generated TextMate grammars, run by the engine VS Code runs them with (vscode-textmate on
// vscode-oniguruma): every regular expression compiles, every keyword and soft keyword of every
// file language gets its scope, the blocks of the embedded behavior languages get theirs, and
// identifiers that only contain a keyword stay unhighlighted.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { LANGUAGE_FACTS, type LanguageFact } from '@maa/language-server/language-facts';
import * as oniguruma from 'vscode-oniguruma';
import { INITIAL, type IGrammar, Registry } from 'vscode-textmate';
import { beforeAll, describe, expect, it } from 'vitest';
import { contributions } from '../src/contributions.js';
import { fileLanguages, type TmGrammar, type TmRule, textMateGrammar, wordsPattern } from '../src/textmate.js';

const require = createRequire(import.meta.url);
const facts = LANGUAGE_FACTS;
const byId = new Map(facts.languages.map((l) => [l.id, l] as const));

let registry: Registry;

beforeAll(async () => {
    const wasm = readFileSync(require.resolve('vscode-oniguruma/release/onig.wasm'));
    await oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength));
    const grammars = new Map(fileLanguages(facts).map((l) => [l.scopeName, textMateGrammar(l, facts)] as const));
    registry = new Registry({
        onigLib: Promise.resolve({
            createOnigScanner: (patterns: string[]) => new oniguruma.OnigScanner(patterns),
            createOnigString: (s: string) => new oniguruma.OnigString(s),
        }),
        loadGrammar: async (scopeName) => (grammars.get(scopeName) as unknown as import('vscode-textmate').IRawGrammar) ?? null,
    });
});

async function grammarOf(fact: LanguageFact): Promise<IGrammar> {
    const g = await registry.loadGrammar(fact.scopeName);
    if (!g) throw new Error(`no grammar for ${fact.id}`);
    return g;
}

/** Tokenizes `text` (several lines) and returns every token with its text and scopes. */
function tokens(grammar: IGrammar, text: string): Array<{ text: string; scopes: string[] }> {
    let state = INITIAL;
    const out: Array<{ text: string; scopes: string[] }> = [];
    for (const line of text.split('\n')) {
        const r = grammar.tokenizeLine(line, state);
        for (const t of r.tokens) out.push({ text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes });
        state = r.ruleStack;
    }
    return out;
}

function scopesOf(toks: ReturnType<typeof tokens>, word: string): string[][] {
    return toks.filter((t) => t.text.trim() === word).map((t) => t.scopes);
}

function regexesOf(rule: TmRule): string[] {
    return [rule.match, rule.begin, rule.end].filter((r): r is string => r !== undefined).concat((rule.patterns ?? []).flatMap(regexesOf));
}

describe('generated TextMate grammars', () => {
    const languages = fileLanguages(facts);

    it('exist for every file language of the family, with its scope name and extensions', () => {
        expect(languages.map((l) => l.id)).toEqual(expect.arrayContaining(['arc', 'cd', 'arcapp', 'ra']));
        for (const lang of languages) {
            const g: TmGrammar = textMateGrammar(lang, facts);
            expect(g.scopeName).toBe(lang.scopeName);
            expect(g.fileTypes.map((t) => `.${t}`)).toEqual(lang.fileExtensions);
        }
    });

    it('hold only regular expressions Oniguruma compiles', () => {
        for (const lang of languages) {
            const g = textMateGrammar(lang, facts);
            const all = [...g.patterns, ...Object.values(g.repository)].flatMap(regexesOf);
            expect(all.length).toBeGreaterThan(5);
            for (const re of all) expect(() => new oniguruma.OnigScanner([re]).dispose(), re).not.toThrow();
        }
    });

    for (const lang of fileLanguages(facts)) {
        it(`${lang.id}: every keyword and soft keyword gets its scope`, async () => {
            const grammar = await grammarOf(lang);
            const toks = tokens(grammar, `${lang.keywords.join(' ')}\n${lang.softKeywords.join(' ')}`);
            for (const kw of lang.keywords) expect(scopesOf(toks, kw), kw).toContainEqual([lang.scopeName, lang.scopes.keyword]);
            for (const kw of lang.softKeywords.filter((w) => !lang.keywords.includes(w))) {
                expect(scopesOf(toks, kw), kw).toContainEqual([lang.scopeName, lang.scopes.softKeyword]);
            }
        });
    }

    it('arc: comments, strings and numbers; names that merely contain a keyword are no keywords', async () => {
        const grammar = await grammarOf(byId.get('arc') as LanguageFact);
        const toks = tokens(grammar, 'component interface_ports { port in int x; } // port\n/* in\n out */ "in" 42');
        expect(scopesOf(toks, 'interface_ports')).toEqual([['source.arc']]);
        expect(toks.find((t) => t.text.includes('// port'))?.scopes).toContain('comment.arc');
        expect(toks.find((t) => t.text === ' out ')?.scopes).toContain('comment.arc');
        expect(toks.find((t) => t.text === 'in' && t.scopes.includes('string.quoted.double.arc'))).toBeDefined();
        expect(scopesOf(toks, '42')).toEqual([['source.arc', 'constant.numeric.arc']]);
    });

    it('arc: the blocks of the embedded behavior languages (transitively) get the embedded keywords, and the host resumes after the block', async () => {
        const arc = byId.get('arc') as LanguageFact;
        const automaton = byId.get('automaton') as LanguageFact;
        const robotarm = byId.get('robotarm') as LanguageFact;
        const grammar = await grammarOf(arc);
        // `initial` and `state` are automaton words, not arc ones; `move` is a RobotArm word.
        const text = `component C {\n  automaton {\n    ${automaton.keywords.join(' ')} ${automaton.softKeywords.join(' ')}\n    if (x) { state } robotarm { move }\n  }\n  port\n}`;
        const toks = tokens(grammar, text);
        for (const kw of automaton.keywords) {
            expect(
                scopesOf(toks, kw).some((s) => s.includes(automaton.scopeName) && s.includes(automaton.scopes.keyword)),
                kw,
            ).toBe(true);
        }
        for (const kw of automaton.softKeywords.filter((w) => !automaton.keywords.includes(w))) {
            expect(
                scopesOf(toks, kw).some((s) => s.includes(automaton.scopes.softKeyword)),
                kw,
            ).toBe(true);
        }
        expect(
            scopesOf(toks, 'move').some(
                (s) => s.includes(robotarm.scopeName) && s.some((x) => x.startsWith('keyword.') && x.endsWith('.robotarm')),
            ),
        ).toBe(true);
        // After the automaton's closing brace (with a nested `{ state }` inside), `port` is an arc keyword again.
        expect(scopesOf(toks, 'port').at(-1)).toEqual([arc.scopeName, arc.scopes.keyword]);
    });

    it('words are matched whole, longest first, with regex metacharacters escaped', () => {
        const re = new RegExp(wordsPattern(['in', 'int', 'a.b']));
        expect(re.exec('int')?.[0]).toBe('int');
        expect(re.test('inx')).toBe(false);
        expect(re.test('aXb')).toBe(false);
        expect(re.test('a.b')).toBe(true);
    });

    it('the manifest contributes each file language with its grammar and the shared language configuration', () => {
        const c = contributions(facts);
        const langs = c.contributes['languages'] as Array<{ id: string; extensions: string[]; configuration: string }>;
        expect(langs.map((l) => l.id).sort()).toEqual(languages.map((l) => l.id).sort());
        for (const l of langs) expect(l.extensions).toEqual(byId.get(l.id)?.fileExtensions);
        const paths = new Set(c.files.map((f) => `./${f.path}`));
        for (const g of c.contributes['grammars'] as Array<{ path: string }>) expect(paths.has(g.path)).toBe(true);
        expect(paths.has('./language-configuration.json')).toBe(true);
        expect(c.activationEvents).toContain('onLanguage:arc');
    });
});
