// Quick fixes, keyed by diagnostic code: each test provokes the diagnostic, applies the fix the
// server offers, and checks the edited models and that the diagnostic is gone afterwards.
import { describe, expect, test } from 'vitest';
import type { CodeAction, Diagnostic } from 'vscode-languageserver-types';
import { applyWorkspaceEdit, servicesOf, TYPES_CD, workspace, type Workspace } from './lsp-helpers.js';

function diagnostic(ws: Workspace, path: string, code: string, covering?: string): Diagnostic {
    const doc = ws.doc(path);
    const found = (doc.diagnostics ?? []).filter((d) => d.code === code && (!covering || doc.textDocument.getText(d.range) === covering));
    if (found.length === 0)
        throw new Error(`no ${code} in ${path}: ${JSON.stringify(doc.diagnostics?.map((d) => `${d.code} ${d.message}`))}`);
    return found[0]!;
}

async function fixes(ws: Workspace, path: string, code: string, covering?: string): Promise<CodeAction[]> {
    const doc = ws.doc(path);
    const d = diagnostic(ws, path, code, covering);
    const actions = await servicesOf(doc).lsp.CodeActionProvider!.getCodeActions(doc, {
        textDocument: { uri: doc.uri.toString() },
        range: d.range,
        context: { diagnostics: [d] },
    });
    return (actions ?? []) as CodeAction[];
}

/** Applies a fix and rebuilds the model root with the result (unchanged files as they were). */
async function apply(ws: Workspace, action: CodeAction | undefined): Promise<{ files: Record<string, string>; after: Workspace }> {
    expect(action, 'a quick fix').toBeDefined();
    const changed = applyWorkspaceEdit(ws, action!.edit);
    const files: Record<string, string> = {};
    for (const [path, doc] of ws.docs) files[path] = changed[path] ?? doc.textDocument.getText();
    return { files, after: await workspace(files) };
}

function codes(ws: Workspace, path: string): string[] {
    return (ws.doc(path).diagnostics ?? []).map((d) => String(d.code));
}

describe('quick fixes', () => {
    test('arc/naming-convention: rename to the convention, with all references', async () => {
        const ws = await workspace({
            'toast/Sensor.arc': 'package toast;\n\ncomponent Sensor {\n  port out int Value;\n}\n',
            'toast/Robot.arc': 'package toast;\n\ncomponent Robot {\n  port out int v;\n  Sensor s;\n  s.Value -> v;\n}\n',
        });
        const actions = await fixes(ws, 'toast/Sensor.arc', 'arc/naming-convention');
        expect(actions.map((a) => a.title)).toEqual(["Rename 'Value' to 'value'"]);
        expect(actions[0]!.isPreferred).toBe(true);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Sensor.arc']).toContain('port out int value;');
        expect(files['toast/Robot.arc']).toContain('s.value -> v;');
        expect(codes(after, 'toast/Sensor.arc')).toEqual([]);
        expect(codes(after, 'toast/Robot.arc')).toEqual([]);
    });

    test('arc/missing-port: create the port with the type of the other end (in this component)', async () => {
        const ws = await workspace({
            'toast/types/Types.cd': TYPES_CD,
            'toast/Sensor.arc': 'package toast;\n\nimport toast.types.*;\n\ncomponent Sensor {\n  port out ToastColor value;\n}\n',
            'toast/Robot.arc': 'package toast;\n\ncomponent Robot {\n  port in int unused;\n  Sensor s;\n  s.value -> shade;\n}\n',
        });
        const actions = await fixes(ws, 'toast/Robot.arc', 'arc/missing-port', 'shade');
        expect(actions.map((a) => a.title)).toEqual(["Create outgoing port 'shade' in 'Robot'"]);
        const { files, after } = await apply(ws, actions[0]);
        // The type is qualified: Robot.arc does not import the class diagram.
        expect(files['toast/Robot.arc']).toBe(
            'package toast;\n\ncomponent Robot {\n  port in int unused;\n  port out toast.types.ToastColor shade;\n  Sensor s;\n  s.value -> shade;\n}\n',
        );
        expect(codes(after, 'toast/Robot.arc')).not.toContain('arc/missing-port');
    });

    test("arc/missing-port: create the port in the subcomponent's type, in its own file", async () => {
        const ws = await workspace({
            'toast/Sensor.arc': 'package toast;\n\ncomponent Sensor {\n}\n',
            'toast/Robot.arc': 'package toast;\n\ncomponent Robot {\n  port in double level;\n  Sensor s;\n  level -> s.calibration;\n}\n',
        });
        const actions = await fixes(ws, 'toast/Robot.arc', 'arc/missing-port', 'calibration');
        expect(actions.map((a) => a.title)).toEqual(["Create incoming port 'calibration' in 'Sensor'"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Sensor.arc']).toBe('package toast;\n\ncomponent Sensor {\n  port in double calibration;\n}\n');
        expect(codes(after, 'toast/Robot.arc')).toEqual([]);
    });

    test('arc/file-name-mismatch: rename the component (with its uses) or the file', async () => {
        const ws = await workspace({
            'toast/Sensor.arc': 'package toast;\n\ncomponent Sensr {\n  port out int value;\n}\n',
            'toast/Robot.arc': 'package toast;\n\ncomponent Robot {\n  port out int v;\n  Sensr s;\n  s.value -> v;\n}\n',
        });
        const actions = await fixes(ws, 'toast/Sensor.arc', 'arc/file-name-mismatch');
        expect(actions.map((a) => a.title)).toEqual(["Rename 'Sensr' to 'Sensor'", "Rename file to 'Sensr.arc'"]);
        expect(actions[1]!.edit!.documentChanges).toEqual([
            {
                kind: 'rename',
                oldUri: ws.doc('toast/Sensor.arc').uri.toString(),
                newUri: ws.doc('toast/Sensor.arc').uri.toString().replace('Sensor.arc', 'Sensr.arc'),
            },
        ]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/Sensor.arc']).toContain('component Sensor {');
        expect(files['toast/Robot.arc']).toContain('  Sensor s;');
        expect(codes(after, 'toast/Sensor.arc')).toEqual([]);
        expect(codes(after, 'toast/Robot.arc')).toEqual([]);
    });

    test('arc/package-mismatch: fix, add or remove the package declaration', async () => {
        const ws = await workspace({
            'toast/A.arc': 'package tost;\n\ncomponent A {\n}\n',
            'toast/B.arc': 'component B {\n}\n',
            'C.arc': 'package toast;\n\ncomponent C {\n}\n',
        });
        const fixA = await fixes(ws, 'toast/A.arc', 'arc/package-mismatch');
        expect(fixA.map((a) => a.title)).toEqual(["Change package to 'toast'"]);
        const fixB = await fixes(ws, 'toast/B.arc', 'arc/package-mismatch');
        expect(fixB.map((a) => a.title)).toEqual(["Add 'package toast;'"]);
        const fixC = await fixes(ws, 'C.arc', 'arc/package-mismatch');
        expect(fixC.map((a) => a.title)).toEqual(['Remove the package declaration (default package)']);
        const a = await apply(ws, fixA[0]);
        expect(a.files['toast/A.arc']).toBe('package toast;\n\ncomponent A {\n}\n');
        const b = await apply(ws, fixB[0]);
        expect(b.files['toast/B.arc']).toBe('package toast;\n\ncomponent B {\n}\n');
        const c = await apply(ws, fixC[0]);
        expect(c.files['C.arc']).toBe('component C {\n}\n');
        for (const [r, p] of [
            [a, 'toast/A.arc'],
            [b, 'toast/B.arc'],
            [c, 'C.arc'],
        ] as const)
            expect(codes(r.after, p)).toEqual([]);
    });

    test('arc/unused-in-port and arc/unconnected-sub-in-port: connect the ports', async () => {
        const ws = await workspace({
            'toast/Sensor.arc': 'package toast;\n\ncomponent Sensor {\n  port in int distance;\n  port out int value;\n}\n',
            'toast/Robot.arc':
                'package toast;\n\ncomponent Robot {\n  port in int distance;\n  port out int v;\n  Sensor s;\n  s.value -> v;\n}\n',
        });
        const unused = await fixes(ws, 'toast/Robot.arc', 'arc/unused-in-port');
        expect(unused.map((a) => a.title)).toEqual(["Connect 'distance' to 's.distance'"]);
        const unconnected = await fixes(ws, 'toast/Robot.arc', 'arc/unconnected-sub-in-port');
        expect(unconnected.map((a) => a.title)).toEqual(["Connect 'distance' to 's.distance'"]);
        const { files, after } = await apply(ws, unused[0]);
        expect(files['toast/Robot.arc']).toBe(
            'package toast;\n\ncomponent Robot {\n  port in int distance;\n  port out int v;\n  Sensor s;\n  s.value -> v;\n  distance -> s.distance;\n}\n',
        );
        expect(codes(after, 'toast/Robot.arc')).toEqual([]);
    });

    test('arc/unconnected-sub-in-port: create an incoming port for it, or connect another subcomponent', async () => {
        const ws = await workspace({
            'toast/Sensor.arc': 'package toast;\n\ncomponent Sensor {\n  port in int distance;\n  port out int value;\n}\n',
            'toast/Source.arc': 'package toast;\n\ncomponent Source {\n  port out int level;\n}\n',
            'toast/Robot.arc': 'package toast;\n\ncomponent Robot {\n  port out int v;\n  Sensor s;\n  Source src;\n  s.value -> v;\n}\n',
        });
        const actions = await fixes(ws, 'toast/Robot.arc', 'arc/unconnected-sub-in-port', 's');
        expect(actions.map((a) => a.title)).toEqual([
            "Connect 'src.level' to 's.distance'",
            "Create incoming port 'distance' and connect it to 's.distance'",
        ]);
        const { files, after } = await apply(ws, actions[1]);
        expect(files['toast/Robot.arc']).toBe(
            'package toast;\n\ncomponent Robot {\n  port out int v;\n  port in int distance;\n  Sensor s;\n  Source src;\n  s.value -> v;\n  distance -> s.distance;\n}\n',
        );
        expect(codes(after, 'toast/Robot.arc')).toEqual(['arc/unconnected-sub-out-port']);
    });

    test('arc/unresolved-type: import the type', async () => {
        const ws = await workspace({
            'toast/types/Types.cd': TYPES_CD,
            'toast/A.arc': 'package toast;\n\ncomponent A {\n  port in ToastColor c;\n}\n',
        });
        const actions = await fixes(ws, 'toast/A.arc', 'arc/unresolved-type');
        expect(actions.map((a) => a.title)).toEqual(["Import 'toast.types.ToastColor'"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/A.arc']).toBe(
            'package toast;\n\nimport toast.types.ToastColor;\n\ncomponent A {\n  port in ToastColor c;\n}\n',
        );
        expect(codes(after, 'toast/A.arc')).toEqual([]);
    });

    test('automaton/missing-state: create the state at the level of the transition', async () => {
        const ws = await workspace({
            'toast/A.arc':
                'package toast;\n\ncomponent A {\n  port in int i;\n  automaton {\n    initial state Idle;\n    state Busy {\n      initial state Warm;\n      Warm -> Hot;\n    };\n    Idle -> Busy;\n    Busy -> Done;\n  }\n}\n',
        });
        const done = await fixes(ws, 'toast/A.arc', 'automaton/missing-state', 'Done');
        expect(done.map((a) => a.title)).toEqual(["Create state 'Done'"]);
        const top = await apply(ws, done[0]);
        expect(top.files['toast/A.arc']).toContain(
            '    state Busy {\n      initial state Warm;\n      Warm -> Hot;\n    };\n    state Done;\n    Idle -> Busy;',
        );
        const hot = await fixes(ws, 'toast/A.arc', 'automaton/missing-state', 'Hot');
        const inner = await apply(ws, hot[0]);
        expect(inner.files['toast/A.arc']).toContain('      initial state Warm;\n      state Hot;\n      Warm -> Hot;');
        // `Done` is still missing after fixing `Hot` only.
        expect(codes(inner.after, 'toast/A.arc').filter((c) => c === 'automaton/missing-state')).toHaveLength(1);
        expect(codes(top.after, 'toast/A.arc').filter((c) => c === 'automaton/missing-state')).toHaveLength(1);
    });

    test('automaton/no-initial-state: mark a state initial', async () => {
        const ws = await workspace({
            'toast/A.arc': 'package toast;\n\ncomponent A {\n  automaton {\n    state Idle;\n    state Busy;\n  }\n}\n',
        });
        const actions = await fixes(ws, 'toast/A.arc', 'automaton/no-initial-state');
        expect(actions.map((a) => a.title)).toEqual(["Make 'Idle' the initial state", "Make 'Busy' the initial state"]);
        const { files, after } = await apply(ws, actions[0]);
        expect(files['toast/A.arc']).toContain('    initial state Idle;\n    state Busy;');
        expect(codes(after, 'toast/A.arc')).toEqual([]);
    });

    test('the provider answers only quick-fix requests and lists the codes it can fix', async () => {
        const ws = await workspace({ 'toast/A.arc': 'package toast;\n\ncomponent a {\n}\n' });
        const doc = ws.doc('toast/A.arc');
        const d = diagnostic(ws, 'toast/A.arc', 'arc/naming-convention');
        const provider = servicesOf(doc).lsp.CodeActionProvider!;
        const refactorOnly = await provider.getCodeActions(doc, {
            textDocument: { uri: doc.uri.toString() },
            range: d.range,
            context: { diagnostics: [d], only: ['refactor'] },
        });
        expect(refactorOnly).toEqual([]);
        expect(provider.codes()).toEqual(
            expect.arrayContaining([
                'arc/naming-convention',
                'arc/missing-port',
                'arc/file-name-mismatch',
                'arc/package-mismatch',
                'arc/unused-in-port',
                'arc/unconnected-sub-in-port',
                'automaton/missing-state',
                'automaton/no-initial-state',
            ]),
        );
    });
});
