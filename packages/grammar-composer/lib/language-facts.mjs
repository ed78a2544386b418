// @ts-check
/**
 * The language facts of a composed family: for every language its id, file extensions, aliases,
 * keywords (read from the composed Langium grammar) and TextMate-style scope names. Clients that
 * need to know the family's languages without running it (the IDE's lexical highlighting, the
 * CLI's file discovery, editor extensions) read these instead of restating them.
 *
 * Two kinds of languages:
 *   - file languages (`maa.language.languages`): a grammar's entry rule and file extensions;
 *   - behavior languages (`maa.language.behavior`): the rule that fills the host's `Behavior`
 *     slot, opened by a block keyword (`automaton { }`); they have no files of their own.
 *
 * A language's keywords are the word keywords of every parser rule reachable from its entry rule
 * (its behavior rule), not descending into identifier rules (`Name`, generated, which admits
 * every soft keyword of the family; `NameSegment`, which admits keywords after a dot) nor into the behavior rules of embedded languages: those
 * have their own facts, and the host lists them under `embeds`. Keywords named soft by some
 * language (`maa.language.softKeywords`) stay usable as names and are listed apart.
 * Everything is sorted so that builds are reproducible.
 */
import { GrammarAST, GrammarUtils, URI } from 'langium';
import { createLangiumGrammarServices } from 'langium/grammar';
import { NodeFileSystem } from 'langium/node';
import { readdirSync } from 'node:fs';
import { basename, join } from 'node:path';

/**
 * @typedef {{ id: string, grammar: string, fileExtensions: string[], aliases?: string[], export?: string }} LanguageEntry
 * @typedef {{ rule: string, keyword: string, export?: string, id?: string, aliases?: string[] }} BehaviorEntry
 * @typedef {{ package: string, languages: LanguageEntry[], behavior?: BehaviorEntry, softKeywords: string[] }} ComposedPackage
 * @typedef {{ keyword: string, softKeyword: string, comment: string, string: string, number: string, operator: string }} Scopes
 * @typedef {{ id: string, kind: 'file' | 'behavior', package: string, aliases: string[], fileExtensions: string[],
 *             blockKeyword?: string, embeds: string[], keywords: string[], softKeywords: string[],
 *             scopeName: string, scopes: Scopes }} LanguageFact
 * @typedef {{ languages: LanguageFact[], softKeywords: string[] }} LanguageFacts
 */

/** Word keywords only: punctuation (`{`, `->`) is highlighted by the lexical rules of each client. */
const WORD = /^[A-Za-z_][A-Za-z0-9_]*$/;

/** @param {string} id @returns {Scopes} */
function scopesOf(id) {
    return {
        keyword: `keyword.control.${id}`,
        softKeyword: `keyword.other.${id}`,
        comment: `comment.${id}`,
        string: `string.quoted.double.${id}`,
        number: `constant.numeric.${id}`,
        operator: `keyword.operator.${id}`,
    };
}

/** @param {Iterable<string>} words */
const sorted = (words) => [...new Set(words)].sort();

/**
 * Reads the composed grammars of `buildDir` and computes the facts of the packages composed there.
 * @param {string} buildDir the folder holding the composed `.langium` files (names and slot grammars included)
 * @param {ComposedPackage[]} packages in composition order
 * @returns {Promise<LanguageFacts>}
 */
export async function computeLanguageFacts(buildDir, packages) {
    const services = createLangiumGrammarServices(NodeFileSystem).grammar;
    const documents = services.shared.workspace.LangiumDocuments;
    /** @type {Map<string, GrammarAST.Grammar>} */
    const grammars = new Map();
    // Load every composed grammar so that imports and rule calls link.
    const loaded = [];
    for (const file of readdirSync(buildDir).filter((f) => f.endsWith('.langium')).sort()) {
        const doc = await documents.getOrCreateDocument(URI.file(join(buildDir, file)));
        loaded.push(doc);
        grammars.set(file, /** @type {GrammarAST.Grammar} */ (doc.parseResult.value));
    }
    await services.shared.workspace.DocumentBuilder.build(loaded, { validation: false });

    /** @type {Map<string, GrammarAST.AbstractRule>} */
    const rules = new Map();
    for (const grammar of grammars.values()) for (const r of grammar.rules) rules.set(r.name, r);

    const softSet = new Set(packages.flatMap((p) => p.softKeywords));
    /** @type {Map<string, string>} behavior rule name -> behavior language id */
    const behaviorRules = new Map();
    for (const p of packages) if (p.behavior) behaviorRules.set(p.behavior.rule, p.behavior.id ?? p.behavior.keyword);

    /**
     * @param {GrammarAST.AbstractRule} start
     * @returns {{ words: Set<string>, embeds: Set<string> }}
     */
    const reach = (start) => {
        /** @type {Set<string>} */ const words = new Set();
        /** @type {Set<string>} */ const embeds = new Set();
        /** @type {Set<GrammarAST.AbstractRule>} */ const seen = new Set([start]);
        const queue = [start];
        while (queue.length > 0) {
            const rule = /** @type {GrammarAST.AbstractRule} */ (queue.shift());
            if (GrammarAST.isTerminalRule(rule)) continue;
            for (const node of streamAll(rule)) {
                if (GrammarAST.isKeyword(node) && WORD.test(node.value)) words.add(node.value);
                else if (GrammarAST.isRuleCall(node)) {
                    const target = node.rule.ref;
                    if (!target || seen.has(target)) continue;
                    seen.add(target);
                    if (target.name === 'Name' || isIdentifierRule(target)) continue;
                    const embedded = behaviorRules.get(target.name);
                    if (embedded !== undefined && target !== start) {
                        embeds.add(embedded);
                        continue;
                    }
                    queue.push(target);
                }
            }
        }
        return { words, embeds };
    };

    /** @param {string} name @param {string} where */
    const ruleNamed = (name, where) => {
        const rule = rules.get(name);
        if (!rule) throw new Error(`${where}: no rule ${name} in the composed grammar`);
        return rule;
    };

    /** @type {LanguageFact[]} */
    const facts = [];
    for (const p of packages) {
        for (const l of p.languages) {
            const grammar = grammars.get(basename(l.grammar));
            const entry = grammar?.rules.find((r) => GrammarAST.isParserRule(r) && r.entry);
            if (!entry) throw new Error(`${p.package}: ${l.grammar} has no entry rule`);
            facts.push(fact(l.id, 'file', p.package, l.aliases ?? [], l.fileExtensions, undefined, reach(entry), softSet));
        }
        if (p.behavior) {
            const id = p.behavior.id ?? p.behavior.keyword;
            const rule = ruleNamed(p.behavior.rule, p.package);
            facts.push(fact(id, 'behavior', p.package, p.behavior.aliases ?? [], [], p.behavior.keyword, reach(rule), softSet));
        }
    }
    facts.sort((a, b) => (a.id < b.id ? -1 : a.id > b.id ? 1 : 0));
    return { languages: facts, softKeywords: sorted(softSet) };
}

/**
 * @param {string} id @param {'file' | 'behavior'} kind @param {string} pkg @param {string[]} aliases
 * @param {string[]} fileExtensions @param {string | undefined} blockKeyword
 * @param {{ words: Set<string>, embeds: Set<string> }} reached @param {Set<string>} softSet
 * @returns {LanguageFact}
 */
function fact(id, kind, pkg, aliases, fileExtensions, blockKeyword, reached, softSet) {
    const words = [...reached.words];
    if (blockKeyword) words.push(blockKeyword);
    const scopeName = kind === 'file' ? `source.${id}` : `meta.embedded.block.${id}`;
    return {
        id,
        kind,
        package: pkg,
        aliases: [...new Set([...aliases, id])],
        fileExtensions: sorted(fileExtensions),
        ...(blockKeyword ? { blockKeyword } : {}),
        embeds: sorted(reached.embeds),
        keywords: sorted(words.filter((w) => !softSet.has(w))),
        softKeywords: sorted(words.filter((w) => softSet.has(w))),
        scopeName,
        scopes: scopesOf(id),
    };
}

/**
 * Identifier rules: `Name` (generated, admitting every soft keyword) and data-type rules with
 * `Name` or `ID` as one alternative (such as `NameSegment`, which admits keywords after a dot).
 * Keywords there are admitted as names, so they tell nothing about a language's own keywords.
 * @param {GrammarAST.AbstractRule} rule
 */
function isIdentifierRule(rule) {
    if (!GrammarAST.isParserRule(rule) || !GrammarUtils.isDataTypeRule(rule)) return false;
    const def = rule.definition;
    return GrammarAST.isAlternatives(def)
        && def.elements.some((e) => GrammarAST.isRuleCall(e) && (e.rule.ref?.name === 'Name' || e.rule.ref?.name === 'ID'));
}

/**
 * Every node below a rule (the rule's definition; Langium's AstUtils.streamAllContents without
 * importing the utilities namespace twice).
 * @param {import('langium').AstNode} root
 * @returns {Generator<import('langium').AstNode>}
 */
function* streamAll(root) {
    for (const [key, value] of Object.entries(root)) {
        if (key.startsWith('$')) continue;
        const items = Array.isArray(value) ? value : [value];
        for (const item of items) {
            if (item && typeof item === 'object' && typeof item.$type === 'string') {
                yield item;
                yield* streamAll(item);
            }
        }
    }
}

/**
 * The TypeScript module of the facts (a typed constant; the JSON file next to it holds the same).
 * @param {LanguageFacts} facts
 */
export function languageFactsModule(facts) {
    return [
        '// Generated by maa-compose-grammar from the composed grammar and the family list: the',
        '// language facts (ids, file extensions, keywords, scopes). Do not edit.',
        '',
        'export interface LanguageScopes {',
        '    readonly keyword: string;',
        '    readonly softKeyword: string;',
        '    readonly comment: string;',
        '    readonly string: string;',
        '    readonly number: string;',
        '    readonly operator: string;',
        '}',
        '',
        '/** One language of the family: a file language (own files) or a behavior language (a block in a host). */',
        'export interface LanguageFact {',
        '    readonly id: string;',
        "    readonly kind: 'file' | 'behavior';",
        '    /** The package that declares the language. */',
        '    readonly package: string;',
        '    /** Display names, the id last. */',
        '    readonly aliases: readonly string[];',
        '    /** With the leading dot; empty for behavior languages. */',
        '    readonly fileExtensions: readonly string[];',
        '    /** Behavior languages: the keyword opening the embedded block (`automaton { }`). */',
        '    readonly blockKeyword?: string;',
        '    /** Ids of the behavior languages whose blocks this language\'s files may hold. */',
        '    readonly embeds: readonly string[];',
        '    /** Reserved words: not usable as names. */',
        '    readonly keywords: readonly string[];',
        '    /** Keywords that stay usable as names (the family\'s soft keywords this language uses). */',
        '    readonly softKeywords: readonly string[];',
        '    /** TextMate-style scope of the language (`source.arc`) and of its token kinds. */',
        '    readonly scopeName: string;',
        '    readonly scopes: LanguageScopes;',
        '}',
        '',
        'export interface LanguageFacts {',
        '    readonly languages: readonly LanguageFact[];',
        '    /** Every soft keyword of the family (the alternatives of the generated `Name` rule). */',
        '    readonly softKeywords: readonly string[];',
        '}',
        '',
        `export const LANGUAGE_FACTS: LanguageFacts = ${JSON.stringify(facts, null, 4)};`,
        '',
    ].join('\n');
}
