// Deeply nested models in every language of the family: at the nesting limit (the deepest model
// without syntax/too-deep) and far beyond it, every phase answers: linking, typing, validation,
// formatting, semantic tokens, hover, completion, outline, folding and both diagrams.
import { describe, expect, test } from 'vitest';
import type { LangiumDocument } from 'langium';
import { servicesOf, workspace, type Workspace } from './lsp-helpers.js';
import { diagramWorkspace, TestClient } from './diagram-helpers.js';

const arc = (body: string): string => `component A {\n  port in int i;\n  port out int o;\n${body}\n}\n`;
const states = (k: number): string => Array.from({ length: k }, (_, n) => `state S${n} {`).join(' ') + ' }'.repeat(k);

/** Models by nesting depth: `k` levels of one construct in file A.<ext>. */
/** `broken`: the nesting is a syntax error in that language anyway (error recovery at depth). */
const CONSTRUCTS: Record<string, { file: string; model: (k: number) => string; broken?: true }> = {
    'parentheses in a guard': {
        file: 'A.arc',
        model: (k) => arc(`  automaton {\n    initial state A;\n    A -> A [${'('.repeat(k)}i > 0${')'.repeat(k)}] / o = 1;\n  }`),
    },
    'parentheses in compute': { file: 'A.arc', model: (k) => arc(`  compute { o = ${'('.repeat(k)}i${')'.repeat(k)}; }`) },
    'unary minus signs': { file: 'A.arc', model: (k) => arc(`  compute { o = ${'- '.repeat(k)}i; }`) },
    'nested blocks': { file: 'A.arc', model: (k) => arc(`  compute { ${'{ '.repeat(k)}o = 1;${' }'.repeat(k)} }`) },
    'nested states': { file: 'A.arc', model: (k) => arc(`  automaton {\n    initial ${states(k)}\n  }`) },
    'nested ifs in an action': {
        file: 'A.arc',
        model: (k) => arc(`  automaton {\n    initial state A;\n    A -> A / { ${'if (i > 0) '.repeat(k)}o = 1; }\n  }`),
    },
    'nested switch expressions': {
        file: 'A.arc',
        model: (k) => arc(`  compute { o = ${'switch (i) { default -> '.repeat(k)}0${'; }'.repeat(k)}; }`),
    },
    'binary operators': { file: 'A.arc', model: (k) => arc(`  compute { o = i${' + i'.repeat(k)}; }`) },
    'robot arm move arguments': {
        file: 'A.arc',
        model: (k) => arc(`  robotarm {\n    location L 10deg 5cm;\n    program P { move${' L'.repeat(k)}; }\n  }`),
    },
    'braces in a class diagram': {
        file: 'T.cd',
        model: (k) => `classdiagram T {\n  class C { int x; ${'{ '.repeat(k)}${'} '.repeat(k)}}\n}\n`,
        broken: true,
    },
    'braces in a robot arm file': {
        file: 'R.ra',
        model: (k) => `robotarm R {\n  program P { ${'{ '.repeat(k)}${'} '.repeat(k)}move top; }\n}\n`,
        broken: true,
    },
    'braces in an application': {
        file: 'X.arcapp',
        model: (k) => `application X for A {\n  platform p { ${'{ '.repeat(k)}${'} '.repeat(k)}}\n}\n`,
        broken: true,
    },
};

function codes(doc: LangiumDocument): string[] {
    return (doc.diagnostics ?? []).map((d) => String(d.code));
}

async function tooDeep(file: string, text: string): Promise<boolean> {
    const ws = await workspace({ [file]: text });
    return codes(ws.doc(file)).includes('syntax/too-deep');
}

/** The largest depth without syntax/too-deep (binary search; 0 if even one level is too deep). */
async function largestAccepted(file: string, model: (k: number) => string): Promise<number> {
    let lo = 0;
    let hi = 1;
    while (!(await tooDeep(file, model(hi)))) {
        lo = hi;
        hi *= 2;
        if (hi > 20_000) return lo; // the construct is never cut (e.g. a flat list)
    }
    while (hi - lo > 1) {
        const mid = Math.floor((lo + hi) / 2);
        if (await tooDeep(file, model(mid))) hi = mid;
        else lo = mid;
    }
    return lo;
}

/** Runs every editor feature on the file; each must answer (not throw). */
async function serveEverything(ws: Workspace, file: string): Promise<void> {
    const doc = ws.doc(file);
    const lsp = servicesOf(doc).lsp;
    const textDocument = { uri: doc.uri.toString() };
    const text = doc.textDocument.getText();
    const positions = [0.25, 0.5, 0.75, 0.999].map((f) => doc.textDocument.positionAt(Math.floor(text.length * f)));
    expect(await lsp.Formatter!.formatDocument(doc, { textDocument, options: { tabSize: 2, insertSpaces: true } })).toBeDefined();
    expect((await lsp.SemanticTokenProvider!.semanticHighlight(doc, { textDocument })).data).toBeDefined();
    expect(await lsp.DocumentSymbolProvider!.getSymbols(doc, { textDocument })).toBeDefined();
    expect(await lsp.FoldingRangeProvider!.getFoldingRanges(doc, { textDocument })).toBeDefined();
    for (const position of positions) {
        await lsp.HoverProvider!.getHoverContent(doc, { textDocument, position });
        await lsp.CompletionProvider!.getCompletion(doc, { textDocument, position });
        await lsp.DefinitionProvider!.getDefinition(doc, { textDocument, position });
        await lsp.ReferencesProvider!.findReferences(doc, { textDocument, position, context: { includeDeclaration: true } });
    }
}

describe.each(Object.entries(CONSTRUCTS))('%s', (_name, c) => {
    test('at the nesting limit and far beyond it, every phase answers', async () => {
        const k = await largestAccepted(c.file, c.model);
        for (const depth of [k, k + 1, 10_000]) {
            const ws = await workspace({ [c.file]: c.model(depth), ...(c.file === 'X.arcapp' ? { 'A.arc': 'component A { }' } : {}) });
            const found = codes(ws.doc(c.file));
            expect(
                found.filter((code) => code.startsWith('internal/')),
                `depth ${depth}`,
            ).toEqual([]);
            expect(found.filter((code) => code === 'syntax/too-deep').length, `depth ${depth}`).toBeLessThanOrEqual(1);
            if (depth === k && !c.broken)
                expect(
                    found.filter((code) => code.startsWith('syntax/')),
                    `depth ${depth}`,
                ).toEqual([]);
            await serveEverything(ws, c.file);
        }
    });
});

describe('diagrams of deeply nested models', () => {
    test('the component diagram and the automaton diagram are built at and beyond the limit', async () => {
        const k = await largestAccepted('A.arc', CONSTRUCTS['nested states']!.model);
        expect(k).toBeGreaterThanOrEqual(30);
        for (const depth of [k, 10_000]) {
            const ws = await diagramWorkspace({ 'A.arc': CONSTRUCTS['nested states']!.model(depth) });
            const client = new TestClient(ws.diagrams);
            const cc = await client.requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri('A.arc'), needsClientLayout: false });
            expect(cc.children?.length ?? 0).toBeGreaterThan(0);
            const automaton = await client.requestModel({
                diagramType: 'maa-automaton',
                sourceUri: ws.uri('A.arc'),
                needsClientLayout: false,
            });
            expect(automaton.type).toBeDefined();
        }
    });
});
