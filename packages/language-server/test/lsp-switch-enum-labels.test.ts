// Editor support for bare enum constants as case labels (`case GOLDEN:` in a switch over a
// ToastColor): go-to-definition and hover reach the constant, renaming the constant renames the
// labels (bare and qualified), completion after `case` offers the selector enum's constants.
import { describe, expect, test } from 'vitest';
import type { WorkspaceEdit } from 'vscode-languageserver-types';
import { applyWorkspaceEdit, lspServices, servicesOf, textAt, TYPES_CD, workspace, type Workspace } from './lsp-helpers.js';

const TOASTER = `package toast;

import toast.types.*;

component Toaster {
  port in ToastColor color;
  port out int level;
  compute {
    switch (color) {
      case WHITE:
        level = 1;
        break;
      case GOLDEN, ToastColor.BURNT:
        level = 2;
    }
  }
}
`;

const FILES = { 'toast/types/Types.cd': TYPES_CD, 'toast/Toaster.arc': TOASTER };

function positionOf(ws: Workspace, path: string, text: string): { uri: string; position: ReturnType<Workspace['position']> } {
    const doc = ws.doc(path);
    const offset = doc.textDocument.getText().indexOf(text);
    if (offset < 0) throw new Error(`'${text}' not in ${path}`);
    return { uri: doc.uri.toString(), position: doc.textDocument.positionAt(offset + 1) };
}

describe('bare enum constants as case labels in the editor', () => {
    test('the model has no diagnostics', async () => {
        const ws = await workspace(FILES);
        expect(ws.doc('toast/Toaster.arc').diagnostics ?? []).toEqual([]);
    });

    test('go-to-definition on a label reaches the constant in the class diagram', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Toaster.arc');
        const { uri, position } = positionOf(ws, 'toast/Toaster.arc', 'GOLDEN,');
        const links = (await servicesOf(doc).lsp.DefinitionProvider!.getDefinition(doc, { textDocument: { uri }, position })) ?? [];
        const cd = ws.doc('toast/types/Types.cd');
        expect(
            links.map((l) => `${l.targetUri === cd.uri.toString() ? 'Types.cd' : l.targetUri}:${textAt(cd, l.targetSelectionRange)}`),
        ).toEqual(['Types.cd:GOLDEN']);
    });

    test('hover on a label describes the enum constant', async () => {
        const ws = await workspace(FILES);
        const doc = ws.doc('toast/Toaster.arc');
        const { uri, position } = positionOf(ws, 'toast/Toaster.arc', 'WHITE:');
        const hover = await servicesOf(doc).lsp.HoverProvider!.getHoverContent(doc, { textDocument: { uri }, position });
        expect((hover?.contents as { value: string } | undefined)?.value ?? '').toContain('Constant of enumeration `ToastColor`');
    });

    test('renaming the constant renames the bare and the qualified labels', async () => {
        const ws = await workspace(FILES);
        const cd = ws.doc('toast/types/Types.cd');
        const rename = async (text: string, newName: string): Promise<Record<string, string>> => {
            const { uri, position } = positionOf(ws, 'toast/types/Types.cd', text);
            const edit: WorkspaceEdit | undefined = await servicesOf(cd).lsp.RenameProvider!.rename(cd, {
                textDocument: { uri },
                position,
                newName,
            });
            return applyWorkspaceEdit(ws, edit);
        };
        const golden = await rename('GOLDEN', 'TOASTED');
        expect(golden['toast/types/Types.cd']).toContain('enum ToastColor { WHITE, TOASTED, BURNT; }');
        expect(golden['toast/Toaster.arc']).toContain('      case TOASTED, ToastColor.BURNT:\n');
        const burnt = await rename('BURNT', 'BLACK');
        expect(burnt['toast/Toaster.arc']).toContain('      case GOLDEN, ToastColor.BLACK:\n');
        // Renaming from a bare label works too.
        const doc = ws.doc('toast/Toaster.arc');
        const at = positionOf(ws, 'toast/Toaster.arc', 'WHITE:');
        const fromLabel = applyWorkspaceEdit(
            ws,
            await servicesOf(doc).lsp.RenameProvider!.rename(doc, {
                textDocument: { uri: at.uri },
                position: at.position,
                newName: 'PALE',
            }),
        );
        expect(fromLabel['toast/Toaster.arc']).toContain('      case PALE:\n');
        expect(fromLabel['toast/types/Types.cd']).toContain('enum ToastColor { PALE, GOLDEN, BURNT; }');
    });

    test('completion after case offers the constants of the selector enum (and no port names)', async () => {
        const ws = await workspace({
            'toast/types/Types.cd': TYPES_CD,
            'toast/Toaster.arc': TOASTER.replace('      case GOLDEN, ToastColor.BURNT:', '      case <|>'),
        });
        const doc = ws.doc('toast/Toaster.arc');
        const list = await lspServices().Arc.lsp.CompletionProvider.getCompletion(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('toast/Toaster.arc'),
        });
        const labels = (list?.items ?? []).map((i) => i.label);
        expect(labels).toEqual(expect.arrayContaining(['WHITE', 'GOLDEN', 'BURNT']));
        expect(labels).not.toContain('color');
        expect(labels).not.toContain('START');
    });

    test('in a switch expression too: completion after case offers the constants, definition reaches them', async () => {
        const expr = TOASTER.replace(
            / {4}switch \(color\) \{[\s\S]*?\n {4}\}\n/,
            '    level = switch (color) { case WHITE -> 1; case <|> };\n',
        );
        const ws = await workspace({ 'toast/types/Types.cd': TYPES_CD, 'toast/Toaster.arc': expr });
        const doc = ws.doc('toast/Toaster.arc');
        const list = await lspServices().Arc.lsp.CompletionProvider.getCompletion(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('toast/Toaster.arc'),
        });
        expect((list?.items ?? []).map((i) => i.label)).toEqual(expect.arrayContaining(['WHITE', 'GOLDEN', 'BURNT']));
        const ok = await workspace({
            'toast/types/Types.cd': TYPES_CD,
            'toast/Toaster.arc': expr.replace('case <|> }', 'case GOLDEN, BURNT -> 2; }'),
        });
        const d = ok.doc('toast/Toaster.arc');
        expect(d.diagnostics ?? []).toEqual([]);
        const { uri, position } = positionOf(ok, 'toast/Toaster.arc', 'BURNT ->');
        const links = (await servicesOf(d).lsp.DefinitionProvider!.getDefinition(d, { textDocument: { uri }, position })) ?? [];
        expect(links.map((l) => textAt(ok.doc('toast/types/Types.cd'), l.targetSelectionRange))).toEqual(['BURNT']);
    });
});
