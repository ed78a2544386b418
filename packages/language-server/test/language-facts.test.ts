// The language facts the grammar composer writes for the family (src/generated/language-facts.*)
// against the composed grammar and the running family: a keyword, a language or a file
// extension that one side has and the other lacks fails here.
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { EmptyFileSystem, GrammarAST, type Grammar } from 'langium';
import { describe, expect, test } from 'vitest';
import * as grammars from '../src/generated/grammar.js';
import { LANGUAGE_FACTS } from '../src/generated/language-facts.js';
import { createMaaServices } from '../src/family.js';

const here = dirname(fileURLToPath(import.meta.url));
const WORD = /^[A-Za-z_]\w*$/;

/** Every composed grammar of the family (one per file language; each holds the rules it uses). */
const composed: Grammar[] = Object.values(grammars)
    .filter((g): g is () => Grammar => typeof g === 'function')
    .map((g) => g());

function keywordsOf(rule: GrammarAST.AbstractRule): string[] {
    if (GrammarAST.isTerminalRule(rule)) return [];
    return collect(rule);
}

function collect(rule: GrammarAST.AbstractRule): string[] {
    const words: string[] = [];
    const walk = (node: object): void => {
        for (const [key, value] of Object.entries(node)) {
            if (key.startsWith('$')) continue;
            for (const item of Array.isArray(value) ? value : [value]) {
                if (!item || typeof item !== 'object' || typeof (item as { $type?: unknown }).$type !== 'string') continue;
                if (GrammarAST.isKeyword(item) && WORD.test(item.value)) words.push(item.value);
                walk(item);
            }
        }
    };
    walk(rule);
    return words;
}

const factKeywords = new Set([
    ...LANGUAGE_FACTS.softKeywords,
    ...LANGUAGE_FACTS.languages.flatMap((l) => [...l.keywords, ...l.softKeywords]),
]);

describe('language facts of the family', () => {
    test('every word keyword of the composed grammar is in the facts', () => {
        expect(composed.length).toBeGreaterThan(0);
        const missing = new Set<string>();
        for (const grammar of composed) {
            for (const rule of grammar.rules)
                for (const word of keywordsOf(rule)) if (!factKeywords.has(word)) missing.add(`${grammar.name}.${rule.name}: ${word}`);
        }
        expect([...missing]).toEqual([]);
    });

    test('the soft keywords are exactly the alternatives of the generated Name rule, and no language lists one as hard', () => {
        const name = composed[0]!.rules.find((r) => r.name === 'Name');
        expect(name).toBeDefined();
        expect([...new Set(keywordsOf(name!))].sort()).toEqual(LANGUAGE_FACTS.softKeywords);
        for (const l of LANGUAGE_FACTS.languages) {
            for (const w of l.keywords) expect(LANGUAGE_FACTS.softKeywords, `${l.id}: ${w}`).not.toContain(w);
            for (const w of l.softKeywords) expect(LANGUAGE_FACTS.softKeywords, `${l.id}: ${w}`).toContain(w);
        }
    });

    test('each language has the keywords of its own rules (spot checks) and embeds the behavior languages', () => {
        const byId = new Map(LANGUAGE_FACTS.languages.map((l) => [l.id, l]));
        expect(byId.get('arc')?.keywords).toEqual(expect.arrayContaining(['component', 'port', 'in', 'out', 'compute', 'if', 'true']));
        expect(byId.get('arc')?.embeds).toEqual(['automaton', 'robotarm']);
        expect(byId.get('cd')?.keywords).toEqual(expect.arrayContaining(['classdiagram', 'class', 'enum', 'association']));
        expect(byId.get('cd')?.keywords).not.toContain('component');
        expect(byId.get('automaton')).toMatchObject({ kind: 'behavior', blockKeyword: 'automaton', fileExtensions: [] });
        expect(byId.get('automaton')?.softKeywords).toEqual(expect.arrayContaining(['state', 'initial', 'entry', 'exit', 'Tick']));
        expect(byId.get('robotarm')?.softKeywords).toEqual(expect.arrayContaining(['location', 'program', 'move', 'top', 'deg']));
        expect(byId.get('arcapp')?.keywords).toEqual(expect.arrayContaining(['application', 'platform', 'for']));
        for (const l of LANGUAGE_FACTS.languages) {
            expect(l.scopeName).toMatch(new RegExp(`\\.${l.id}$`));
            expect(l.aliases.at(-1)).toBe(l.id);
        }
    });

    test('the file languages and extensions are those of the running family', () => {
        const services = createMaaServices(EmptyFileSystem);
        const running = services.shared.ServiceRegistry.all
            .map((s) => ({ id: s.LanguageMetaData.languageId, fileExtensions: [...s.LanguageMetaData.fileExtensions].sort() }))
            .sort((a, b) => a.id.localeCompare(b.id));
        const facts = LANGUAGE_FACTS.languages
            .filter((l) => l.kind === 'file')
            .map((l) => ({ id: l.id, fileExtensions: [...l.fileExtensions] }));
        expect(facts).toEqual(running);
    });

    test('the facts are sorted (reproducible builds) and the JSON file holds the same as the module', () => {
        const json = JSON.parse(readFileSync(join(here, '..', 'src', 'generated', 'language-facts.json'), 'utf8')) as unknown;
        expect(json).toEqual(LANGUAGE_FACTS);
        const ids = LANGUAGE_FACTS.languages.map((l) => l.id);
        expect(ids).toEqual([...ids].sort());
        for (const l of LANGUAGE_FACTS.languages) {
            for (const list of [l.keywords, l.softKeywords, l.fileExtensions, l.embeds]) expect(list).toEqual([...list].sort());
        }
    });
});
