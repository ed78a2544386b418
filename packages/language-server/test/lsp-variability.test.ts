// Editor support for variable architectures: completion and hover of features, rename of a
// feature (and of the feature bindings that name it), formatting of feature declarations,
// constraints and variation points.
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import type { Hover } from 'vscode-languageserver-types';
import { applyWorkspaceEdit, lspServices, workspace } from './lsp-helpers.js';

const LAMP = (body: string): Record<string, string> => ({
    'Lamp.arc': `component Lamp {\n  feature dimmable, eco;\n  port in int level;\n  port out int brightness;\n${body}\n}\n`,
});

describe('features in the editor', () => {
    test('completion in a condition offers the features', async () => {
        const ws = await workspace(LAMP('  constraint(!(dimmable && <|>));'));
        const doc = ws.doc('Lamp.arc');
        const list = await lspServices().Arc.lsp.CompletionProvider!.getCompletion(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('Lamp.arc'),
        });
        expect((list?.items ?? []).map((i) => i.label)).toEqual(expect.arrayContaining(['dimmable', 'eco']));
    });

    test('hover on a feature names it as a feature of its component', async () => {
        const ws = await workspace(LAMP('  varif (dimm<|>able) {\n    compute { brightness = level / 2; }\n  }'));
        const doc = ws.doc('Lamp.arc');
        const hover = (await lspServices().Arc.lsp.HoverProvider!.getHoverContent(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('Lamp.arc'),
        })) as Hover | undefined;
        const text = JSON.stringify(hover?.contents ?? '');
        expect(text).toContain('feature dimmable');
        expect(text).toContain('Feature of component');
    });

    test('rename of a feature renames its uses in constraints and conditions', async () => {
        const ws = await workspace(
            LAMP('  constraint(!dimm<|>able || !eco);\n  varif (dimmable) {\n    compute { brightness = level / 2; }\n  }'),
        );
        const doc = ws.doc('Lamp.arc');
        const edit = await lspServices().Arc.lsp.RenameProvider!.rename(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('Lamp.arc'),
            newName: 'dim',
        });
        const text = applyWorkspaceEdit(ws, edit ?? undefined)['Lamp.arc']!;
        expect(text).toContain('feature dim, eco;');
        expect(text).toContain('constraint(!dim || !eco);');
        expect(text).toContain('varif (dim) {');
    });
});

// A feature binding (`Lamp lamp(dimmable = dim);`) names a feature of the instantiated type (its key)
// and, in its value, features of the enclosing component: renames and references follow both.
const LAMP_ARC = (name: string): string =>
    `package lamps;\n\ncomponent Lamp {\n  feature ${name};\n  port in int level;\n  port out int brightness;\n  varif (${name.replace('<|>', '')}) {\n    compute { brightness = level / 2; }\n  }\n}\n`;
const ROOM_ARC = (key: string, dim = 'dim'): string =>
    `package lamps;\n\ncomponent Room {\n  feature ${dim.replace('<|>', '')}, eco;\n  constraint(!dim || !eco);\n  port in int level;\n  port out int brightness;\n  Lamp lamp(${key} = ${dim});\n  varif (dim) {\n    level -> lamp.level;\n  } else {\n    level -> lamp.level;\n  }\n  lamp.brightness -> brightness;\n}\n`;

async function renameAt(files: Record<string, string>, at: string, newName: string): Promise<Record<string, string>> {
    const ws = await workspace(files);
    const doc = ws.doc(at);
    const edit = await lspServices().Arc.lsp.RenameProvider!.rename(doc, {
        textDocument: { uri: doc.uri.toString() },
        position: ws.position(at),
        newName,
    });
    return applyWorkspaceEdit(ws, edit ?? undefined);
}

describe('feature bindings in the editor', () => {
    test('renaming a feature renames the key of the bindings that name it, in other files', async () => {
        const out = await renameAt(
            { 'lamps/Lamp.arc': LAMP_ARC('dimm<|>able'), 'lamps/Room.arc': ROOM_ARC('dimmable') },
            'lamps/Lamp.arc',
            'adjustable',
        );
        expect(out['lamps/Lamp.arc']).toContain('feature adjustable;');
        expect(out['lamps/Lamp.arc']).toContain('varif (adjustable) {');
        expect(out['lamps/Room.arc']).toContain('Lamp lamp(adjustable = dim);');
        // the enclosing component's own feature is another one
        expect(out['lamps/Room.arc']).toContain('constraint(!dim || !eco);');
    });

    test('renaming at the key of a binding renames the feature of the instantiated type', async () => {
        const out = await renameAt(
            { 'lamps/Lamp.arc': LAMP_ARC('dimmable'), 'lamps/Room.arc': ROOM_ARC('dimm<|>able') },
            'lamps/Room.arc',
            'adjustable',
        );
        expect(out['lamps/Room.arc']).toContain('Lamp lamp(adjustable = dim);');
        expect(out['lamps/Lamp.arc']).toContain('feature adjustable;');
        expect(out['lamps/Lamp.arc']).toContain('varif (adjustable) {');
    });

    test('renaming the enclosing feature renames the value of the binding, the constraint and the varif', async () => {
        const out = await renameAt(
            { 'lamps/Lamp.arc': LAMP_ARC('dimmable'), 'lamps/Room.arc': ROOM_ARC('dimmable', 'd<|>im') },
            'lamps/Room.arc',
            'dimmed',
        );
        const room = out['lamps/Room.arc']!;
        expect(room).toContain('feature dimmed, eco;');
        expect(room).toContain('constraint(!dimmed || !eco);');
        expect(room).toContain('Lamp lamp(dimmable = dimmed);');
        expect(room).toContain('varif (dimmed) {');
        expect(out['lamps/Lamp.arc']).toBeUndefined();
    });

    test('the references of a feature include the bindings that name it', async () => {
        const ws = await workspace({ 'lamps/Lamp.arc': LAMP_ARC('dimm<|>able'), 'lamps/Room.arc': ROOM_ARC('dimmable') });
        const doc = ws.doc('lamps/Lamp.arc');
        const locations = await lspServices().Arc.lsp.ReferencesProvider!.findReferences(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('lamps/Lamp.arc'),
            context: { includeDeclaration: false },
        });
        const room = ws.doc('lamps/Room.arc');
        const found = locations
            .map((l) => `${l.uri === room.uri.toString() ? 'Room' : l.uri === doc.uri.toString() ? 'Lamp' : l.uri}:${l.range.start.line}`)
            .sort();
        // the varif of Lamp (line 6) and the binding key in Room (line 7)
        expect(found).toEqual(['Lamp:6', 'Room:7']);
        const binding = locations.find((l) => l.uri === room.uri.toString())!;
        expect(room.textDocument.getText(binding.range)).toBe('dimmable');
    });
});

describe('formatting variable architectures', () => {
    test('feature lists, constraints and varif/else blocks', async () => {
        await expectFormatting(lspServices().Arc)({
            before: 'component Lamp {\n  feature  dimmable ,eco ;\n  port in int level;\n  port out int brightness;\n  constraint ( !dimmable||eco ) ;\n  varif(dimmable){\n  level -> brightness;\n  }else{ }\n}\n',
            after: 'component Lamp {\n  feature dimmable, eco;\n  port in int level;\n  port out int brightness;\n  constraint(!dimmable || eco);\n  varif (dimmable) {\n    level -> brightness;\n  } else { }\n}\n',
        });
    });
});
