// Completion through the family's language server services: keywords, the component's ports,
// fields and parameters inside embedded automata (guards, actions, events), states, types and
// components by simple name (with an import where needed), enum constants after `Type.`.
import { describe, expect, test } from 'vitest';
import { expectCompletion } from 'langium/test';
import type { CompletionItem, CompletionList } from 'vscode-languageserver-types';
import { lspServices, TYPES_CD, workspace } from './lsp-helpers.js';

async function complete(files: Record<string, string>, path: string): Promise<CompletionItem[]> {
    const ws = await workspace(files);
    const doc = ws.doc(path);
    const list = await lspServices().Arc.lsp.CompletionProvider.getCompletion(doc, {
        textDocument: { uri: doc.uri.toString() },
        position: ws.position(path),
    });
    return list?.items ?? [];
}

const labels = (items: CompletionItem[]): string[] => items.map((i) => i.label);

function controller(automatonBody: string, extra = ''): Record<string, string> {
    return {
        'toast/types/Types.cd': TYPES_CD,
        'toast/Controller.arc': `package toast;

import toast.types.*;

component Controller(int threshold = 30) {
  port in int distance,
       in ToastColor color,
       out ToasterCmd toaster;
  int cycles = 0;
${extra}
  <<timed>> automaton {
${automatonBody}
  }
}
`,
    };
}

describe('completion inside embedded automata', () => {
    test("a guard offers the component's ports, fields and parameters first", async () => {
        const items = await complete(
            controller('    initial state Idle;\n    Idle -> Idle [<|>] / { cycles++; };'),
            'toast/Controller.arc',
        );
        const names = labels(items);
        for (const n of ['distance', 'color', 'toaster', 'cycles', 'threshold']) expect(names).toContain(n);
        const distance = items.find((i) => i.label === 'distance')!;
        expect(distance.detail).toBe('in int');
        // Component members sort before types and keywords.
        const sorted = [...items].sort((a, b) => (a.sortText ?? '').localeCompare(b.sortText ?? ''));
        expect(
            sorted
                .slice(0, 5)
                .map((i) => i.label)
                .sort(),
        ).toEqual(['color', 'cycles', 'distance', 'threshold', 'toaster']);
    });

    test('a partial name in a guard narrows to the matching port', async () => {
        const items = await complete(
            controller('    initial state Idle;\n    Idle -> Idle [dist<|>] / { cycles++; };'),
            'toast/Controller.arc',
        );
        expect(labels(items)).toContain('distance');
        expect(labels(items)).not.toContain('color');
    });

    test("an action offers the component's ports", async () => {
        const items = await complete(controller('    initial state Idle;\n    Idle -> Idle / { to<|> };'), 'toast/Controller.arc');
        expect(labels(items)).toContain('toaster');
    });

    test('the event of a transition offers incoming ports only (and Tick)', async () => {
        const items = await complete(controller('    initial state Idle;\n    Idle -> Idle <|>;'), 'toast/Controller.arc');
        const names = labels(items);
        expect(names).toContain('distance');
        expect(names).toContain('color');
        expect(names).not.toContain('toaster');
        expect(names).toContain('Tick');
    });

    test("the target of a transition offers the automaton's states, substates included", async () => {
        const items = await complete(
            controller('    initial state Idle;\n    state Busy { initial state Inner; };\n    Idle -> <|>'),
            'toast/Controller.arc',
        );
        expect(labels(items)).toEqual(expect.arrayContaining(['Idle', 'Busy', 'Inner']));
    });

    test('enum constants after `Type.` in a guard and in an action', async () => {
        const guard = await complete(
            controller('    initial state Idle;\n    Idle -> Idle [color == ToastColor.<|>];'),
            'toast/Controller.arc',
        );
        expect(labels(guard)).toEqual(['WHITE', 'GOLDEN', 'BURNT']);
        const action = await complete(
            controller('    initial state Idle;\n    Idle -> Idle / { toaster = ToasterCmd.S<|>; };'),
            'toast/Controller.arc',
        );
        expect(labels(action)).toEqual(expect.arrayContaining(['START', 'STOP']));
    });

    test('keywords of the automaton language where an element may start', async () => {
        const items = await complete(controller('    initial state Idle;\n    <|>'), 'toast/Controller.arc');
        expect(labels(items)).toEqual(expect.arrayContaining(['state', 'initial', 'Idle']));
        // Soft keywords are names elsewhere; they are never offered as names.
        expect(items.filter((i) => i.label === 'Tick')).toEqual([]);
    });
});

describe('completion in the host language', () => {
    test('port types: class-diagram types by simple name, primitive types as keywords', async () => {
        const items = await complete(
            {
                'toast/types/Types.cd': TYPES_CD,
                'toast/A.arc': 'package toast;\n\nimport toast.types.*;\n\ncomponent A {\n  port in <|>\n}\n',
            },
            'toast/A.arc',
        );
        const names = labels(items);
        expect(names).toEqual(expect.arrayContaining(['ToastColor', 'JointTarget', 'int', 'boolean', 'String']));
        expect(names.filter((n) => n.includes('.'))).toEqual([]);
    });

    test('a type from another package is offered with its import', async () => {
        const ws = await workspace({
            'toast/types/Types.cd': TYPES_CD,
            'toast/A.arc': 'package toast;\n\ncomponent A {\n  port in Toa<|>\n}\n',
        });
        const doc = ws.doc('toast/A.arc');
        const list = await lspServices().Arc.lsp.CompletionProvider.getCompletion(doc, {
            textDocument: { uri: doc.uri.toString() },
            position: ws.position('toast/A.arc'),
        });
        const item = list!.items.find((i) => i.label === 'ToastColor')!;
        expect(item.detail).toBe('toast.types.ToastColor (import)');
        expect(item.additionalTextEdits).toEqual([
            {
                range: { start: { line: 0, character: 14 }, end: { line: 0, character: 14 } },
                newText: '\n\nimport toast.types.ToastColor;',
            },
        ]);
    });

    test('subcomponent types offer the components of the model root; connectors the ports of subcomponents', async () => {
        const files = {
            'toast/Sensor.arc': 'package toast;\n\ncomponent Sensor {\n  port out int value;\n}\n',
            'toast/Robot.arc': 'package toast;\n\ncomponent Robot {\n  port out int o;\n  Sen<|>\n}\n',
        };
        expect(labels(await complete(files, 'toast/Robot.arc'))).toContain('Sensor');
        const connector = await complete(
            {
                'toast/Sensor.arc': files['toast/Sensor.arc'],
                'toast/Robot.arc': 'package toast;\n\ncomponent Robot {\n  port out int o;\n  Sensor s;\n  s.<|>\n}\n',
            },
            'toast/Robot.arc',
        );
        expect(labels(connector)).toEqual(['value']);
    });

    test("Langium's expectCompletion helper: keywords at the start of a file", async () => {
        await expectCompletion(lspServices().Arc)({
            text: '<|>',
            index: 0,
            assert: (list: CompletionList) =>
                expect(list.items.map((i) => i.label)).toEqual(expect.arrayContaining(['package', 'import', 'component'])),
            disposeAfterCheck: true,
        });
    });
});
