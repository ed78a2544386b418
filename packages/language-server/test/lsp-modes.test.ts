// Editor support of mode automata in the composed family: formatting in MontiArc's style, hover
// on a mode, modes as tokens of their own (declarations and references in transitions), the
// outline, completion and rename of modes, folding of a mode, and the C&C diagram.
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import type { SModelElement } from 'sprotty-protocol';
import type { DocumentSymbol } from 'vscode-languageserver-types';
import { byId, diagramWorkspace, TestClient } from './diagram-helpers.js';
import { lspServices, semanticTokensOf, servicesOf, workspace } from './lsp-helpers.js';

const format = (): ReturnType<typeof expectFormatting> => expectFormatting(lspServices().Arc);

const PASS = 'component Pass {\n  port in int i;\n  port out int o;\n  <<sync>> compute {\n    o = i;\n  }\n}\n';
const SWITCH = `component Switch {
  port in int i;
  port out int o;
  <<sync>> mode automaton {
    initial mode Up {
      Pass p;
      i -> p.i;
      p.o -> o;
    }
    mode Down {
      Pass q;
      i -> q.i;
      q.o -> o;
    }
    Up -> Down [i < 0];
    Down -> Up [i > 0];
  }
}
`;

describe('formatting', () => {
    test('mode automaton, modes, mode transitions and final states', async () => {
        await format()({
            before: `component F {
  port in int i, out int o;
  <<sync>>   mode   automaton{
  initial   mode A{ Pass p; i->p.i ; p.o->o; }
  mode B {Pass q;i -> q.i;q.o -> o;}
  A->B[ i<0 ] ;
  B  ->  A;
  }
  automaton {
  initial state S;
  final   state T;
  }
}
`,
            after: `component F {
  port in int i, out int o;
  <<sync>> mode automaton {
    initial mode A {
      Pass p;
      i -> p.i;
      p.o -> o;
    }
    mode B {
      Pass q;
      i -> q.i;
      q.o -> o;
    }
    A -> B [i < 0];
    B -> A;
  }
  automaton {
    initial state S;
    final state T;
  }
}
`,
        });
    });
});

describe('navigation', () => {
    test('hover on a mode names its role, subcomponents and transitions', async () => {
        const ws = await workspace({ 'Pass.arc': PASS, 'Switch.arc': SWITCH.replace('    Up -> Down', '    U<|>p -> Down') });
        const doc = ws.doc('Switch.arc');
        const hover = await servicesOf(doc).lsp.HoverProvider!.getHoverContent(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('Switch.arc'),
        });
        const value = (hover?.contents as { value: string } | undefined)?.value ?? '';
        expect(value).toContain('initial mode Up');
        expect(value).toContain('Initial mode of the sync mode automaton of `Switch`');
        expect(value).toContain('**Subcomponents**: `p`');
        expect(value).toContain('- `-> Down [i < 0]`');
    });

    test('the outline lists the mode automaton, its modes with their subcomponents, and the transitions', async () => {
        const ws = await workspace({ 'Pass.arc': PASS, 'Switch.arc': SWITCH });
        const doc = ws.doc('Switch.arc');
        const symbols = (await servicesOf(doc).lsp.DocumentSymbolProvider!.getSymbols(doc, {
            textDocument: { uri: doc.uri.toString() },
        })) as DocumentSymbol[];
        const flat = (list: DocumentSymbol[], depth = 0): string[] =>
            list.flatMap((s) => [
                `${'  '.repeat(depth)}${s.name}${s.detail ? ` (${s.detail})` : ''}`,
                ...flat(s.children ?? [], depth + 1),
            ]);
        const outline = flat(symbols).join('\n');
        expect(outline).toContain('mode automaton (sync)');
        expect(outline).toMatch(/Up \(initial\)\n\s+p/);
        expect(outline).toContain('Up -> Down ([i < 0])');
    });

    test('modes are tokens of their own; a mode folds', async () => {
        const ws = await workspace({ 'Pass.arc': PASS, 'Switch.arc': SWITCH });
        const f = ws.doc('Switch.arc');
        const found = (await semanticTokensOf(f)).map((t) => `${t.line}:${t.text}:${t.type}`);
        expect(found).toContain('4:Up:namespace');
        expect(found).toContain('14:Up:namespace');
        expect(found).toContain('14:Down:namespace');
        const ranges = await servicesOf(f).lsp.FoldingRangeProvider!.getFoldingRanges(f, { textDocument: { uri: f.uri.toString() } });
        expect(ranges.map((r) => `${r.startLine}-${r.endLine}`)).toContain('4-7');
    });

    test('completion offers the modes at a transition target; renaming a mode renames its transitions', async () => {
        const ws = await workspace({ 'Pass.arc': PASS, 'Switch.arc': SWITCH.replace('    Down -> Up [i > 0];', '    Down -> <|>') });
        const doc = ws.doc('Switch.arc');
        const items = await servicesOf(doc).lsp.CompletionProvider!.getCompletion(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('Switch.arc'),
        });
        expect(items?.items.map((x) => x.label)).toEqual(expect.arrayContaining(['Up', 'Down']));

        const ws2 = await workspace({ 'Pass.arc': PASS, 'Switch.arc': SWITCH.replace('initial mode Up', 'initial mode U<|>p') });
        const doc2 = ws2.doc('Switch.arc');
        const edit = await servicesOf(doc2).lsp.RenameProvider!.rename(doc2, {
            textDocument: { uri: doc2.uri.toString() },
            position: ws2.position('Switch.arc'),
            newName: 'Forward',
        });
        const edits = Object.values(edit?.changes ?? {}).flat();
        expect(edits.length).toBe(3);
        expect(edits.every((e) => e.newText === 'Forward')).toBe(true);
    });
});

describe('diagram', () => {
    test('the C&C diagram shows the subcomponents and connectors of every mode, marked with their mode', async () => {
        const ws = await diagramWorkspace({ 'Pass.arc': PASS, 'Switch.arc': SWITCH });
        const client = new TestClient(ws.diagrams);
        const model = await client.requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri('Switch.arc'), needsClientLayout: false });
        const elements = [...byId(model).values()] as Array<
            SModelElement & { name?: string; mode?: string; composed?: boolean; sourceId?: string; targetId?: string }
        >;
        const root = elements.find((e) => e.type === 'node:component' && e.name === 'Switch');
        expect(root?.composed).toBe(true);
        const subs = elements.filter((e) => e.type === 'node:component' && e.name !== 'Switch').map((e) => `${e.name}@${e.mode}`);
        expect(subs.sort()).toEqual(['p@Up', 'q@Down']);
        const edges = elements.filter((e) => e.type === 'edge:connector').map((e) => `${e.mode}: ${e.sourceId} -> ${e.targetId}`);
        expect(edges).toHaveLength(4);
        expect(edges.filter((e) => e.startsWith('Up:'))).toHaveLength(2);
        expect(new Set(elements.map((e) => e.id)).size).toBe(elements.length);
    });
});
