import { existsSync, mkdtempSync, mkdirSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { NodeFileSystem } from 'langium/node';
import { URI } from 'langium';
import { afterAll, describe, expect, test } from 'vitest';
import { builtinDocuments } from '@maa/language-adl';
import { configureGeneratorRegistry, discoverGenerators } from '@maa/generator-core';
import { createMaaLspServices } from '../src/family.js';

// Generator names in application configurations resolve against the installed generators; the
// editor jumps from a name to the `"name"` entry of the manifest in the generator's package.json.
describe('.arcapp generator names', () => {
    const dir = mkdtempSync(join(tmpdir(), 'maa-arcapp-lsp-'));
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    test('go to definition opens the manifest at the generator name', async () => {
        const manifests = [
            { name: 'demo.Components', kind: 'component', output: { gpl: 'python', rte: 'demo-rte' }, entry: 'c.js' },
            { name: 'demo.DataTypes', kind: 'datatype', output: { gpl: 'python' }, entry: 'd.js' },
        ];
        const pkgDir = join(dir, 'node_modules', 'demo-generators');
        mkdirSync(pkgDir, { recursive: true });
        const pkgJson = JSON.stringify({ name: 'demo-generators', version: '1.0.0', maa: { generators: manifests } }, null, 2);
        writeFileSync(join(pkgDir, 'package.json'), pkgJson);
        writeFileSync(join(dir, 'Robot.arc'), 'component Robot { }\n');
        const appText = 'application App for Robot {\n  platform demo {\n    demo.Components;\n    demo.DataTypes;\n  }\n}\n';
        writeFileSync(join(dir, 'App.arcapp'), appText);

        const services = createMaaLspServices(NodeFileSystem);
        const fsys = {
            existsSync: (u: URI) => existsSync(u.fsPath),
            readFileSync: (u: URI) => readFileSync(u.fsPath, 'utf8'),
            readDirectorySync: (u: URI) => readdirSync(u.fsPath).map((n) => ({ uri: URI.file(join(u.fsPath, n)) })),
        };
        configureGeneratorRegistry(services.shared, discoverGenerators(fsys, URI.file(dir)));
        services.shared.maa.ModelRoots.setRoots([URI.file(dir)]);
        const docs = services.shared.workspace.LangiumDocuments;
        const robot = docs.createDocument(URI.file(join(dir, 'Robot.arc')), 'component Robot { }\n');
        const app = docs.createDocument(URI.file(join(dir, 'App.arcapp')), appText);
        await services.shared.workspace.DocumentBuilder.build([...builtinDocuments(services.shared), robot, app], { validation: true });
        expect((app.diagnostics ?? []).filter((d) => d.severity === 1).map((d) => `${String(d.code)} ${d.message}`)).toEqual([]);

        const arcapp = services.languages.get('arcapp')!;
        const offset = appText.indexOf('demo.DataTypes') + 6;
        const links = await arcapp.lsp.DefinitionProvider.getDefinition(app, {
            textDocument: { uri: app.uri.toString() },
            position: app.textDocument.positionAt(offset),
        });
        expect(links).toHaveLength(1);
        const link = links![0]!;
        expect(URI.parse(link.targetUri).fsPath).toBe(join(pkgDir, 'package.json'));
        const lines = pkgJson.split('\n');
        expect(
            lines[link.targetSelectionRange.start.line]!.substring(
                link.targetSelectionRange.start.character,
                link.targetSelectionRange.end.character,
            ),
        ).toBe('demo.DataTypes');

        // Component names still go to the component's declaration.
        const compLinks = await arcapp.lsp.DefinitionProvider.getDefinition(app, {
            textDocument: { uri: app.uri.toString() },
            position: app.textDocument.positionAt(appText.indexOf('Robot') + 1),
        });
        expect(compLinks?.[0]?.targetUri).toBe(robot.uri.toString());
    });
});
