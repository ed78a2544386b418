// Editor support for switch, do-while, break/continue and autoconnect in the composed family:
// formatting in MontiArc style, folding of a multi-line switch, `autoconnect`'s kinds as
// keyword tokens (`type`/`off` stay names elsewhere), and the C&C diagram drawing the
// connectors autoconnect implies.
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import type { SModelElement } from 'sprotty-protocol';
import { byId, diagramWorkspace, TestClient } from './diagram-helpers.js';
import { lspServices, semanticTokensOf, servicesOf, workspace } from './lsp-helpers.js';

const format = (): ReturnType<typeof expectFormatting> => expectFormatting(lspServices().Arc);

describe('formatting', () => {
    test('switch groups and rules, do-while, break, continue, autoconnect', async () => {
        await format()({
            before: `component F {
  port in int i, out int o;
  compute {
    switch(i){
    case 1 :
    case 2,3:
    o=1 ;
    break ;
    default:
    o = 2;
    }
    switch ( i ) { case 1->o = 1; default  ->  { o = 2; } }
    do{ o++; continue ; }while( o<i ) ;
  }
}
`,
            after: `component F {
  port in int i, out int o;
  compute {
    switch (i) {
      case 1:
      case 2, 3:
        o = 1;
        break;
      default:
        o = 2;
    }
    switch (i) {
      case 1 -> o = 1;
      default -> { o = 2; }
    }
    do { o++; continue; } while (o < i);
  }
}
`,
        });
    });
});

describe('folding and semantic tokens', () => {
    test('a multi-line switch folds; autoconnect kinds are keywords, a port named type is a property', async () => {
        const ws = await workspace({
            'F.arc':
                'component F {\n  port in int type, out int o;\n  component Inner {\n    port in int type;\n    port out int o;\n  }\n  Inner inner;\n  autoconnect port;\n}\n',
            'G.arc':
                'component G {\n  port in int i, out int o;\n  compute {\n    switch (i) {\n      case 1:\n        o = 1;\n        break;\n      default:\n        o = 2;\n    }\n  }\n}\n',
        });
        const g = ws.doc('G.arc');
        const ranges = await servicesOf(g).lsp.FoldingRangeProvider!.getFoldingRanges(g, { textDocument: { uri: g.uri.toString() } });
        expect(ranges.map((r) => `${r.startLine}-${r.endLine}`)).toContain('3-8');

        const f = ws.doc('F.arc');
        const found = (await semanticTokensOf(f)).map((t) => `${t.line}:${t.text}:${t.type}`);
        expect(found).toContain('7:port:keyword');
        expect(found).toContain('1:type:property');
    });
});

describe('hover', () => {
    test('hovering autoconnect lists the connectors it implies', async () => {
        const ws = await workspace({
            'F.arc':
                'component F {\n  port in int i, out int o;\n  component Inner {\n    port in int i;\n    port out int o;\n  }\n  Inner inner;\n  auto<|>connect port;\n}\n',
        });
        const doc = ws.doc('F.arc');
        const hover = await servicesOf(doc).lsp.HoverProvider!.getHoverContent(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('F.arc'),
        });
        const value = (hover?.contents as { value: string } | undefined)?.value ?? '';
        expect(value).toContain('Implied connectors: `inner.o -> o`, `i -> inner.i`.');
    });
});

describe('diagram', () => {
    test('the connectors autoconnect implies are edges of the C&C diagram, none with autoconnect off', async () => {
        const text = (kind: string): string =>
            `component F {\n  port in int i, out int o;\n  component Inner {\n    port in int i;\n    port out int o;\n  }\n  Inner inner;\n  autoconnect ${kind};\n}\n`;
        const ws = await diagramWorkspace({ 'F.arc': text('port'), 'G.arc': text('off').replace('component F', 'component G') });
        const edges = async (file: string): Promise<string[]> => {
            const client = new TestClient(ws.diagrams);
            const model = await client.requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri(file), needsClientLayout: false });
            return (
                [...byId(model).values()].filter((e) => e.type === 'edge:connector') as Array<
                    SModelElement & { sourceId: string; targetId: string }
                >
            ).map((e) => `${e.sourceId} -> ${e.targetId}`);
        };
        const implied = await edges('F.arc');
        expect(implied).toHaveLength(2);
        expect(await edges('G.arc')).toEqual([]);
    });
});
