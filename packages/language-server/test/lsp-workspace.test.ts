// Model roots in the editor come from the workspace: every workspace folder is a root, and so is
// every folder below one that holds a `maa.json`; packages, scopes and reserved names follow.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { URI, type LangiumDocument } from 'langium';
import { NodeFileSystem } from 'langium/node';
import { afterAll, describe, expect, test, vi } from 'vitest';
import { FileChangeType } from 'vscode-languageserver-protocol';
import { createMaaLspServices } from '../src/family.js';

const tmp = mkdtempSync(join(tmpdir(), 'maa-lsp-ws-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

function write(path: string, text: string): string {
    const file = join(tmp, path);
    mkdirSync(dirname(file), { recursive: true });
    writeFileSync(file, text);
    return file;
}

describe('model roots from the workspace', () => {
    test('workspace folders and folders with a maa.json are roots; maa.json changes are picked up', async () => {
        // Workspace folder `repo`: two projects with a maa.json each, plus loose models.
        write('repo/projects/one/maa.json', '{}\n');
        write('repo/projects/one/toast/Sensor.arc', 'package toast;\n\ncomponent Sensor {\n  port out int value;\n}\n');
        write(
            'repo/projects/one/toast/Robot.arc',
            'package toast;\n\ncomponent Robot {\n  port out int v;\n  Sensor s;\n  Heater h;\n  s.value -> v;\n}\n',
        );
        write('repo/projects/two/maa.json', '{ "reservedNames": { "port": ["speed"] } }\n');
        write('repo/projects/two/toast/Heater.arc', 'package toast;\n\ncomponent Heater {\n  port in int speed;\n}\n');
        write('repo/misc/Loose.arc', 'package misc;\n\ncomponent Loose {\n}\n');
        // A second workspace folder.
        write('other/plant/Plant.arc', 'package plant;\n\ncomponent Plant {\n}\n');

        const s = createMaaLspServices(NodeFileSystem);
        const folders = [
            { name: 'repo', uri: URI.file(join(tmp, 'repo')).toString() },
            { name: 'other', uri: URI.file(join(tmp, 'other')).toString() },
        ];
        const manager = s.shared.workspace.WorkspaceManager;
        manager.initialize({ processId: null, rootUri: null, capabilities: {}, workspaceFolders: folders });
        await manager.initialized({});

        const roots = s.shared.maa.ModelRoots.all()
            .map((r) => r.substring(URI.file(tmp).toString().length))
            .sort();
        expect(roots).toEqual(['/other/', '/repo/', '/repo/projects/one/', '/repo/projects/two/']);

        const doc = (path: string): LangiumDocument => s.shared.workspace.LangiumDocuments.getDocument(URI.file(join(tmp, path)))!;
        const codes = (path: string): string[] => (doc(path).diagnostics ?? []).map((d) => String(d.code)).sort();
        // Every file was loaded and validated at start-up, also without being opened.
        expect(codes('repo/projects/one/toast/Sensor.arc')).toEqual([]);
        expect(codes('repo/misc/Loose.arc')).toEqual([]);
        expect(codes('other/plant/Plant.arc')).toEqual([]);
        // Roots are separate scopes: Heater lives in the other project.
        expect(codes('repo/projects/one/toast/Robot.arc')).toEqual(['arc/missing-component-type']);
        // The project's maa.json reserves `speed` for ports.
        expect(codes('repo/projects/two/toast/Heater.arc')).toEqual(['arc/reserved-name']);

        // The maa.json changes: the server finds the roots again and rebuilds.
        write('repo/projects/two/maa.json', '{}\n');
        s.shared.lsp.DocumentUpdateHandler.didChangeWatchedFiles({
            changes: [{ uri: URI.file(join(tmp, 'repo/projects/two/maa.json')).toString(), type: FileChangeType.Changed }],
        });
        await vi.waitFor(() => expect(codes('repo/projects/two/toast/Heater.arc')).toEqual([]), { timeout: 10_000 });

        // A project loses its maa.json: its files now belong to the workspace folder's root.
        rmSync(join(tmp, 'repo/projects/one/maa.json'));
        s.shared.lsp.DocumentUpdateHandler.didChangeWatchedFiles({
            changes: [{ uri: URI.file(join(tmp, 'repo/projects/one/maa.json')).toString(), type: FileChangeType.Deleted }],
        });
        await vi.waitFor(() => expect(codes('repo/projects/one/toast/Sensor.arc')).toEqual(['arc/package-mismatch']), { timeout: 10_000 });
        expect(s.shared.maa.ModelRoots.rootOf(URI.file(join(tmp, 'repo/projects/one/toast/Sensor.arc')))).toBe(
            `${URI.file(join(tmp, 'repo')).toString()}/`,
        );
    });
});
