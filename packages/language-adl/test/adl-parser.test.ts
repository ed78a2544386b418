import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import {
    AstUtils,
    CompositeCstNodeImpl,
    EmptyFileSystem,
    GrammarAST,
    createLangiumParser,
    isAstNode,
    type AstNode,
    type CstNode,
    type LangiumCoreServices,
    type LangiumParser,
} from 'langium';
import { describe, expect, test } from 'vitest';
import { createAdlServices } from '../src/index.js';
import { AdlParser } from '../src/parser/adl-parser.js';
import { cocosCaseFiles, cocosSuiteFile, loadCocosCases } from '../src/testing/index.js';

// AdlParser (src/parser/adl-parser.ts) builds the CST and AST with cheaper code than Langium's
// parser; these tests parse the same texts with both and demand identical ASTs and errors, and the
// same CST up to one documented difference: a composite node whose only child is the composite
// node of a rule call without assignment and without an AST node of its own takes over that
// child's content (the pass-through levels of the expression grammar, `dissolvePassThrough`).

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');

/** The `.arc` and `.cd` files below a folder (none when it is absent). */
function modelFiles(root: string): string[] {
    const found: string[] = [];
    const walk = (dir: string): void => {
        for (const name of readdirSync(dir)) {
            const p = path.join(dir, name);
            if (statSync(p).isDirectory()) {
                if (name !== 'node_modules' && !name.startsWith('.')) walk(p);
            } else if (/\.(arc|cd)$/.test(name)) found.push(p);
        }
    };
    if (existsSync(root)) walk(root);
    return found.sort();
}

/** The `.arc` and `.cd` files of the repository's examples. */
const exampleFiles = (): string[] => modelFiles(path.join(repo, 'examples'));

/**
 * MontiArc's conformance models (the workplace's shared/conformance beside the clone, read at test
 * time, absent in a user's clone): the files of every context-condition case and the I/O models.
 */
function conformanceTexts(): Array<[string, string]> {
    // The cases share most helper files: each distinct text once.
    const texts = new Map<string, string>();
    for (const suite of ['cocos.json', 'cocos-extended.json'] as const) {
        for (const c of loadCocosCases(cocosSuiteFile(repo, suite)) ?? []) {
            for (const [file, text] of Object.entries(cocosCaseFiles(c))) {
                if (!texts.has(text)) texts.set(text, `${suite} ${c.cls} ${file}`);
            }
        }
    }
    const shared = path.join(repo, '..', 'shared', 'conformance');
    for (const file of modelFiles(shared)) texts.set(readFileSync(file, 'utf8'), path.relative(shared, file));
    return [...texts].map(([text, name]): [string, string] => [name, text]);
}

const inline: Record<string, string> = {
    'comments.arc': `/* leading */ package a.b; // after
import a.b.Types.*;
/** doc */ component C(int k = 3) {
  port in int x, /* between */ y, out int z;
  int state = 0; // soft keyword as a name
  compute {
    z = (x << 2) + y * k - ~x >> 1 >>> 2;
    state += x > y ? x : y; // a comment
    if (x >= 0 && !(y < 0) || x != y) { z = -x; } else z++;
    for (int i = 0; i < 3; i++) { z = z + i; }
    switch (x) { case 1, 2 -> z = 1; default -> z = 0; }
  }
}
`,
    'errors.arc': `package a;
component D {
  port in int x
  port out int ;
  compute { x = ; y = (1 + ; }
`,
    'truncated.arc': 'component E { port in int x; compute { x = 1 +',
    'empty.arc': '',
    'only-comment.arc': '// nothing here\n',
    'types.cd': `package t;
classdiagram T {
  enum Mode { A, B; }
  class P<X> extends Object { X first; int[] all; }
  association [1] P -> (parts) P [*];
}
`,
};

/**
 * Langium's CST with the pass-through nodes dissolved as AdlParser does (bottom-up: a chain of
 * them becomes its outermost node). Written apart from the parser's code, from the rule.
 */
function dissolvePassThrough(node: CstNode): void {
    const content = (node as { content?: CstNode[] }).content;
    if (!content) return;
    for (const child of content) dissolvePassThrough(child);
    const only = content.length === 1 ? content[0] : undefined;
    if (
        only instanceof CompositeCstNodeImpl &&
        (only as unknown as { _astNode?: unknown })._astNode === undefined &&
        GrammarAST.isRuleCall(only.grammarSource) &&
        !AstUtils.getContainerOfType(only.grammarSource, GrammarAST.isAssignment)
    ) {
        content.splice(0, 1, ...only.content);
    }
}

/** One line per CST node, in document order: what it is, where, and what it belongs to. */
function cstLines(root: CstNode): string[] {
    const ids = new Map<unknown, number>();
    const id = (o: unknown): number | string => {
        if (o === undefined) return '-';
        if (!ids.has(o)) ids.set(o, ids.size);
        return ids.get(o)!;
    };
    const lines: string[] = [];
    const visit = (node: CstNode, depth: number): void => {
        const content = (node as { content?: CstNode[] }).content;
        const ast = (node as { _astNode?: AstNode })._astNode;
        lines.push(
            [
                depth,
                content ? 'composite' : 'leaf',
                node.offset,
                node.length,
                node.hidden,
                id(node.grammarSource),
                id(node.container),
                ast?.$type ?? '',
                JSON.stringify(node.range),
            ].join(' '),
        );
        for (const child of content ?? []) visit(child, depth + 1);
    };
    visit(root, 0);
    return lines;
}

/** One line per AST node and property, in document order, with its container and CST range. */
function astLines(root: AstNode): string[] {
    const lines: string[] = [];
    const visit = (node: AstNode): void => {
        lines.push(
            `${node.$type} in ${node.$container?.$type}.${node.$containerProperty}[${node.$containerIndex}] at ${node.$cstNode?.offset}+${node.$cstNode?.length}`,
        );
        for (const key of Object.keys(node).sort()) {
            if (key.startsWith('$')) continue;
            const values = (node as unknown as Record<string, unknown>)[key];
            if (Array.isArray(values)) lines.push(`${key}: list of ${values.length}`);
            for (const value of Array.isArray(values) ? values : [values]) {
                if (isAstNode(value)) {
                    if (value.$container !== node) lines.push(`${key}: container mismatch`);
                    visit(value);
                } else if (typeof value === 'object' && value !== null && '$refText' in value) {
                    const ref = value as { $refText: string; $refNode?: CstNode };
                    lines.push(`${key} -> ${ref.$refText} at ${ref.$refNode?.offset}`);
                } else lines.push(`${key} = ${JSON.stringify(value)}${Array.isArray(values) ? ' (list)' : ''}`);
            }
        }
    };
    visit(root);
    return lines;
}

function parseWith(parser: LangiumParser, text: string, dissolve = false): { ast: string[]; cst: string[]; errors: string[] } {
    const result = parser.parse(text);
    if (dissolve) dissolvePassThrough(result.value.$cstNode!);
    return {
        ast: astLines(result.value),
        cst: cstLines(result.value.$cstNode!),
        errors: [
            ...result.lexerErrors.map((e) => `lexer ${e.offset}: ${e.message}`),
            ...result.parserErrors.map((e) => `parser ${e.token.startOffset}: ${e.message}`),
        ],
    };
}

describe('AdlParser builds the same trees as Langium', () => {
    const services = createAdlServices(EmptyFileSystem);
    // Langium's own parser for the same services (same grammar, lexer, linker and converter).
    const langiumParsers = new Map<LangiumCoreServices, LangiumParser>();
    const parsers = (s: LangiumCoreServices): [LangiumParser, LangiumParser] => {
        if (!langiumParsers.has(s)) langiumParsers.set(s, createLangiumParser(s));
        return [s.parser.LangiumParser, langiumParsers.get(s)!];
    };

    test('the family uses it', () => {
        expect(services.Arc.parser.LangiumParser).toBeInstanceOf(AdlParser);
        expect(services.Cd.parser.LangiumParser).toBeInstanceOf(AdlParser);
    });

    const cases: Array<[string, string]> = [
        ...Object.entries(inline),
        ...exampleFiles().map((f): [string, string] => [path.relative(repo, f), readFileSync(f, 'utf8')]),
    ];
    test.each(cases)('%s: whole, cut in half, without its first semicolon', async (name, text) => {
        const [ours, langiums] = parsers(name.endsWith('.cd') ? services.Cd : services.Arc);
        for (const variant of [text, text.slice(0, Math.floor(text.length / 2)), text.replace(';', '')]) {
            expect(parseWith(ours, variant)).toEqual(parseWith(langiums, variant, true));
        }
        await new Promise((r) => setImmediate(r));
    });

    const conformance = conformanceTexts();
    test.skipIf(conformance.length === 0)(`MontiArc's conformance models (${conformance.length} files)`, async () => {
        for (const [name, text] of conformance) {
            const [ours, langiums] = parsers(name.endsWith('.cd') ? services.Cd : services.Arc);
            expect(parseWith(ours, text), name).toEqual(parseWith(langiums, text, true));
            await new Promise((r) => setImmediate(r));
        }
    });

    test('an operand is one composite node, a nesting of sixteen in Langium', () => {
        const [ours, langiums] = parsers(services.Arc);
        const text = 'component A { port in int x; compute { x = 7; } }';
        const depthOfLiteral = (parser: LangiumParser): number => {
            const literal = AstUtils.streamAst(parser.parse(text).value).find((n) => n.$type === 'IntLiteral')!;
            let depth = 0;
            for (
                let node: CstNode = literal.$cstNode!;
                (node as { content?: CstNode[] }).content;
                node = (node as { content: CstNode[] }).content[0]!
            ) {
                depth++;
            }
            return depth;
        };
        expect(depthOfLiteral(ours)).toBe(1);
        expect(depthOfLiteral(langiums)).toBeGreaterThan(10);
    });

    test('the comparison sees a difference', () => {
        const [ours] = parsers(services.Arc);
        expect(parseWith(ours, 'component A { port in int x; }')).not.toEqual(parseWith(ours, 'component A { port  in int x; }'));
    });
});
