/**
 * TextMate grammars of the family, generated from the language facts the grammar composer writes
 * (ids, keywords, soft keywords, scopes): one grammar per file language, with the blocks of the
 * behavior languages it embeds (`automaton { … }`, `robotarm { … }`) highlighted by the embedded
 * language's own keywords. Nothing here is written per language by hand. The language server's
 * semantic tokens refine the colours in the editor.
 */
import type { LanguageFact, LanguageFacts } from '@maa/language-server/language-facts';

/** The subset of the TextMate grammar format the generated grammars use (VS Code's tmLanguage JSON). */
export interface TmRule {
    name?: string;
    match?: string;
    begin?: string;
    end?: string;
    beginCaptures?: Record<string, { name: string }>;
    endCaptures?: Record<string, { name: string }>;
    patterns?: TmRule[];
    include?: string;
}

export interface TmGrammar {
    scopeName: string;
    name: string;
    fileTypes: string[];
    patterns: TmRule[];
    repository: Record<string, TmRule>;
}

/** Escapes a word for an Oniguruma regular expression. */
function escapeRegExp(word: string): string {
    return word.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}

/** Matches any of `words` as a whole word (longest first, so `int` never cuts `interface`). */
export function wordsPattern(words: readonly string[]): string {
    const sorted = [...new Set(words)].sort((a, b) => b.length - a.length || a.localeCompare(b));
    return `(?<![\\w$])(?:${sorted.map(escapeRegExp).join('|')})(?![\\w$])`;
}

/** The lexical rules every language of the family shares (Java-like comments, strings, numbers). */
function lexicalRules(fact: LanguageFact): TmRule[] {
    const s = fact.scopes;
    return [
        { name: s.comment, begin: '/\\*', end: '\\*/' },
        { name: s.comment, match: '//.*$' },
        { name: s.string, begin: '"', end: '"', patterns: [{ name: `constant.character.escape.${fact.id}`, match: '\\\\.' }] },
        { name: s.number, match: '(?<![\\w$])\\d+(?:\\.\\d+)?(?:[eE][+-]?\\d+)?[lLfFdD]?(?![\\w$])' },
    ];
}

/** Keywords, soft keywords and operators of one language. */
function wordRules(fact: LanguageFact): TmRule[] {
    const rules: TmRule[] = [];
    if (fact.keywords.length > 0) rules.push({ name: fact.scopes.keyword, match: wordsPattern(fact.keywords) });
    const soft = fact.softKeywords.filter((w) => !fact.keywords.includes(w));
    if (soft.length > 0) rules.push({ name: fact.scopes.softKeyword, match: wordsPattern(soft) });
    rules.push({ name: fact.scopes.operator, match: '->|==|!=|<=|>=|&&|\\|\\||[-+*/%!<>=?:]' });
    return rules;
}

/** The repository key of a language's rules inside a grammar. */
function rulesKey(id: string): string {
    return `language-${id}`;
}

/**
 * The rules of one language: its embedded blocks first (a block keyword followed by `{` opens the
 * behavior language until the matching `}`), then comments, strings, words. Nested braces inside
 * a block are a recursive rule so that the block ends at its own closing brace.
 */
function languageRules(fact: LanguageFact, byId: ReadonlyMap<string, LanguageFact>): TmRule {
    const blocks: TmRule[] = [];
    for (const id of fact.embeds) {
        const embedded = byId.get(id);
        if (!embedded?.blockKeyword) continue;
        blocks.push({ include: `#block-${id}` });
    }
    return { patterns: [...blocks, ...lexicalRules(fact), ...wordRules(fact), { include: `#braces-${fact.id}` }] };
}

/** The block rule of a behavior language: `automaton {` … `}` with the language's rules inside. */
function blockRule(fact: LanguageFact): TmRule {
    return {
        name: fact.scopeName,
        begin: `(?<![\\w$])(${escapeRegExp(fact.blockKeyword ?? fact.id)})\\s*(\\{)`,
        beginCaptures: { '1': { name: fact.scopes.keyword }, '2': { name: `punctuation.section.block.begin.${fact.id}` } },
        end: '\\}',
        endCaptures: { '0': { name: `punctuation.section.block.end.${fact.id}` } },
        patterns: [{ include: `#${rulesKey(fact.id)}` }],
    };
}

/** The languages a file language reaches through its embedded blocks (transitively), itself first. */
function reachable(fact: LanguageFact, byId: ReadonlyMap<string, LanguageFact>): LanguageFact[] {
    const seen = new Map<string, LanguageFact>();
    const visit = (f: LanguageFact): void => {
        if (seen.has(f.id)) return;
        seen.set(f.id, f);
        for (const id of f.embeds) {
            const e = byId.get(id);
            if (e) visit(e);
        }
    };
    visit(fact);
    return [...seen.values()];
}

/** The TextMate grammar of one file language of the family. */
export function textMateGrammar(fact: LanguageFact, facts: LanguageFacts): TmGrammar {
    const byId = new Map(facts.languages.map((l) => [l.id, l] as const));
    const repository: Record<string, TmRule> = {};
    for (const lang of reachable(fact, byId)) {
        repository[rulesKey(lang.id)] = languageRules(lang, byId);
        repository[`braces-${lang.id}`] = { begin: '\\{', end: '\\}', patterns: [{ include: `#${rulesKey(lang.id)}` }] };
        if (lang !== fact) repository[`block-${lang.id}`] = blockRule(lang);
    }
    return {
        scopeName: fact.scopeName,
        name: fact.aliases[0] ?? fact.id,
        fileTypes: fact.fileExtensions.map((e) => e.replace(/^\./, '')),
        patterns: [{ include: `#${rulesKey(fact.id)}` }],
        repository,
    };
}

/** The file languages of the family (the ones VS Code gets as languages; behavior languages live in blocks). */
export function fileLanguages(facts: LanguageFacts): LanguageFact[] {
    return facts.languages.filter((l) => l.kind === 'file');
}
