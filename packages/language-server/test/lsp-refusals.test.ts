// Requests that cannot be served are refused with an LSP error a user can read, never an
// internal error: rename to a string that is no name of the languages the edit touches, and
// rename of the generator names of an `.arcapp` (declared in manifests, not in model files).
// References, highlight and prepareRename on those generator names answer from the documents.
import { readdirSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { URI, type LangiumDocument } from 'langium';
import { NodeFileSystem } from 'langium/node';
import { describe, expect, test } from 'vitest';
import { ErrorCodes, LSPErrorCodes, ResponseError } from 'vscode-languageserver-protocol';
import type { WorkspaceEdit } from 'vscode-languageserver-types';
import { builtinDocuments, type AdlLspServices } from '@maa/language-adl';
import { createMaaLspServices } from '../src/family.js';
import { applyWorkspaceEdit, servicesOf, TYPES_CD, workspace, type Workspace } from './lsp-helpers.js';

const ROBOT = `package toast;

component Robot {
  port in int distance;

  robotarm {
    location toaster 120deg 20cm;
    program Load { move toaster; }
  }
}
`;

const APP = `application App for toast.Robot {
}
`;

const ARM = `package toast;

robotarm Arm {
  input int angle;
  location toaster 120deg 20cm;
  program Load { move toaster; move angle; }
}
`;

const FILES = { 'toast/types/Types.cd': TYPES_CD, 'toast/Robot.arc': ROBOT, 'App.arcapp': APP, 'toast/Arm.ra': ARM };

function positionOf(doc: LangiumDocument, text: string, delta = 1): { line: number; character: number } {
    const offset = doc.textDocument.getText().indexOf(text);
    if (offset < 0) throw new Error(`'${text}' not in ${doc.uri.toString()}`);
    return doc.textDocument.positionAt(offset + delta);
}

async function renameAt(ws: Workspace, path: string, text: string, newName: string): Promise<WorkspaceEdit | undefined> {
    const doc = ws.doc(path);
    return servicesOf(doc).lsp.RenameProvider!.rename(doc, {
        textDocument: { uri: doc.uri.toString() },
        position: positionOf(doc, text),
        newName,
    });
}

/** The error a rename is refused with (fails when the rename is not refused). */
async function refusal(ws: Workspace, path: string, text: string, newName: string): Promise<ResponseError<unknown>> {
    try {
        await renameAt(ws, path, text, newName);
    } catch (e) {
        if (e instanceof ResponseError) return e;
        throw new Error(`refused with a ${String(e)} instead of an LSP error`);
    }
    throw new Error(`renaming '${text}' in ${path} to '${newName}' was not refused`);
}

describe('rename refuses names that a language cannot parse', () => {
    test.each([
        ['', /cannot be empty/],
        ['a b', /starts with a letter/],
        ['1abc', /starts with a letter/],
        ['x-y', /starts with a letter/],
        ['component', /'component' is a keyword of \.arc files/],
    ])('%j is refused with InvalidParams', async (newName, reason) => {
        const ws = await workspace(FILES);
        const e = await refusal(ws, 'toast/Robot.arc', 'distance;', newName);
        expect(e.code).toBe(ErrorCodes.InvalidParams);
        expect(e.message).toMatch(/is not a valid name/);
        expect(e.message).toMatch(reason);
    });

    test('a keyword of another language that the rename edits is refused, naming that language', async () => {
        // `platform` is an identifier in .arc files but a keyword of .arcapp files, and the
        // application names the component.
        const ws = await workspace(FILES);
        const e = await refusal(ws, 'toast/Robot.arc', 'Robot {', 'platform');
        expect(e.code).toBe(ErrorCodes.InvalidParams);
        expect(e.message).toMatch(/'platform' is a keyword of \.arcapp files/);
    });

    test('keywords of the class diagram language are refused in .cd files', async () => {
        const ws = await workspace(FILES);
        const e = await refusal(ws, 'toast/types/Types.cd', 'ToastColor', 'enum');
        expect(e.message).toMatch(/'enum' is a keyword of \.cd files/);
    });

    test('in RobotArm files: keywords of the language are refused, its soft keywords accepted', async () => {
        const ws = await workspace(FILES);
        const e = await refusal(ws, 'toast/Arm.ra', 'toaster 120deg', 'package');
        expect(e.message).toMatch(/'package' is a keyword of \.ra files/);
        await expect(refusal(ws, 'toast/Arm.ra', 'angle;', '9')).resolves.toMatchObject({ code: ErrorCodes.InvalidParams });
        const renamed = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Arm.ra', 'toaster 120deg', 'open'));
        expect(renamed['toast/Arm.ra']).toContain('location open 120deg 20cm;');
        expect(renamed['toast/Arm.ra']).toContain('move open;');
    });

    test('valid names and soft keywords are accepted', async () => {
        const ws = await workspace(FILES);
        const renamed = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Robot.arc', 'distance;', '$d_2'));
        expect(renamed['toast/Robot.arc']).toContain('port in int $d_2;');
        // `top` is a keyword of the robot arm language that the grammar admits as a name.
        const soft = applyWorkspaceEdit(ws, await renameAt(ws, 'toast/Robot.arc', 'toaster 120deg', 'top'));
        expect(soft['toast/Robot.arc']).toContain('location top 120deg 20cm;');
        expect(soft['toast/Robot.arc']).toContain('move top;');
    });
});

const example = resolve(dirname(fileURLToPath(import.meta.url)), '../../../examples/toast-service');

function modelFiles(dir: string): string[] {
    return readdirSync(dir).flatMap((name) => {
        const path = join(dir, name);
        if (statSync(path).isDirectory()) return modelFiles(path);
        return /\.(arc|cd|ra|arcapp)$/.test(name) ? [path] : [];
    });
}

describe('generator names of the unmodified TR.arcapp', () => {
    // The generators are discovered from the installed packages, as in the editor.
    const setup = (async () => {
        const services = createMaaLspServices(NodeFileSystem);
        services.shared.maa.ModelRoots.setRoots([URI.file(example)]);
        const docs = await Promise.all(
            modelFiles(example).map((f) => services.shared.workspace.LangiumDocuments.getOrCreateDocument(URI.file(f))),
        );
        await services.shared.workspace.DocumentBuilder.build([...builtinDocuments(services.shared), ...docs], { validation: true });
        const app = docs.find((d) => d.uri.path.endsWith('/TR.arcapp'))!;
        return { services, app, arcapp: services.shared.ServiceRegistry.getServices(app.uri) as AdlLspServices };
    })();
    // Line 11 of TR.arcapp: `    timesync.Components;`.
    const at = (app: LangiumDocument, name: string): { line: number; character: number } => positionOf(app, `${name};`, name.length - 2);
    const params = (app: LangiumDocument, name: string) => ({ textDocument: { uri: app.uri.toString() }, position: at(app, name) });

    test('the example links its generator names (the test is about them, not about missing ones)', async () => {
        const { app } = await setup;
        expect(app.textDocument.getText().split('\n')[10]).toBe('    timesync.Components;');
        expect((app.diagnostics ?? []).map((d) => d.message)).toEqual([]);
    });

    test('prepareRename answers null and rename is refused with a reason', async () => {
        const { app, arcapp } = await setup;
        expect(arcapp.lsp.RenameProvider.prepareRename(app, params(app, 'timesync.Components'))).toBeUndefined();
        const refused = arcapp.lsp.RenameProvider.rename(app, { ...params(app, 'timesync.Components'), newName: 'other' });
        await expect(refused).rejects.toBeInstanceOf(ResponseError);
        await expect(refused).rejects.toMatchObject({
            code: LSPErrorCodes.RequestFailed,
            message: expect.stringMatching(/'timesync\.Components' .* cannot be renamed/),
        });
    });

    test('references are the uses of the generator in the documents', async () => {
        const { app, arcapp } = await setup;
        for (const includeDeclaration of [true, false]) {
            const refs = await arcapp.lsp.ReferencesProvider!.findReferences(app, {
                ...params(app, 'timesync.Components'),
                context: { includeDeclaration },
            });
            expect(
                refs.map(
                    (r) => `${relative(example, URI.parse(r.uri).fsPath)}:${r.range.start.line + 1} ${app.textDocument.getText(r.range)}`,
                ),
            ).toEqual(['TR.arcapp:11 timesync.Components']);
        }
        const ros = await arcapp.lsp.ReferencesProvider!.findReferences(app, {
            ...params(app, 'ros2.DataTypes'),
            context: { includeDeclaration: true },
        });
        expect(ros.map((r) => r.range.start.line + 1)).toEqual([8]);
    });

    test('document highlight marks the uses in the document', async () => {
        const { app, arcapp } = await setup;
        const highlights = await arcapp.lsp.DocumentHighlightProvider!.getDocumentHighlight(app, params(app, 'timesync.AutomataBehavior'));
        expect(highlights?.map((h) => app.textDocument.getText(h.range))).toEqual(['timesync.AutomataBehavior']);
    });

    test('component names of the application still rename and find their references', async () => {
        const { app, arcapp } = await setup;
        const component = { textDocument: { uri: app.uri.toString() }, position: positionOf(app, 'ToastServiceRobot {') };
        const refs = await arcapp.lsp.ReferencesProvider!.findReferences(app, { ...component, context: { includeDeclaration: true } });
        expect(refs.map((r) => relative(example, URI.parse(r.uri).fsPath))).toEqual(
            expect.arrayContaining(['TR.arcapp', join('toast', 'ToastServiceRobot.arc')]),
        );
        expect(arcapp.lsp.RenameProvider.prepareRename(app, component)).toBeDefined();
    });
});
