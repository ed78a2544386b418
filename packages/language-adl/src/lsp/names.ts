import { AstUtils, GrammarAST, GrammarUtils, type LangiumCoreServices } from 'langium';

/** Keywords that the grammar's `Name` rule admits as names (soft keywords such as `state`), per grammar. */
const softKeywords = new WeakMap<GrammarAST.Grammar, ReadonlySet<string>>();

function admittedKeywords(grammar: GrammarAST.Grammar): ReadonlySet<string> {
    let set = softKeywords.get(grammar);
    if (!set) {
        const rule = [...GrammarUtils.getAllReachableRules(grammar, false)].find((r) => r.name === 'Name');
        set = new Set(
            rule
                ? AstUtils.streamAllContents(rule)
                      .filter(GrammarAST.isKeyword)
                      .map((k) => k.value)
                : [],
        );
        softKeywords.set(grammar, set);
    }
    return set;
}

/**
 * Why a string cannot be a name in a language of the family, or undefined when it can. The
 * language's own lexer decides: a name is exactly one identifier token (a letter, `_` or `$`,
 * then letters, digits, `_` or `$`), or a keyword that the grammar admits as a name; any other
 * keyword of that language is refused.
 */
export function nameProblem(services: LangiumCoreServices, name: string): string | undefined {
    const language = services.LanguageMetaData.fileExtensions[0] ?? services.LanguageMetaData.languageId;
    if (name.length === 0) return 'a name cannot be empty';
    const lexed = services.parser.Lexer.tokenize(name);
    const token = lexed.tokens[0];
    const single = lexed.errors.length === 0 && lexed.hidden.length === 0 && lexed.tokens.length === 1 && token?.image === name;
    if (!single || !token) return "a name starts with a letter, '_' or '$' followed by letters, digits, '_' or '$'";
    if (token.tokenType.name === 'ID') return undefined;
    if (admittedKeywords(services.Grammar).has(name)) return undefined;
    return /^[_a-zA-Z$][\w$]*$/.test(name)
        ? `'${name}' is a keyword of ${language} files`
        : "a name starts with a letter, '_' or '$' followed by letters, digits, '_' or '$'";
}
