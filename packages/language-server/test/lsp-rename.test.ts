// Rename across the language family and the files of a model root: ports (connectors, guards,
// actions, events of automata), components (subcomponent types, qualified references,
// imports, the file), states, enum constants; invalid names and built-in elements are refused.
import { describe, expect, test } from 'vitest';
import type { WorkspaceEdit } from 'vscode-languageserver-types';
import { behaviorLanguages } from '../src/family.js';
import { applyWorkspaceEdit, servicesOf, TYPES_CD, workspace, type Workspace } from './lsp-helpers.js';

const CONTROLLER = `package toast;

import toast.types.*;

component Controller {
  port in int distance,
       in ToastColor color,
       out ToasterCmd toaster;

  <<timed>> automaton {
    initial { toaster = ToasterCmd.STOP; } state Idle;
    state Busy;
    Idle -> Busy [distance < 10] distance / { toaster = ToasterCmd.START; };
    Busy -> Idle [color == ToastColor.GOLDEN && distance > 0] color;
  }
}
`;

const ROBOT = `package toast;

import toast.Controller;
import toast.types.*;

component Robot {
  port in int d;
  port in ToastColor c;
  port out ToasterCmd t;
  Controller ctrl;
  toast.Controller other;
  d -> ctrl.distance, other.distance;
  c -> ctrl.color, other.color;
  ctrl.toaster -> t;
}
`;

const FACTORY = `package plant;

import toast.*;

component Factory extends toast.Controller {
  Robot robot;
}
`;

const FILES = {
    'toast/types/Types.cd': TYPES_CD,
    'toast/Controller.arc': CONTROLLER,
    'toast/Robot.arc': ROBOT,
    'plant/Factory.arc': FACTORY,
};

async function renameAt(ws: Workspace, path: string, text: string, newName: string): Promise<WorkspaceEdit | undefined> {
    const doc = ws.doc(path);
    const offset = doc.textDocument.getText().indexOf(text);
    if (offset < 0) throw new Error(`'${text}' not in ${path}`);
    return servicesOf(doc).lsp.RenameProvider!.rename(doc, {
        textDocument: { uri: doc.uri.toString() },
        position: doc.textDocument.positionAt(offset + 1),
        newName,
    });
}

describe('rename', () => {
    test("a port: its declaration, the automaton's guards, events and actions, connectors in other files", async () => {
        const ws = await workspace(FILES);
        const after = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Controller.arc', 'distance,', 'range'));
        expect(Object.keys(after).sort()).toEqual(['toast/Controller.arc', 'toast/Robot.arc']);
        expect(after['toast/Controller.arc']).toContain('  port in int range,\n');
        expect(after['toast/Controller.arc']).toContain('Idle -> Busy [range < 10] range / { toaster = ToasterCmd.START; };');
        expect(after['toast/Controller.arc']).toContain('[color == ToastColor.GOLDEN && range > 0] color;');
        expect(after['toast/Controller.arc']).not.toContain('distance');
        expect(after['toast/Robot.arc']).toContain('d -> ctrl.range, other.range;');
    });

    test('a port from one of its uses (an event of a transition)', async () => {
        const ws = await workspace(FILES);
        const after = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Controller.arc', 'color;', 'shade'));
        expect(after['toast/Controller.arc']).toContain('in ToastColor shade,');
        expect(after['toast/Controller.arc']).toContain('[shade == ToastColor.GOLDEN && distance > 0] shade;');
        expect(after['toast/Robot.arc']).toContain('c -> ctrl.shade, other.shade;');
    });

    test('a component: subcomponent types, qualified references, parents and imports across files', async () => {
        const ws = await workspace(FILES);
        const after = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Controller.arc', 'Controller {', 'Brain'));
        expect(after['toast/Controller.arc']).toContain('component Brain {');
        expect(after['toast/Robot.arc']).toContain('import toast.Brain;');
        expect(after['toast/Robot.arc']).toContain('  Brain ctrl;\n  toast.Brain other;\n');
        expect(after['plant/Factory.arc']).toContain('component Factory extends toast.Brain {');
        // Wildcard imports stay as they are.
        expect(after['plant/Factory.arc']).toContain('import toast.*;');
    });

    test('prepareRename: the name under the cursor, the last segment of a qualified name', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Robot.arc');
        const provider = servicesOf(doc).lsp.RenameProvider!;
        const at = (text: string, delta = 1) => doc.textDocument.positionAt(doc.textDocument.getText().indexOf(text) + delta);
        const prepare = (text: string, delta?: number) => {
            const r = provider.prepareRename(doc, { textDocument: { uri: doc.uri.toString() }, position: at(text, delta) });
            return r && 'start' in r ? doc.textDocument.getText(r) : undefined;
        };
        expect(prepare('toast.Controller other')).toBe('Controller');
        expect(prepare('Controller other', 3)).toBe('Controller');
        expect(prepare('ctrl.distance', 6)).toBe('distance');
        expect(prepare('import toast.Controller', 1)).toBeUndefined();
    });

    test('a component from a single-type import', async () => {
        const ws = await workspace(FILES);
        const after = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Robot.arc', 'Controller;', 'Brain'));
        expect(after['toast/Controller.arc']).toContain('component Brain {');
        expect(after['toast/Robot.arc']).toContain('import toast.Brain;');
    });

    test("a component from a subcomponent's type; a file rename when the client supports it", async () => {
        const ws = await workspace(FILES);
        const edit = await renameAt(ws, 'toast/Robot.arc', 'Controller ctrl', 'Brain');
        const after = applyWorkspaceEdit(ws, edit);
        expect(after['toast/Controller.arc']).toContain('component Brain {');
        // Without the client capability the edit is a plain `changes` map.
        expect(edit?.documentChanges).toBeUndefined();
    });

    test('a class-diagram type and an enum constant (member accesses included)', async () => {
        const ws = await workspace(FILES);
        const type = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/types/Types.cd', 'ToasterCmd', 'HeaterCmd'));
        expect(type['toast/types/Types.cd']).toContain('enum HeaterCmd { START, STOP; }');
        expect(type['toast/Controller.arc']).toContain('out HeaterCmd toaster;');
        expect(type['toast/Controller.arc']).toContain('initial { toaster = HeaterCmd.STOP; } state Idle;');
        expect(type['toast/Robot.arc']).toContain('port out HeaterCmd t;');

        const constant = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/types/Types.cd', 'GOLDEN', 'BROWN'));
        expect(constant['toast/types/Types.cd']).toContain('enum ToastColor { WHITE, BROWN, BURNT; }');
        expect(constant['toast/Controller.arc']).toContain('[color == ToastColor.BROWN && distance > 0]');
    });

    test('a state: its transitions', async () => {
        const ws = await workspace(FILES);
        const after = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Controller.arc', 'Busy;', 'Heating'));
        expect(after['toast/Controller.arc']).toContain('state Heating;\n    Idle -> Heating [');
        expect(after['toast/Controller.arc']).toContain('Heating -> Idle [');
    });

    // Only when the RobotArm language is part of the family (packages/language-server, `maa.family`).
    test.runIf(behaviorLanguages().some((l) => /robot/i.test(l)))(
        'a port used in an embedded RobotArm block (`move angle height`) and in another file',
        async () => {
            const ws = await workspace({
                'toast/Arm.arc':
                    'package toast;\n\ncomponent Arm {\n  port in int angle,\n       in int height;\n  robotarm {\n    program Deliver {\n      move angle height;\n    }\n  }\n}\n',
                'toast/Cell.arc':
                    'package toast;\n\ncomponent Cell {\n  port in int a, in int h;\n  Arm arm;\n  a -> arm.angle;\n  h -> arm.height;\n}\n',
            });
            const after = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Arm.arc', 'angle,', 'joint'));
            expect(after['toast/Arm.arc']).toContain('port in int joint,');
            expect(after['toast/Arm.arc']).toContain('move joint height;');
            expect(after['toast/Cell.arc']).toContain('a -> arm.joint;');
        },
    );

    test('invalid names are refused; built-in library elements cannot be renamed', async () => {
        const ws = await workspace({ ...FILES, 'toast/S.arc': 'package toast;\n\ncomponent S {\n  port in String s;\n}\n' });
        await expect(renameAt(ws, 'toast/Controller.arc', 'distance,', '1abc')).rejects.toThrow(/not a valid name/);
        expect(await renameAt(ws, 'toast/S.arc', 'String', 'Text')).toBeUndefined();
        const doc = ws.doc('toast/S.arc');
        const at = doc.textDocument.positionAt(doc.textDocument.getText().indexOf('String') + 1);
        expect(
            servicesOf(doc).lsp.RenameProvider!.prepareRename(doc, { textDocument: { uri: doc.uri.toString() }, position: at }),
        ).toBeUndefined();
    });

    test('renaming a top-level component renames its file when the client supports file renames', async () => {
        const ws = await workspace(FILES);
        const provider = servicesOf(ws.doc('toast/Controller.arc')).lsp.RenameProvider;
        const component = (
            ws.doc('toast/Controller.arc').parseResult.value as unknown as { component: Parameters<typeof provider.renameElement>[0] }
        ).component;
        // Simulate a client with `workspace.workspaceEdit.resourceOperations: ['rename']`.
        (provider as unknown as { canRenameFiles: boolean }).canRenameFiles = true;
        try {
            const edit = provider.renameElement(component, 'Brain');
            const changes = edit.documentChanges ?? [];
            const rename = changes.find((c) => 'kind' in c && c.kind === 'rename');
            expect(rename).toEqual({
                kind: 'rename',
                oldUri: ws.doc('toast/Controller.arc').uri.toString(),
                newUri: ws.doc('toast/Controller.arc').uri.toString().replace('Controller.arc', 'Brain.arc'),
            });
            // The text edits come first (they address the old file name).
            expect(changes.indexOf(rename!)).toBe(changes.length - 1);
            expect(applyWorkspaceEdit(ws, edit)['toast/Robot.arc']).toContain('  Brain ctrl;');
        } finally {
            (provider as unknown as { canRenameFiles: boolean }).canRenameFiles = false;
        }
    });
});
