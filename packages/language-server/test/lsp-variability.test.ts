// Editor support for variable architectures: completion and hover of features, rename of a
// feature, formatting of feature declarations, constraints and variation points.
import { describe, expect, test } from 'vitest';
import { expectFormatting } from 'langium/test';
import type { Hover } from 'vscode-languageserver-types';
import { applyWorkspaceEdit, lspServices, workspace } from './lsp-helpers.js';

const LAMP = (body: string): Record<string, string> => ({
    'Lamp.arc': `component Lamp {\n  feature dimmable, eco;\n  port in int level;\n  port out int brightness;\n${body}\n}\n`
});

describe('features in the editor', () => {
    test('completion in a condition offers the features', async () => {
        const ws = await workspace(LAMP('  constraint(!(dimmable && <|>));'));
        const doc = ws.doc('Lamp.arc');
        const list = await lspServices().Arc.lsp.CompletionProvider!.getCompletion(doc, { textDocument: { uri: doc.uri.toString() }, position: ws.position('Lamp.arc') });
        expect((list?.items ?? []).map((i) => i.label)).toEqual(expect.arrayContaining(['dimmable', 'eco']));
    });

    test('hover on a feature names it as a feature of its component', async () => {
        const ws = await workspace(LAMP('  varif (dimm<|>able) {\n    compute { brightness = level / 2; }\n  }'));
        const doc = ws.doc('Lamp.arc');
        const hover = (await lspServices().Arc.lsp.HoverProvider!.getHoverContent(doc, { textDocument: { uri: doc.uri.toString() }, position: ws.position('Lamp.arc') })) as Hover | undefined;
        const text = JSON.stringify(hover?.contents ?? '');
        expect(text).toContain('feature dimmable');
        expect(text).toContain('Feature of component');
    });

    test('rename of a feature renames its uses in constraints and conditions', async () => {
        const ws = await workspace(LAMP('  constraint(!dimm<|>able || !eco);\n  varif (dimmable) {\n    compute { brightness = level / 2; }\n  }'));
        const doc = ws.doc('Lamp.arc');
        const edit = await lspServices().Arc.lsp.RenameProvider!.rename(doc, { textDocument: { uri: doc.uri.toString() }, position: ws.position('Lamp.arc'), newName: 'dim' });
        const text = applyWorkspaceEdit(ws, edit ?? undefined)['Lamp.arc']!;
        expect(text).toContain('feature dim, eco;');
        expect(text).toContain('constraint(!dim || !eco);');
        expect(text).toContain('varif (dim) {');
    });
});

describe('formatting variable architectures', () => {
    test('feature lists, constraints and varif/else blocks', async () => {
        await expectFormatting(lspServices().Arc)({
            before: 'component Lamp {\n  feature  dimmable ,eco ;\n  port in int level;\n  port out int brightness;\n  constraint ( !dimmable||eco ) ;\n  varif(dimmable){\n  level -> brightness;\n  }else{ }\n}\n',
            after: 'component Lamp {\n  feature dimmable, eco;\n  port in int level;\n  port out int brightness;\n  constraint(!dimmable || eco);\n  varif (dimmable) {\n    level -> brightness;\n  } else { }\n}\n'
        });
    });
});
