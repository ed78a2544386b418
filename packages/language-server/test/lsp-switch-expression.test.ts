// Editor support for switch expressions: MontiArc-style formatting (one arm per line), `yield`
// as a keyword token in a yield statement and a variable token where it is a name, and
// diagnostics through the composed family.
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import { lspServices, semanticTokensOf, workspace } from './lsp-helpers.js';

const format = (): ReturnType<typeof expectFormatting> => expectFormatting(lspServices().Arc);

describe('switch expressions in the editor', () => {
    test('formatting: one arm per line, a space after ->, yield with one space', async () => {
        await format()({
            before: `component F {
  port in int i, out int o;
  compute {
    o = switch(i){case 1,2->10 ; case 3->{ int y = 4; yield   y*2 ; }
    default   ->  0;};
  }
}
`,
            after: `component F {
  port in int i, out int o;
  compute {
    o = switch (i) {
      case 1, 2 -> 10;
      case 3 -> { int y = 4; yield y * 2; }
      default -> 0;
    };
  }
}
`,
        });
    });

    test('semantic tokens: yield is a keyword in a yield statement and a variable where it names one; no diagnostics', async () => {
        const ws = await workspace({
            'F.arc':
                'component F {\n  port in int i, out int o;\n  compute {\n    int yield = 2;\n    o = switch (i) {\n      case 1 -> {\n        yield yield + 1;\n      }\n      default -> yield;\n    };\n  }\n}\n',
        });
        const doc = ws.doc('F.arc');
        expect(doc.diagnostics ?? []).toEqual([]);
        const found = (await semanticTokensOf(doc)).map((t) => `${t.line}:${t.text}:${t.type}`);
        expect(found).toContain('6:yield:keyword');
        expect(found).toContain('6:yield:variable');
        expect(found).toContain('8:yield:variable');
        expect(found.filter((t) => t.endsWith(':keyword') && t.includes('yield'))).toEqual(['6:yield:keyword']);
    });

    test('diagnostics of the composed family: a switch expression that is not exhaustive', async () => {
        const ws = await workspace({
            'F.arc': 'component F {\n  port in int i, out int o;\n  compute {\n    o = switch (i) { case 1 -> 10; };\n  }\n}\n',
        });
        const doc = ws.doc('F.arc');
        expect((doc.diagnostics ?? []).map((d) => d.code)).toEqual(['statement/switch-not-exhaustive']);
    });
});
