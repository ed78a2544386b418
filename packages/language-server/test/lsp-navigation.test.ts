// Go to definition, find references, hover, document symbols, folding, semantic tokens and
// highlights: in the host language and inside embedded automata, across files of a model root.
import { describe, expect, test } from 'vitest';
import { expectFindReferences, expectGoToDefinition, expectHover, expectSymbols, expectSemanticToken, highlightHelper } from 'langium/test';
import { SemanticTokenTypes, type DocumentSymbol, type Hover, type Location } from 'vscode-languageserver-types';
import { lspServices, servicesOf, textAt, TYPES_CD, workspace, type Workspace } from './lsp-helpers.js';

const CONTROLLER = `package toast;

import toast.types.*;

/* Decides when to toast. */
component Controller(int threshold = 30) {
  port in int distance,   // cm to the next object
       in ToastColor color,
       <<delayed>> out ToasterCmd toaster;
  int cycles = 0;

  <<timed>> automaton {
    initial { toaster = ToasterCmd.STOP; } state Idle;
    state Toasting {
      entry / { cycles++; }
    };
    Idle -> Toasting [distance < threshold] distance / { toaster = ToasterCmd.START; };
    Toasting -> Idle [color == ToastColor.GOLDEN] color / { toaster = ToasterCmd.STOP; };
  }
}
`;

const ROBOT = `package toast;

component Robot {
  port in int d;
  Controller ctrl(25);
  toast.Controller other;
  d -> ctrl.distance, other.distance;
}
`;

const FILES = { 'toast/types/Types.cd': TYPES_CD, 'toast/Controller.arc': CONTROLLER, 'toast/Robot.arc': ROBOT };

/** The offset of the n-th occurrence (0-based) of a text in a document. */
function offsetOf(ws: Workspace, path: string, text: string, n = 0): number {
    const all = ws.doc(path).textDocument.getText();
    let at = -1;
    for (let i = 0; i <= n; i++) {
        at = all.indexOf(text, at + 1);
        if (at < 0) throw new Error(`'${text}' #${n} not in ${path}`);
    }
    return at;
}

async function definitionAt(ws: Workspace, path: string, text: string, n = 0): Promise<{ path: string; text: string }[]> {
    const doc = ws.doc(path);
    const position = doc.textDocument.positionAt(offsetOf(ws, path, text, n) + 1);
    const links =
        (await servicesOf(doc).lsp.DefinitionProvider!.getDefinition(doc, { textDocument: { uri: doc.uri.toString() }, position })) ?? [];
    return links.map((l) => {
        const target = [...ws.docs].find(([, d]) => d.uri.toString() === l.targetUri);
        return { path: target?.[0] ?? l.targetUri, text: target ? textAt(target[1], l.targetSelectionRange) : '' };
    });
}

async function referencesAt(ws: Workspace, path: string, text: string, n = 0): Promise<string[]> {
    const doc = ws.doc(path);
    const position = doc.textDocument.positionAt(offsetOf(ws, path, text, n) + 1);
    const locations: Location[] = await servicesOf(doc).lsp.ReferencesProvider!.findReferences(doc, {
        textDocument: { uri: doc.uri.toString() },
        position,
        context: { includeDeclaration: true },
    });
    return locations
        .map((l) => {
            const [p, d] = [...ws.docs].find(([, x]) => x.uri.toString() === l.uri)!;
            return `${p}:${l.range.start.line + 1}:${textAt(d, l.range)}`;
        })
        .sort();
}

async function hoverAt(ws: Workspace, path: string, text: string, n = 0): Promise<string> {
    const doc = ws.doc(path);
    const position = doc.textDocument.positionAt(offsetOf(ws, path, text, n) + 1);
    const hover: Hover | undefined = await servicesOf(doc).lsp.HoverProvider!.getHoverContent(doc, {
        textDocument: { uri: doc.uri.toString() },
        position,
    });
    return hover ? (hover.contents as { value: string }).value : '';
}

describe('go to definition', () => {
    test("from names inside an embedded automaton to the component's ports, fields, parameters and states", async () => {
        const ws = await workspace(FILES);
        const c = 'toast/Controller.arc';
        // A guard name and an event name land on the port declaration.
        expect(await definitionAt(ws, c, 'distance <')).toEqual([{ path: c, text: 'distance' }]);
        expect(await definitionAt(ws, c, 'distance /')).toEqual([{ path: c, text: 'distance' }]);
        expect(await definitionAt(ws, c, 'threshold]')).toEqual([{ path: c, text: 'threshold' }]);
        expect(await definitionAt(ws, c, 'cycles++')).toEqual([{ path: c, text: 'cycles' }]);
        expect(await definitionAt(ws, c, 'Toasting [')).toEqual([{ path: c, text: 'Toasting' }]);
        // The enum constant of a member access, in another file.
        expect(await definitionAt(ws, c, 'GOLDEN')).toEqual([{ path: 'toast/types/Types.cd', text: 'GOLDEN' }]);
        expect(await definitionAt(ws, c, 'ToastColor.GOLDEN')).toEqual([{ path: 'toast/types/Types.cd', text: 'ToastColor' }]);
    });

    test('across files: subcomponent types, qualified names and ports of subcomponents', async () => {
        const ws = await workspace(FILES);
        const r = 'toast/Robot.arc';
        expect(await definitionAt(ws, r, 'Controller ctrl')).toEqual([{ path: 'toast/Controller.arc', text: 'Controller' }]);
        expect(await definitionAt(ws, r, 'Controller other')).toEqual([{ path: 'toast/Controller.arc', text: 'Controller' }]);
        expect(await definitionAt(ws, r, 'distance,')).toEqual([{ path: 'toast/Controller.arc', text: 'distance' }]);
        expect(await definitionAt(ws, r, 'ctrl.')).toEqual([{ path: r, text: 'ctrl' }]);
    });

    test("Langium's expectGoToDefinition: an event in a single document", async () => {
        await expectGoToDefinition(lspServices().Arc)({
            text: 'component A {\n  port in int <|x|>;\n  automaton {\n    initial state S;\n    S -> S <|>x;\n  }\n}\n',
            index: 0,
            rangeIndex: 0,
            disposeAfterCheck: true,
        });
    });
});

describe('find references', () => {
    test('a port: its declaration, guards, events and actions of the automaton, connectors in other files', async () => {
        const ws = await workspace(FILES);
        expect(await referencesAt(ws, 'toast/Controller.arc', 'distance,')).toEqual([
            'toast/Controller.arc:17:distance',
            'toast/Controller.arc:17:distance',
            'toast/Controller.arc:7:distance',
            'toast/Robot.arc:7:distance',
            'toast/Robot.arc:7:distance',
        ]);
        expect(await referencesAt(ws, 'toast/Controller.arc', 'toaster;')).toEqual([
            'toast/Controller.arc:13:toaster',
            'toast/Controller.arc:17:toaster',
            'toast/Controller.arc:18:toaster',
            'toast/Controller.arc:9:toaster',
        ]);
    });

    test('an enum constant: its member accesses', async () => {
        const ws = await workspace(FILES);
        expect(await referencesAt(ws, 'toast/types/Types.cd', 'STOP')).toEqual([
            'toast/Controller.arc:13:STOP',
            'toast/Controller.arc:18:STOP',
            'toast/types/Types.cd:5:STOP',
        ]);
    });

    test("Langium's expectFindReferences: a state", async () => {
        await expectFindReferences(lspServices().Arc)({
            text: 'component A {\n  automaton {\n    initial state <|<|>S|>;\n    <|S|> -> <|S|>;\n  }\n}\n',
            includeDeclaration: true,
            disposeAfterCheck: true,
        });
    });
});

describe('hover', () => {
    test('a port: direction, type, timing and its comment', async () => {
        const ws = await workspace(FILES);
        const text = await hoverAt(ws, 'toast/Controller.arc', 'distance <');
        expect(text).toContain('port in int distance');
        expect(text).toContain('Incoming port of component `Controller`: type `int`, timing `timed` (from the behavior)');
        expect(text).toContain('cm to the next object');
        const toaster = await hoverAt(ws, 'toast/Controller.arc', 'toaster = ToasterCmd.START');
        expect(toaster).toContain('<<delayed>> port out ToasterCmd toaster');
        expect(toaster).toContain('delayed by one time slice');
    });

    test('a component: parameters, ports and its documentation; a subcomponent: its type', async () => {
        const ws = await workspace(FILES);
        const text = await hoverAt(ws, 'toast/Robot.arc', 'Controller ctrl');
        expect(text).toContain('component Controller(int threshold = 30)');
        expect(text).toContain('- `int threshold = 30`');
        expect(text).toContain('- `in int distance` — timed (from the behavior)');
        expect(text).toContain('Decides when to toast.');
        const sub = await hoverAt(ws, 'toast/Robot.arc', 'ctrl.');
        expect(sub).toContain('Controller ctrl(25)');
        expect(sub).toContain('an instance of `toast.Controller`');
    });

    test('a state and an enum constant', async () => {
        const ws = await workspace(FILES);
        const state = await hoverAt(ws, 'toast/Controller.arc', 'Idle ->');
        expect(state).toContain('initial state Idle');
        expect(state).toContain('Initial state of the timed automaton of `Controller`');
        expect(state).toContain('- `-> Toasting [distance < threshold] distance`');
        expect(await hoverAt(ws, 'toast/Controller.arc', 'GOLDEN')).toContain('ToastColor.GOLDEN');
    });

    test("Langium's expectHover on a field", async () => {
        await expectHover(lspServices().Arc)({
            text: 'component A {\n  // how often\n  int cycles = 0;\n  compute { <|>cycles++; }\n}\n',
            index: 0,
            hover: /int cycles = 0[\s\S]*Field of component `A`[\s\S]*how often/,
            disposeAfterCheck: true,
        });
    });
});

describe('document symbols, folding, highlighting', () => {
    test('the outline: component, parameters, ports, fields, automaton, states and transitions', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Controller.arc');
        const symbols = await servicesOf(doc).lsp.DocumentSymbolProvider!.getSymbols(doc, { textDocument: { uri: doc.uri.toString() } });
        const print = (s: DocumentSymbol, depth = 0): string[] => [
            `${'  '.repeat(depth)}${s.name}${s.detail ? ` : ${s.detail}` : ''}`,
            ...(s.children ?? []).flatMap((c) => print(c, depth + 1)),
        ];
        expect(symbols.flatMap((s) => print(s))).toEqual([
            'Controller : (int threshold = 30)',
            '  threshold : int',
            '  distance : in int',
            '  color : in ToastColor',
            '  toaster : out ToasterCmd (delayed)',
            '  cycles : int',
            '  automaton : timed',
            '    Idle : initial',
            '    Toasting',
            '    Idle -> Toasting : [distance < threshold] distance',
            '    Toasting -> Idle : [color == ToastColor.GOLDEN] color',
        ]);
    });

    test("Langium's expectSymbols on a class diagram: types with their constants and attributes", async () => {
        const flat = (sym: DocumentSymbol): string[] => [sym.name, ...(sym.children ?? []).flatMap(flat)];
        await expectSymbols(lspServices().Cd)({
            text: TYPES_CD,
            assert: (symbols) =>
                expect(symbols.flatMap(flat)).toEqual([
                    'Types',
                    'ToastColor',
                    'WHITE',
                    'GOLDEN',
                    'BURNT',
                    'ToasterCmd',
                    'START',
                    'STOP',
                    'JointTarget',
                    'speed',
                ]),
            disposeAfterCheck: true,
        });
    });

    test('folding: component body, automaton, hierarchical state, imports and comment runs', async () => {
        const ws = await workspace({
            ...FILES,
            'toast/F.arc':
                'package toast;\n\nimport toast.types.*;\nimport toast.types.Types.*;\n\n// one\n// two\n// three\ncomponent F {\n  port in int a;\n  automaton {\n    initial state S {\n      initial state T;\n    };\n  }\n}\n',
        });
        const doc = ws.doc('toast/F.arc');
        const ranges = await servicesOf(doc).lsp.FoldingRangeProvider!.getFoldingRanges(doc, { textDocument: { uri: doc.uri.toString() } });
        expect(ranges.map((r) => `${r.startLine}-${r.endLine}${r.kind ? ` ${r.kind}` : ''}`)).toEqual([
            '2-3 imports',
            '5-7 comment',
            '8-14',
            '10-13',
            '11-12',
        ]);
    });

    test('semantic tokens distinguish ports, fields, parameters, components, types, states and enum constants', async () => {
        const ws = await workspace({ 'toast/types/Types.cd': TYPES_CD });
        const highlight = highlightHelper(lspServices().Arc);
        const tokens = await highlight(
            'package toast;\nimport toast.types.*;\ncomponent <|Hl|>(int <|limit|>) {\n  port in <|ToastColor|> <|c|>, out int <|o|>;\n  int <|n|> = 0;\n  <|Hl|> <|inner|>;\n' +
                '  automaton {\n    initial state <|S|>;\n    <|S|> -> S [<|c|> == ToastColor.<|GOLDEN|> && <|n|> < <|limit|>] / { <|o|> = 1; };\n  }\n}\n',
            { documentUri: `${ws.root.toString()}/toast/Hl.arc` },
        );
        const expected: Array<[number, string]> = [
            [0, SemanticTokenTypes.class],
            [1, SemanticTokenTypes.parameter],
            [2, SemanticTokenTypes.enum],
            [3, SemanticTokenTypes.property],
            [4, SemanticTokenTypes.property],
            [5, SemanticTokenTypes.variable],
            [6, SemanticTokenTypes.class],
            [7, SemanticTokenTypes.variable],
            [8, SemanticTokenTypes.namespace],
            [9, SemanticTokenTypes.namespace],
            [10, SemanticTokenTypes.property],
            [11, SemanticTokenTypes.enumMember],
            [12, SemanticTokenTypes.variable],
            [13, SemanticTokenTypes.parameter],
            [14, SemanticTokenTypes.property],
        ];
        for (const [rangeIndex, tokenType] of expected)
            expectSemanticToken(tokens, { rangeIndex, tokenType: tokenType as SemanticTokenTypes });
    });
});
