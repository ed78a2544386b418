// The RobotArm language in the language server, in both forms (the embedded `robotarm { }` block
// and standalone `.ra` files): completion after `move` (the block's locations and the component's
// incoming ports; a file's inputs and locations), go to definition, references and rename from
// `move angle` to the port (the Port2InputAdapter), outline, semantic tokens, formatting (the
// example's files unchanged), hover and the quick fixes of the robotarm/* codes.
import { readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import type { LangiumDocument } from 'langium';
import {
    SymbolKind,
    type CodeAction,
    type CompletionItem,
    type Diagnostic,
    type DocumentSymbol,
    type Hover,
    type Location,
} from 'vscode-languageserver-types';
import {
    applyEdits,
    applyWorkspaceEdit,
    lspServices,
    servicesOf,
    semanticTokensOf,
    textAt,
    workspace,
    type SemanticToken,
    type Workspace,
} from './lsp-helpers.js';

const TYPES = `package toast.types;

classdiagram Types {
  enum ArmProgram { NONE, LOAD, PICKUP_AND_DEPLOY; }
  enum ArmStatus { IDLE, BUSY, DONE; }
}
`;

const ARM = `package toast;

import toast.types.*;

component Arm {
  port in ArmProgram cmd,
       in int angle,
       in int height,
       out ArmStatus status,
       out int progress;

  robotarm {
    location toaster 120deg 20cm;
    location plate -90deg 100 mm;

    program Load { move top; open; move toaster; close; move top; }

    program PickupAndDeploy {
      move top; open; move toaster; close; move top; move angle height; open;
    }
  }
}
`;

const RA = `package toast;

// Listing 1.
robotarm ToastService {
  input int angle;
  input int height;
  location toaster 120deg 20cm;
  program PickupAndDeploy {
    move top; open; move toaster; close; move top; move angle height; open;
  }
}
`;

const FILES = { 'toast/types/Types.cd': TYPES, 'toast/Arm.arc': ARM, 'toast/ToastService.ra': RA };

/** The offset of the n-th occurrence (0-based) of a text in a document. */
function offsetOf(doc: LangiumDocument, text: string, n = 0): number {
    const all = doc.textDocument.getText();
    let at = -1;
    for (let i = 0; i <= n; i++) {
        at = all.indexOf(text, at + 1);
        if (at < 0) throw new Error(`'${text}' #${n} not in ${doc.uri.path}`);
    }
    return at;
}

function at(
    doc: LangiumDocument,
    text: string,
    n = 0,
    delta = 1,
): { textDocument: { uri: string }; position: ReturnType<LangiumDocument['textDocument']['positionAt']> } {
    return { textDocument: { uri: doc.uri.toString() }, position: doc.textDocument.positionAt(offsetOf(doc, text, n) + delta) };
}

function pathOf(ws: Workspace, uri: string): [string, LangiumDocument] {
    const found = [...ws.docs].find(([, d]) => d.uri.toString() === uri);
    if (!found) throw new Error(`no document ${uri}`);
    return found;
}

function noErrors(ws: Workspace): void {
    for (const [path, doc] of ws.docs) {
        const errors = (doc.diagnostics ?? []).filter((d) => d.severity === 1 || d.severity === 2);
        expect(errors.map((d) => `${path}: ${d.code} ${d.message}`)).toEqual([]);
    }
}

describe('the fixtures', () => {
    test('check without errors or warnings', async () => {
        noErrors(await workspace(FILES));
    });
});

describe('completion after move', () => {
    async function complete(files: Record<string, string>, path: string): Promise<CompletionItem[]> {
        const ws = await workspace(files);
        const doc = ws.doc(path);
        const list = await servicesOf(doc).lsp.CompletionProvider!.getCompletion(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position(path),
        });
        return list?.items ?? [];
    }

    test("in an embedded block: the block's locations and the component's incoming ports, no outgoing ports", async () => {
        const items = await complete({ ...FILES, 'toast/Arm.arc': ARM.replace('move angle height; open;', 'move <|>') }, 'toast/Arm.arc');
        const names = items.map((i) => i.label);
        for (const n of ['toaster', 'plate', 'angle', 'height', 'cmd', 'top', 'bottom']) expect(names).toContain(n);
        expect(names).not.toContain('status');
        expect(names).not.toContain('progress');
        expect(items.find((i) => i.label === 'angle')!.detail).toBe('in int');
        expect(items.find((i) => i.label === 'toaster')!.documentation).toMatchObject({ value: expect.stringContaining('120deg') });
    });

    test('in an embedded block, a partial name narrows the candidates', async () => {
        const items = await complete({ ...FILES, 'toast/Arm.arc': ARM.replace('move angle height; open;', 'move an<|>') }, 'toast/Arm.arc');
        const names = items.map((i) => i.label);
        expect(names).toContain('angle');
        expect(names).not.toContain('toaster');
    });

    test('inherited incoming ports are offered too', async () => {
        const items = await complete(
            {
                ...FILES,
                'toast/Base.arc': 'package toast;\n\ncomponent Base {\n  port in int reach, out int done;\n}\n',
                'toast/Sub.arc':
                    'package toast;\n\ncomponent Sub extends Base {\n  robotarm {\n    program P {\n      move <|>\n    }\n  }\n}\n',
            },
            'toast/Sub.arc',
        );
        const names = items.map((i) => i.label);
        expect(names).toContain('reach');
        expect(names).not.toContain('done');
    });

    test('in a .ra file: the inputs and locations', async () => {
        const items = await complete(
            { 'toast/ToastService.ra': RA.replace('move angle height; open;', 'move <|>') },
            'toast/ToastService.ra',
        );
        const names = items.map((i) => i.label);
        for (const n of ['angle', 'height', 'toaster', 'top', 'bottom']) expect(names).toContain(n);
        expect(items.find((i) => i.label === 'angle')!.kind).toBe(6 /* Variable */);
    });
});

describe('navigation from move to the port (Port2InputAdapter)', () => {
    test('go to definition from `move angle` lands on the port declaration in the .arc', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Arm.arc');
        const links =
            (await servicesOf(doc).lsp.DefinitionProvider!.getDefinition(doc, at(doc, 'move angle', 0, 'move '.length + 1))) ?? [];
        expect(links).toHaveLength(1);
        const [path, target] = pathOf(ws, links[0]!.targetUri);
        expect(path).toBe('toast/Arm.arc');
        expect(textAt(target, links[0]!.targetSelectionRange)).toBe('angle');
        expect(links[0]!.targetSelectionRange.start.line).toBe(6);
    });

    test('go to definition from `move angle` lands on an inherited port in another file', async () => {
        const ws = await workspace({
            'toast/Base.arc': 'package toast;\n\ncomponent Base {\n  port in int reach, in int lift;\n}\n',
            'toast/Sub.arc':
                'package toast;\n\ncomponent Sub extends Base {\n  robotarm {\n    program P {\n      move reach lift;\n    }\n  }\n}\n',
        });
        const doc = ws.doc('toast/Sub.arc');
        const links = (await servicesOf(doc).lsp.DefinitionProvider!.getDefinition(doc, at(doc, 'reach'))) ?? [];
        const [path, target] = pathOf(ws, links[0]!.targetUri);
        expect([path, textAt(target, links[0]!.targetSelectionRange)]).toEqual(['toast/Base.arc', 'reach']);
    });

    test('go to definition from `move toaster` lands on the location; in a .ra file from `move angle` on the input', async () => {
        const ws = await workspace(FILES);
        const arm = ws.doc('toast/Arm.arc');
        const toLocation =
            (await servicesOf(arm).lsp.DefinitionProvider!.getDefinition(arm, at(arm, 'move toaster', 0, 'move '.length + 1))) ?? [];
        expect(textAt(arm, toLocation[0]!.targetSelectionRange)).toBe('toaster');
        expect(toLocation[0]!.targetSelectionRange.start.line).toBe(12);
        const ra = ws.doc('toast/ToastService.ra');
        const toInput = (await servicesOf(ra).lsp.DefinitionProvider!.getDefinition(ra, at(ra, 'move angle', 0, 'move '.length + 1))) ?? [];
        expect(textAt(ra, toInput[0]!.targetSelectionRange)).toBe('angle');
        expect(toInput[0]!.targetSelectionRange.start.line).toBe(4);
    });

    test('find references from the port include the move', async () => {
        const ws = await workspace({
            ...FILES,
            'toast/Cell.arc': 'package toast;\n\ncomponent Cell {\n  port in int a;\n  Arm arm;\n  a -> arm.angle;\n}\n',
        });
        const doc = ws.doc('toast/Arm.arc');
        const locations: Location[] = await servicesOf(doc).lsp.ReferencesProvider!.findReferences(doc, {
            ...at(doc, 'angle,'),
            context: { includeDeclaration: true },
        });
        const found = locations
            .map((l) => {
                const [p, d] = pathOf(ws, l.uri);
                return `${p}:${l.range.start.line + 1}:${textAt(d, l.range)}`;
            })
            .sort();
        expect(found).toEqual(['toast/Arm.arc:19:angle', 'toast/Arm.arc:7:angle', 'toast/Cell.arc:6:angle']);
    });

    test('renaming the port updates the block (and the connector in another file)', async () => {
        const ws = await workspace({
            ...FILES,
            'toast/Cell.arc': 'package toast;\n\ncomponent Cell {\n  port in int a;\n  Arm arm;\n  a -> arm.height;\n}\n',
        });
        const doc = ws.doc('toast/Arm.arc');
        const edit = await servicesOf(doc).lsp.RenameProvider!.rename(doc, { ...at(doc, 'height,'), newName: 'lift' });
        const after = applyWorkspaceEdit(ws, edit);
        expect(after['toast/Arm.arc']).toContain('       in int lift,\n');
        expect(after['toast/Arm.arc']).toContain('move angle lift; open;');
        expect(after['toast/Cell.arc']).toContain('a -> arm.lift;');
    });

    test('renaming from the use in the block renames the port; renaming a location renames its moves', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Arm.arc');
        const edit = await servicesOf(doc).lsp.RenameProvider!.rename(doc, {
            ...at(doc, 'move angle', 0, 'move '.length + 1),
            newName: 'turn',
        });
        const after = applyWorkspaceEdit(ws, edit)['toast/Arm.arc']!;
        expect(after).toContain('       in int turn,\n');
        expect(after).toContain('move turn height;');
        const loc = await servicesOf(doc).lsp.RenameProvider!.rename(doc, { ...at(doc, 'toaster 120deg'), newName: 'slot' });
        const renamed = applyWorkspaceEdit(ws, loc)['toast/Arm.arc']!;
        expect(renamed).toContain('location slot 120deg 20cm;');
        expect(renamed.match(/move slot;/g)).toHaveLength(2);
    });
});

describe('outline', () => {
    const print = (s: DocumentSymbol, depth = 0): string[] => [
        `${'  '.repeat(depth)}${s.name}${s.detail ? ` : ${s.detail}` : ''}`,
        ...(s.children ?? []).flatMap((c) => print(c, depth + 1)),
    ];

    test('an embedded block: locations and programs under `robotarm`', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Arm.arc');
        const symbols = await servicesOf(doc).lsp.DocumentSymbolProvider!.getSymbols(doc, { textDocument: { uri: doc.uri.toString() } });
        expect(symbols.flatMap((s) => print(s))).toEqual([
            'Arm : toast.Arm',
            '  cmd : in ArmProgram',
            '  angle : in int',
            '  height : in int',
            '  status : out ArmStatus',
            '  progress : out int',
            '  robotarm : 2 locations, 2 programs',
            '    toaster : 120deg 20cm',
            '    plate : -90deg 100 mm',
            '    Load : 5 steps',
            '    PickupAndDeploy : 7 steps',
        ]);
        const robotarm = symbols[0]!.children!.find((s) => s.name === 'robotarm')!;
        expect(textAt(doc, robotarm.selectionRange)).toBe('robotarm');
        expect(robotarm.children!.map((s) => s.kind)).toEqual([
            SymbolKind.Constant,
            SymbolKind.Constant,
            SymbolKind.Function,
            SymbolKind.Function,
        ]);
    });

    test('a .ra file: the robot arm with inputs, locations and programs; folding', async () => {
        const ws = await workspace({ 'toast/ToastService.ra': RA });
        const doc = ws.doc('toast/ToastService.ra');
        const symbols = await servicesOf(doc).lsp.DocumentSymbolProvider!.getSymbols(doc, { textDocument: { uri: doc.uri.toString() } });
        expect(symbols.flatMap((s) => print(s))).toEqual([
            'ToastService : robot arm: 2 inputs, 1 location, 1 program',
            '  angle : input int',
            '  height : input int',
            '  toaster : 120deg 20cm',
            '  PickupAndDeploy : 7 steps',
        ]);
        expect(symbols[0]!.children!.map((s) => s.kind)).toEqual([
            SymbolKind.Variable,
            SymbolKind.Variable,
            SymbolKind.Constant,
            SymbolKind.Function,
        ]);
        const ranges = await servicesOf(doc).lsp.FoldingRangeProvider!.getFoldingRanges(doc, { textDocument: { uri: doc.uri.toString() } });
        expect(ranges.map((r) => `${r.startLine}-${r.endLine}`)).toEqual(['3-9', '7-8']);
    });

    test('folding: the block and a multi-line program', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Arm.arc');
        const ranges = await servicesOf(doc).lsp.FoldingRangeProvider!.getFoldingRanges(doc, { textDocument: { uri: doc.uri.toString() } });
        const lines = ranges.map((r) => `${r.startLine}-${r.endLine}`);
        expect(lines).toContain('11-19'); // robotarm { ... }
        expect(lines).toContain('17-18'); // program PickupAndDeploy { ... }
    });
});

describe('semantic tokens', () => {
    const tokens = (ws: Workspace, path: string): Promise<SemanticToken[]> => semanticTokensOf(ws.doc(path));

    const show = (t: SemanticToken): string => `${t.text} ${t.type}${t.modifiers.length ? ` ${t.modifiers.join(',')}` : ''}`;

    test('embedded: locations, programs, the constants, numbers and units, ports after move styled as ports', async () => {
        const ws = await workspace(FILES);
        const all = (await tokens(ws, 'toast/Arm.arc')).map(show);
        const from = all.indexOf('toaster variable declaration,readonly');
        expect(all.slice(from, from + 20)).toEqual([
            'toaster variable declaration,readonly',
            '120 number',
            'deg type defaultLibrary',
            '20 number',
            'cm type defaultLibrary',
            'plate variable declaration,readonly',
            '-90 number',
            'deg type defaultLibrary',
            '100 number',
            'mm type defaultLibrary',
            'Load function declaration',
            'top variable defaultLibrary,readonly',
            'toaster variable readonly',
            'top variable defaultLibrary,readonly',
            'PickupAndDeploy function declaration',
            'top variable defaultLibrary,readonly',
            'toaster variable readonly',
            'top variable defaultLibrary,readonly',
            // `move angle height`: references to incoming ports, colored like the port declarations.
            'angle property readonly',
            'height property readonly',
        ]);
        expect(all).toContain('angle property declaration,readonly');
        expect(all).toContain('status property declaration');
    });

    test('.ra: the robot arm, inputs (declarations and after move), locations and programs', async () => {
        const ws = await workspace({
            'toast/ToastService.ra': RA.replace('move angle height;', 'move angle height; move -45deg 0.1m; move bottom;'),
        });
        const all = (await tokens(ws, 'toast/ToastService.ra')).map(show);
        expect(all).toEqual([
            'ToastService class declaration',
            'int type defaultLibrary',
            'angle parameter declaration',
            'int type defaultLibrary',
            'height parameter declaration',
            'toaster variable declaration,readonly',
            '120 number',
            'deg type defaultLibrary',
            '20 number',
            'cm type defaultLibrary',
            'PickupAndDeploy function declaration',
            'top variable defaultLibrary,readonly',
            'toaster variable readonly',
            'top variable defaultLibrary,readonly',
            'angle parameter',
            'height parameter',
            '-45 number',
            'deg type defaultLibrary',
            '0.1 number',
            'm type defaultLibrary',
            'bottom variable defaultLibrary,readonly',
        ]);
    });
});

describe('formatting', () => {
    test('an embedded block: two-space indentation, one element per line, one step per line; one-line programs and rows of steps stay', async () => {
        await expectFormatting(lspServices().Arc)({
            before: `component A {
  port in int a, in int h;
robotarm{
location   p 10deg    5cm ;
      location q -1.5rad 100 mm;
program Up {move top ;open;}
  program Empty {   }
  program Row {
        move p;   close;move a h ;
      }
program Steps { move top;
open;
      move   a   h;
 }
    program Rows {
        move top;  open;
  move p; close;
 move top;
    }
}
}
`,
            after: `component A {
  port in int a, in int h;
  robotarm {
    location p 10deg 5cm;
    location q -1.5rad 100 mm;
    program Up { move top; open; }
    program Empty { }
    program Row {
      move p; close; move a h;
    }
    program Steps {
      move top;
      open;
      move a h;
    }
    program Rows {
      move top; open;
      move p; close;
      move top;
    }
  }
}
`,
            disposeAfterCheck: true,
        });
    });

    test('a .ra file: package, blank line, the robot arm', async () => {
        await expectFormatting(lspServices().languages.get('ra')!)({
            before: 'package  toast ;\nrobotarm   ToastService{\ninput int  angle ;\n   input int height;\nlocation toaster 120deg 20cm;\nprogram P{\nmove angle height ;\n    open ;\n}\n}\n',
            after: 'package toast;\n\nrobotarm ToastService {\n  input int angle;\n  input int height;\n  location toaster 120deg 20cm;\n  program P {\n    move angle height;\n    open;\n  }\n}\n',
            disposeAfterCheck: true,
        });
    });

    test('comments in a program keep it one step per line, the comments indented with it', async () => {
        await expectFormatting(lspServices().Arc)({
            before: 'component A {\n  robotarm {\n  // the pickup\n  program P {\n  move top; // up\n      open;\n  }\n  }\n}\n',
            after: 'component A {\n  robotarm {\n    // the pickup\n    program P {\n      move top; // up\n      open;\n    }\n  }\n}\n',
            disposeAfterCheck: true,
        });
    });

    const here = dirname(fileURLToPath(import.meta.url));
    const example = resolve(here, '../../../examples/toast-service');
    test.each([['toast/ArmController.arc'], ['toast/ToastService.ra']])(
        'the example %s is already formatted (formatting changes nothing)',
        async (path) => {
            const text = readFileSync(resolve(example, path), 'utf8');
            const ws = await workspace({
                'toast/types/Types.cd': readFileSync(resolve(example, 'toast/types/Types.cd'), 'utf8'),
                [path]: text,
            });
            const doc = ws.doc(path);
            const edits = await servicesOf(doc).lsp.Formatter!.formatDocument(doc, {
                textDocument: { uri: doc.uri.toString() },
                options: { tabSize: 2, insertSpaces: true },
            });
            expect(applyEdits(doc, edits)).toBe(text);
        },
    );
});

describe('hover', () => {
    async function hoverAt(ws: Workspace, path: string, text: string, n = 0, delta = 1): Promise<string> {
        const doc = ws.doc(path);
        const hover: Hover | undefined = await servicesOf(doc).lsp.HoverProvider!.getHoverContent(doc, at(doc, text, n, delta));
        return hover ? (hover.contents as { value: string }).value : '';
    }

    test('a location: its angle and height in source and SI units', async () => {
        const ws = await workspace(FILES);
        const h = await hoverAt(ws, 'toast/Arm.arc', 'toaster 120deg');
        expect(h).toContain('```arc\nlocation toaster 120deg 20cm\n```');
        expect(h).toContain('Location of the robotarm block of component `Arm`');
        expect(h).toContain('joint angle `120deg` = 2.0944 rad');
        expect(h).toContain('gripper height `20cm` = 0.2 m');
        // From a use after `move`, with the unit as written.
        const plate = await hoverAt(ws, 'toast/Arm.arc', 'plate -90deg');
        expect(plate).toContain('joint angle `-90deg` = -1.5708 rad');
        expect(plate).toContain('gripper height `100 mm` = 0.1 m');
        expect(await hoverAt(ws, 'toast/Arm.arc', 'move toaster', 0, 'move '.length + 1)).toContain('joint angle `120deg`');
    });

    test('a program lists its steps', async () => {
        const ws = await workspace(FILES);
        const h = await hoverAt(ws, 'toast/Arm.arc', 'PickupAndDeploy');
        expect(h).toContain('```arc\nprogram PickupAndDeploy\n```');
        expect(h).toContain('started by the command `PICKUP_AND_DEPLOY` on port `cmd`');
        expect(h).toContain(
            [
                '1. `move top;` — lift to `top` (angle unchanged, height 30cm)',
                '2. `open;` — open the gripper',
                '3. `move toaster;` — to location `toaster` (angle 120deg, height 20cm)',
                '4. `close;` — close the gripper',
                '5. `move top;` — lift to `top` (angle unchanged, height 30cm)',
                '6. `move angle height;` — angle port `angle` (deg), height port `height` (cm)',
                '7. `open;` — open the gripper',
            ].join('\n'),
        );
    });

    test('`move angle` on a port shows the port', async () => {
        const ws = await workspace(FILES);
        const h = await hoverAt(ws, 'toast/Arm.arc', 'move angle', 0, 'move '.length + 1);
        expect(h).toContain('port in int angle');
        expect(h).toContain('Incoming port of component `Arm`');
    });

    test('.ra: an input, the robot arm and a program of a file', async () => {
        const ws = await workspace({ 'toast/ToastService.ra': RA });
        const input = await hoverAt(ws, 'toast/ToastService.ra', 'move angle', 0, 'move '.length + 1);
        expect(input).toContain('```ra\ninput int angle\n```');
        expect(input).toContain('Input of robot arm `ToastService`');
        const arm = await hoverAt(ws, 'toast/ToastService.ra', 'ToastService {');
        expect(arm).toContain('**Inputs**: `angle`, `height`');
        expect(arm).toContain('Listing 1.');
        const program = await hoverAt(ws, 'toast/ToastService.ra', 'PickupAndDeploy');
        expect(program).toContain('6. `move angle height;` — angle input `angle` (deg), height input `height` (cm)');
    });
});

describe('quick fixes', () => {
    function diagnostic(ws: Workspace, path: string, code: string): Diagnostic {
        const doc = ws.doc(path);
        const found = (doc.diagnostics ?? []).filter((d) => d.code === code);
        if (found.length === 0)
            throw new Error(`no ${code} in ${path}: ${JSON.stringify(doc.diagnostics?.map((d) => `${d.code} ${d.message}`))}`);
        return found[0]!;
    }

    async function fixes(ws: Workspace, path: string, code: string): Promise<CodeAction[]> {
        const doc = ws.doc(path);
        const d = diagnostic(ws, path, code);
        return ((await servicesOf(doc).lsp.CodeActionProvider!.getCodeActions(doc, {
            textDocument: { uri: doc.uri.toString() },
            range: d.range,
            context: { diagnostics: [d] },
        })) ?? []) as CodeAction[];
    }

    async function apply(ws: Workspace, action: CodeAction | undefined): Promise<{ files: Record<string, string>; after: Workspace }> {
        expect(action, 'a quick fix').toBeDefined();
        const changed = applyWorkspaceEdit(ws, action!.edit);
        const files: Record<string, string> = {};
        for (const [path, doc] of ws.docs) files[path] = changed[path] ?? doc.textDocument.getText();
        return { files, after: await workspace(files) };
    }

    const codes = (ws: Workspace, path: string): string[] => (ws.doc(path).diagnostics ?? []).map((d) => String(d.code));

    test('robotarm/unresolved-name in `move x;`: create a location', async () => {
        const ws = await workspace({
            ...FILES,
            'toast/Arm.arc': ARM.replace('move toaster; close; move top; }', 'move plat; close; move top; }'),
        });
        const actions = await fixes(ws, 'toast/Arm.arc', 'robotarm/unresolved-name');
        expect(actions.map((a) => a.title)).toEqual(["Create location 'plat'"]);
        expect(actions[0]!.isPreferred).toBe(true);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Arm.arc']).toContain('    location plate -90deg 100 mm;\n    location plat 0deg 20cm;\n\n    program Load');
        expect(codes(after, 'toast/Arm.arc')).toEqual([]);
    });

    test('robotarm/unresolved-name in a block without locations and in a .ra file', async () => {
        const ws = await workspace({
            'toast/Solo.ra': 'package toast;\n\nrobotarm Solo {\n  input int angle;\n  program P { move home; }\n}\n',
        });
        const { files, after } = await apply(ws, (await fixes(ws, 'toast/Solo.ra', 'robotarm/unresolved-name'))[0]);
        expect(files['toast/Solo.ra']).toBe(
            'package toast;\n\nrobotarm Solo {\n  input int angle;\n  location home 0deg 20cm;\n  program P { move home; }\n}\n',
        );
        expect(codes(after, 'toast/Solo.ra')).toEqual([]);

        const embedded = await workspace({
            ...FILES,
            'toast/Arm.arc': ARM.replace(/ {4}location toaster .*\n {4}location plate .*\n\n/, '')
                .replace(/move toaster;/g, 'move top;')
                .replace('move top; }', 'move rest; }'),
        });
        const fixed = await apply(embedded, (await fixes(embedded, 'toast/Arm.arc', 'robotarm/unresolved-name'))[0]);
        expect(fixed.files['toast/Arm.arc']).toContain('  robotarm {\n    location rest 0deg 20cm;\n    program Load');
        expect(codes(fixed.after, 'toast/Arm.arc')).toEqual([]);
    });

    test('robotarm/unresolved-name in a joint move: create an incoming port (embedded) or an input (.ra)', async () => {
        const ws = await workspace({ ...FILES, 'toast/Arm.arc': ARM.replace('move angle height;', 'move angle lift;') });
        const actions = await fixes(ws, 'toast/Arm.arc', 'robotarm/unresolved-name');
        expect(actions.map((a) => a.title)).toEqual(["Create incoming port 'lift' in 'Arm'"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Arm.arc']).toContain('       out int progress;\n  port in int lift;\n');
        expect(codes(after, 'toast/Arm.arc')).toEqual([]);

        const ra = await workspace({ 'toast/ToastService.ra': RA.replace('move angle height;', 'move turn height;') });
        const raFix = await apply(ra, (await fixes(ra, 'toast/ToastService.ra', 'robotarm/unresolved-name'))[0]);
        expect(raFix.files['toast/ToastService.ra']).toContain('  input int height;\n  input int turn;\n  location toaster');
        expect(codes(raFix.after, 'toast/ToastService.ra')).toEqual([]);
    });

    test('robotarm/input-in-embedded: remove the input, or replace it by an incoming port', async () => {
        const ws = await workspace({
            ...FILES,
            'toast/Arm.arc': ARM.replace('  robotarm {\n', '  robotarm {\n    input int angle;\n    input double speed;\n'),
        });
        const removeOnly = await fixes(ws, 'toast/Arm.arc', 'robotarm/input-in-embedded');
        // `angle` is a port already: the only fix is to remove the input.
        expect(removeOnly.map((a) => a.title)).toEqual(["Remove input 'angle'"]);
        const removed = await apply(ws, removeOnly[0]);
        expect(removed.files['toast/Arm.arc']).toContain('  robotarm {\n    input double speed;\n    location toaster');

        const speed = await fixes(removed.after, 'toast/Arm.arc', 'robotarm/input-in-embedded');
        expect(speed.map((a) => a.title)).toEqual(["Replace input 'speed' by 'port in double speed;'", "Remove input 'speed'"]);
        const replaced = await apply(removed.after, speed[0]);
        expect(replaced.files['toast/Arm.arc']).toContain(
            '       out int progress;\n  port in double speed;\n\n  robotarm {\n    location toaster',
        );
        expect(codes(replaced.after, 'toast/Arm.arc')).toEqual([]);
        const dropped = await apply(removed.after, speed[1]);
        expect(dropped.files['toast/Arm.arc']).toBe(ARM);
    });

    test('robotarm/missing-cmd-port: declare `cmd` with the enum whose constants name the programs (imported if needed)', async () => {
        const noCmd = ARM.replace('  port in ArmProgram cmd,\n       in int angle,', '  port in int angle,').replace(
            'import toast.types.*;\n\n',
            '',
        );
        const ws = await workspace({ ...FILES, 'toast/Arm.arc': noCmd.replace(/ArmStatus status/, 'toast.types.ArmStatus status') });
        const actions = await fixes(ws, 'toast/Arm.arc', 'robotarm/missing-cmd-port');
        expect(actions.map((a) => a.title)).toEqual(["Declare 'port in ArmProgram cmd;' in 'Arm'"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Arm.arc']).toContain('package toast;\n\nimport toast.types.ArmProgram;\n');
        expect(files['toast/Arm.arc']).toContain('       out int progress;\n  port in ArmProgram cmd;\n');
        expect(codes(after, 'toast/Arm.arc')).toEqual([]);
    });

    test('robotarm/missing-cmd-port: no fix without a fitting enum; a `cmd` port of the wrong direction is turned around', async () => {
        const ws = await workspace({
            'toast/types/Types.cd': TYPES.replace('PICKUP_AND_DEPLOY', 'DANCE'),
            'toast/Arm.arc': ARM.replace('  port in ArmProgram cmd,\n       in int angle,', '  port in int angle,'),
        });
        expect(await fixes(ws, 'toast/Arm.arc', 'robotarm/missing-cmd-port')).toEqual([]);

        const out = await workspace({ ...FILES, 'toast/Arm.arc': ARM.replace('port in ArmProgram cmd', 'port out ArmProgram cmd') });
        const actions = await fixes(out, 'toast/Arm.arc', 'robotarm/missing-cmd-port');
        expect(actions.map((a) => a.title)).toEqual(["Make port 'cmd' incoming"]);
        const { files, after } = await apply(out, actions[0]);
        expect(files['toast/Arm.arc']).toBe(ARM);
        expect(codes(after, 'toast/Arm.arc')).toEqual([]);
    });

    test('robotarm/missing-status-port: declare `status` with the enum of IDLE, BUSY, DONE', async () => {
        const ws = await workspace({ ...FILES, 'toast/Arm.arc': ARM.replace('       out ArmStatus status,\n', '') });
        const actions = await fixes(ws, 'toast/Arm.arc', 'robotarm/missing-status-port');
        expect(actions.map((a) => a.title)).toEqual(["Declare 'port out ArmStatus status;' in 'Arm'"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Arm.arc']).toContain('       out int progress;\n  port out ArmStatus status;\n');
        expect(codes(after, 'toast/Arm.arc')).toEqual([]);

        const none = await workspace({
            'toast/types/Types.cd': TYPES.replace('DONE', 'FINISHED'),
            'toast/Arm.arc': ARM.replace('       out ArmStatus status,\n', ''),
        });
        expect(await fixes(none, 'toast/Arm.arc', 'robotarm/missing-status-port')).toEqual([]);
    });

    test('robotarm/naming-convention: rename with every use', async () => {
        const ws = await workspace({ ...FILES, 'toast/Arm.arc': ARM.replace(/toaster/g, 'Toaster') });
        const actions = await fixes(ws, 'toast/Arm.arc', 'robotarm/naming-convention');
        expect(actions.map((a) => a.title)).toEqual(["Rename 'Toaster' to 'toaster'"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Arm.arc']).toBe(ARM);
        expect(codes(after, 'toast/Arm.arc')).toEqual([]);
    });

    test('robotarm/invalid-unit without a unit: add deg to an angle, cm to a height', async () => {
        const ws = await workspace({
            'toast/ToastService.ra': RA.replace('120deg 20cm', '120 20cm').replace('move angle height;', 'move angle 15;'),
        });
        const angle = await fixes(ws, 'toast/ToastService.ra', 'robotarm/invalid-unit');
        expect(angle.map((a) => a.title)).toEqual(["Add the unit 'deg' (120deg)"]);
        const first = await apply(ws, angle[0]);
        const height = await fixes(first.after, 'toast/ToastService.ra', 'robotarm/invalid-unit');
        expect(height.map((a) => a.title)).toEqual(["Add the unit 'cm' (15cm)"]);
        const second = await apply(first.after, height[0]);
        expect(second.files['toast/ToastService.ra']).toBe(RA.replace('move angle height;', 'move angle 15cm;'));
        expect(codes(second.after, 'toast/ToastService.ra')).toEqual([]);
    });

    test('robotarm/file-name-mismatch: rename the robot arm after the file, or the file', async () => {
        const ws = await workspace({ 'toast/Toasting.ra': RA });
        const actions = await fixes(ws, 'toast/Toasting.ra', 'robotarm/file-name-mismatch');
        expect(actions.map((a) => a.title)).toEqual(["Rename 'ToastService' to 'Toasting'", "Rename file to 'ToastService.ra'"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Toasting.ra']).toBe(RA.replace('robotarm ToastService {', 'robotarm Toasting {'));
        expect(codes(after, 'toast/Toasting.ra')).toEqual([]);
        expect(actions[1]!.edit!.documentChanges).toEqual([
            {
                kind: 'rename',
                oldUri: ws.doc('toast/Toasting.ra').uri.toString(),
                newUri: ws.doc('toast/Toasting.ra').uri.toString().replace('Toasting.ra', 'ToastService.ra'),
            },
        ]);
    });

    test('robotarm/package-mismatch: change, add or remove the package declaration', async () => {
        const wrong = await workspace({ 'toast/ToastService.ra': RA.replace('package toast;', 'package kitchen;') });
        const change = await apply(wrong, (await fixes(wrong, 'toast/ToastService.ra', 'robotarm/package-mismatch'))[0]);
        expect(change.files['toast/ToastService.ra']).toBe(RA);
        expect(codes(change.after, 'toast/ToastService.ra')).toEqual([]);

        const missing = await workspace({ 'toast/ToastService.ra': RA.replace('package toast;\n\n', '') });
        const add = await fixes(missing, 'toast/ToastService.ra', 'robotarm/package-mismatch');
        expect(add.map((a) => a.title)).toEqual(["Add 'package toast;'"]);
        expect((await apply(missing, add[0])).files['toast/ToastService.ra']).toBe(RA);

        const top = await workspace({ 'ToastService.ra': RA });
        const remove = await apply(top, (await fixes(top, 'ToastService.ra', 'robotarm/package-mismatch'))[0]);
        expect(remove.files['ToastService.ra']).toBe(RA.replace('package toast;\n\n', ''));
        expect(codes(remove.after, 'ToastService.ra')).toEqual([]);
    });
});
