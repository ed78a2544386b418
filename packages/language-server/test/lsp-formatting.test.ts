// The formatter in MontiArc style: two-space indentation, one element per line, single spaces
// around operators and arrows; blocks written on one line stay on one line, continued comma
// lists are aligned; formatting a formatted model changes nothing (the examples included).
import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import { applyEdits, lspServices, servicesOf, workspace } from './lsp-helpers.js';

const format = (): ReturnType<typeof expectFormatting> => expectFormatting(lspServices().Arc);

describe('formatting .arc', () => {
    test('a component: header, ports, fields, subcomponents, connectors, expressions', async () => {
        await format()({
            before: `package   toast ;
import toast.types.* ;
import toast.other.X;
/* The controller. */
component Messy<T extends Number>(int threshold=30,T b)   extends Base ( 1 ) {
port in int distance ,
     in T color,
         out int toaster,
  <<delayed>>   out int arm;
      int cycles=0,
        more = -  1;


   int z = ( 1+2 )*3 ;
  // a comment
  Sub s1 ( 1,2 ), s2;
  s1.o->s2.i , s2.j;
  compute {
  if(distance>threshold){ toaster = 1;} else { toaster=arm+cycles*2; }
  cycles ++;
  }
}
`,
            after: `package toast;

import toast.types.*;
import toast.other.X;

/* The controller. */
component Messy<T extends Number>(int threshold = 30, T b) extends Base(1) {
  port in int distance,
       in T color,
       out int toaster,
       <<delayed>> out int arm;
  int cycles = 0,
      more = -1;

  int z = (1 + 2) * 3;
  // a comment
  Sub s1(1, 2), s2;
  s1.o -> s2.i, s2.j;
  compute {
    if (distance > threshold) { toaster = 1; } else { toaster = arm + cycles * 2; }
    cycles++;
  }
}
`,
            disposeAfterCheck: true,
        });
    });

    test('an embedded automaton: states, hierarchy, initial actions, transitions; one-line actions stay one-line', async () => {
        await format()({
            before: `component A {
port in int i, out int o;
<<sync>>    automaton {
initial { o = 0;} state Idle;
 state Busy{
 entry/{ o=1; }
   initial state Inner;
  Inner->Inner[i>0]/o = i;
 };
Idle->Busy[i<2]/{ o = 2; };
    Busy -> Idle [ i == 0 ] / {
    o = 3;
  o = 4; };
  }
}
`,
            after: `component A {
  port in int i, out int o;
  <<sync>> automaton {
    initial { o = 0; } state Idle;
    state Busy {
      entry / { o = 1; }
      initial state Inner;
      Inner -> Inner [i > 0] / o = i;
    };
    Idle -> Busy [i < 2] / { o = 2; };
    Busy -> Idle [i == 0] / {
      o = 3;
      o = 4;
    };
  }
}
`,
            disposeAfterCheck: true,
        });
    });

    test("the client's tab size does not change the two-space style; range formatting formats only the range", async () => {
        const ws = await workspace({ 'toast/R.arc': 'package toast;\n\ncomponent R {\nport in int a;\n    port in int b;\n}\n' });
        const doc = ws.doc('toast/R.arc');
        const formatter = servicesOf(doc).lsp.Formatter!;
        const all = await formatter.formatDocument(doc, {
            textDocument: { uri: doc.uri.toString() },
            options: { tabSize: 8, insertSpaces: false },
        });
        expect(applyEdits(doc, all)).toBe('package toast;\n\ncomponent R {\n  port in int a;\n  port in int b;\n}\n');
        const range = await formatter.formatDocumentRange(doc, {
            textDocument: { uri: doc.uri.toString() },
            options: { tabSize: 2, insertSpaces: true },
            range: { start: { line: 4, character: 0 }, end: { line: 4, character: 18 } },
        });
        expect(applyEdits(doc, range)).toBe('package toast;\n\ncomponent R {\nport in int a;\n  port in int b;\n}\n');
    });

    test('a document with syntax errors is left alone', async () => {
        await format()({
            before: 'component A {\nport in int ;\n}\n',
            after: 'component A {\nport in int ;\n}\n',
            disposeAfterCheck: true,
        });
    });
});

describe('formatting .cd', () => {
    test('class diagrams: one type per line, members indented, enum constants on one line', async () => {
        await expectFormatting(lspServices().Cd)({
            before: 'package toast.types;\nclassdiagram Types{\nenum ToastColor{WHITE,GOLDEN , BURNT;}\n    class Pair<A,B> extends Base{ A first; B  second;\ndouble[] values;\n}\n}\n',
            after: 'package toast.types;\n\nclassdiagram Types {\n  enum ToastColor { WHITE, GOLDEN, BURNT; }\n  class Pair<A, B> extends Base {\n    A first;\n    B second;\n    double[] values;\n  }\n}\n',
            disposeAfterCheck: true,
        });
    });
});

describe('formatting is idempotent on the examples', () => {
    const here = dirname(fileURLToPath(import.meta.url));
    const examples = resolve(here, '../../../examples');
    const files: string[] = [];
    const walk = (dir: string): void => {
        for (const name of readdirSync(dir)) {
            const p = join(dir, name);
            if (statSync(p).isDirectory()) walk(p);
            // Blocks of behavior languages that register no formatting rules are left as written.
            else if (/\.(arc|cd)$/.test(name)) files.push(p);
        }
    };
    walk(examples);

    test.each(files.map((f) => [relative(examples, f), f]))('%s', async (_name, file) => {
        const text = readFileSync(file, 'utf8');
        const ws = await workspace({ [relative(examples, file)]: text });
        const doc = ws.doc(relative(examples, file));
        const edits = await servicesOf(doc).lsp.Formatter!.formatDocument(doc, {
            textDocument: { uri: doc.uri.toString() },
            options: { tabSize: 2, insertSpaces: true },
        });
        expect(applyEdits(doc, edits)).toBe(text);
    });
});
