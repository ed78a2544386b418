// Editor support for class-diagram methods (in classes and enums) and the JDK library: completion
// of members after `Type.` and after a value (enum constant, class-diagram value, Map), hover on a
// called method, go-to-definition into the class diagram, formatting of an enum with methods.
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import type { Hover } from 'vscode-languageserver-types';
import { lspServices, workspace } from './lsp-helpers.js';

const SHAPES = `package t;
classdiagram Shapes {
  class Rect { double w; double area(); static Rect square(double side); }
  enum Color { RED, GREEN; int code(); static Color parse(String text); }
}
`;

function model(body: string): Record<string, string> {
    return {
        't/Shapes.cd': SHAPES,
        'Foo.arc': `import t.Shapes.*;\nimport java.util.*;\n\ncomponent Foo(Rect r) {\n  port in int x;\n${body}\n}\n`,
    };
}

async function labelsAt(files: Record<string, string>): Promise<string[]> {
    const ws = await workspace(files);
    const doc = ws.doc('Foo.arc');
    const list = await lspServices().Arc.lsp.CompletionProvider!.getCompletion(doc, {
        textDocument: { uri: doc.uri.toString() },
        position: ws.position('Foo.arc'),
    });
    return (list?.items ?? []).map((i) => i.label);
}

describe('completion of methods', () => {
    test('after an enum type: its constants and its static methods', async () => {
        const labels = await labelsAt(model('  Color k = Color.<|>;'));
        expect(labels).toEqual(expect.arrayContaining(['RED', 'GREEN', 'parse']));
    });
});

describe('hover and definition of a called method', () => {
    test('hover shows the declaration; definition jumps into the class diagram', async () => {
        const ws = await workspace(model('  int c = Color.RED.co<|>de();'));
        const doc = ws.doc('Foo.arc');
        const params = { textDocument: { uri: doc.uri.toString() }, position: ws.position('Foo.arc') };
        const hover = (await lspServices().Arc.lsp.HoverProvider!.getHoverContent(doc, params)) as Hover | undefined;
        expect(JSON.stringify(hover?.contents ?? '')).toContain('int code()');
        const links = await lspServices().Arc.lsp.DefinitionProvider!.getDefinition(doc, params);
        expect(links?.[0]?.targetUri).toContain('Shapes.cd');
    });
});

describe('formatting an enum with methods', () => {
    test('constants, then methods after the semicolon', async () => {
        await expectFormatting(lspServices().Cd)({
            before: 'package t;\nclassdiagram E {\n  enum Level {LOW ,HIGH ;int rank( ) ;  static Level parse(String s);}\n}\n',
            after: 'package t;\n\nclassdiagram E {\n  enum Level { LOW, HIGH; int rank(); static Level parse(String s); }\n}\n',
        });
    });
});

describe('completion of members after a value', () => {
    test("after an enum constant: the enum's methods", async () => {
        expect(await labelsAt(model('  int c = Color.RED.<|>;'))).toContain('code');
    });
    test('after a class-diagram value: its attributes and methods', async () => {
        expect(await labelsAt(model('  double a = r.<|>;'))).toEqual(expect.arrayContaining(['w', 'area']));
    });
    test("after a Map: the JDK library's methods", async () => {
        expect(await labelsAt(model('  Map<String, Integer> mp = HashMap.HashMap();\n  boolean b = mp.<|>;'))).toEqual(
            expect.arrayContaining(['containsKey', 'getOrDefault', 'keySet']),
        );
    });
});
