// Diagram updates after edits (issue 18: keystroke → diagram): the update starts once the build
// has linked every document, before its validation; it never shows a half-linked workspace, keeps
// the markers the diagram had until the validation's update, and an edit that changes nothing
// the diagram shows sends no update.
import { DocumentState } from 'langium';
import { describe, expect, test } from 'vitest';
import type { ActionMessage, SModelRoot } from 'sprotty-protocol';
import { byId, diagramWorkspace, TestClient } from './diagram-helpers.js';

const root = (m: ActionMessage): SModelRoot => (m.action as unknown as { newRoot: SModelRoot }).newRoot;

describe('diagram updates after edits', () => {
    test('are sent only while every document is linked, and keep the markers until the validation', async () => {
        const ws = await diagramWorkspace();
        const documents = ws.family.shared.workspace.LangiumDocuments;
        const linkedAtSend: boolean[] = [];
        ws.diagrams.diagram.DiagramServerManager.onDidSend(() => {
            linkedAtSend.push(documents.all.every((d) => d.state >= DocumentState.IndexedReferences));
        });
        const client = new TestClient(ws.diagrams);
        await client.requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri('toast/ToastServiceRobot.arc'), needsClientLayout: false });

        // An error in the controller: the update after the validation marks it.
        const mark = client.received.length;
        await ws.edit('toast/Controller.arc', (t) => t.replace('ToastColor.GOLDEN', 'ToastColor.GOLD'));
        await client.next(mark, (k, m) => k === 'updateModel' && byId(root(m)).get('root.ctrl')?.severity === 'error');

        // A renamed instance: every update shows it, none loses the controller's marker meanwhile.
        const mark1 = client.received.length;
        await ws.edit('toast/ToastServiceRobot.arc', (t) => t.replace('ArmController arm;', 'ArmController arm2;'));
        await client.next(mark1, (k) => k === 'updateModel');
        const updates = client.received.slice(mark1).filter((m) => m.action.kind === 'updateModel');
        for (const update of updates) {
            const elements = byId(root(update));
            expect(elements.has('root.arm2')).toBe(true);
            expect(elements.has('root.arm')).toBe(false);
            expect(elements.get('root.ctrl')?.severity).toBe('error');
        }
        expect(linkedAtSend.length).toBeGreaterThan(0);
        expect(linkedAtSend.every((linked) => linked)).toBe(true);
    });

    test('an update before the validation is not sent when nothing changed; the one after it is', async () => {
        const ws = await diagramWorkspace();
        const client = new TestClient(ws.diagrams);
        const shown = await client.requestModel({
            diagramType: 'maa-cc',
            sourceUri: ws.uri('toast/ToastServiceRobot.arc'),
            needsClientLayout: false,
        });
        const manager = ws.diagrams.diagram.DiagramServerManager;
        const mark = client.received.length;
        await manager.updateAll(true);
        expect(client.received.length).toBe(mark);
        await manager.updateAll();
        const sent = client.received.slice(mark);
        expect(sent.map((m) => m.action.kind)).toEqual(['updateModel']);
        expect({ ...root(sent[0]!), revision: undefined }).toEqual({ ...shown, revision: undefined });
    });
});
