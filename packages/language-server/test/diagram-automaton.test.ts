// The automaton diagram (`maa-automaton`, docs/ide.md): states (nested in their state), initial
// markers, transitions with their `trigger [guard] / action` labels, traces and layout.
import { describe, expect, test } from 'vitest';
import type { SModelElement, SModelRoot } from 'sprotty-protocol';
import { byId, diagramWorkspace, exampleFiles, TestClient, type DiagramWorkspace } from './diagram-helpers.js';

type Element = SModelElement & Record<string, unknown>;

async function automatonModel(ws: DiagramWorkspace, file: string): Promise<SModelRoot> {
    return new TestClient(ws.diagrams).requestModel({ diagramType: 'maa-automaton', sourceUri: ws.uri(file), needsClientLayout: false });
}

function of(model: SModelRoot, type: string): Element[] {
    return [...byId(model).values()].filter((e) => e.type === type);
}

describe('the automaton diagram', () => {
    test('shows the states and transitions of the Controller', async () => {
        const ws = await diagramWorkspace();
        const model = await automatonModel(ws, 'toast/Controller.arc');
        expect(model).toMatchObject({ type: 'graph', id: 'automaton:toast.Controller', component: 'toast.Controller' });
        expect(of(model, 'node:state').map((s) => `${s.id} ${String(s.name)} ${String(s.statePath)} ${String(s.initial)}`)).toEqual([
            'state:Idle Idle Idle true',
            'state:Loading Loading Loading false',
            'state:Toasting Toasting Toasting false',
            'state:Serving Serving Serving false',
        ]);
        expect(of(model, 'edge:transition').map((t) => `${t.id}: ${String(t.label)}`)).toEqual([
            'tr:Idle->Loading: [distance < threshold] / { arm = ArmProgram.LOAD_BREAD; }',
            'tr:Loading->Toasting: [armStatus == ArmStatus.DONE] / { toaster = ToasterCmd.START; }',
            'tr:Toasting->Serving: [color == ToastColor.GOLDEN] / { toaster = ToasterCmd.STOP; arm = ArmProgram.PICKUP_AND_DEPLOY; }',
            'tr:Serving->Idle: [armStatus == ArmStatus.DONE] / { served++; }',
        ]);
        const idle = byId(model).get('tr:Idle->Loading')!;
        expect(idle).toMatchObject({ sourceId: 'state:Idle', targetId: 'state:Loading' });
        // The label shows the text shortened to fit (at most ~260 px), the whole text in `fullText`.
        expect((idle.children ?? [])[0]).toMatchObject({ type: 'label:transition', fullText: idle.label });
        expect(String(((idle.children ?? [])[0] as Element).text)).toMatch(/^\[distance < threshold\] \/ arm = ArmProgram\..*…$/);
        for (const e of [...byId(model).values()].filter((x) => x.type !== 'graph')) expect(e.trace, e.id).toMatch(/Controller\.arc\?\d+/);
        for (const s of of(model, 'node:state')) {
            expect((s.size as { width: number }).width, s.id).toBeGreaterThan(0);
            expect(s.position, s.id).toBeDefined();
        }
        for (const t of of(model, 'edge:transition')) expect((t.routingPoints as unknown[]).length).toBeGreaterThanOrEqual(2);
    });

    test('nests substates, loops internal transitions and numbers parallel transitions', async () => {
        const files = exampleFiles();
        files['toast/Modes.arc'] = `package toast;

component Modes {
  port in int i,
       out int o;

  automaton {
    initial { o = 0; } state Off;
    state On {
      initial state Low;
      state High;
      Low -> High [i > 10];
      -> [i > 100] / { o = 2; };
    };
    Off -> On [i > 0] / o = 1;
    On -> Off [i < 0];
    On -> Off [i == 0];
    Off -> High i;
  }
}
`;
        const ws = await diagramWorkspace(files);
        const model = await automatonModel(ws, 'toast/Modes.arc');
        const all = byId(model);
        expect(of(model, 'node:state').map((s) => `${String(s.statePath)} ${String(s.initial)}`)).toEqual([
            'Off true',
            'On false',
            'On.Low true',
            'On.High false',
        ]);
        const on = all.get('state:On')!;
        expect((on.children ?? []).filter((c) => c.type === 'node:state').map((c) => c.id)).toEqual(['state:On.Low', 'state:On.High']);
        expect(of(model, 'edge:transition').map((t) => `${t.id} ${t.sourceId}->${t.targetId} ${String(t.label)}`)).toEqual([
            'tr:On.Low->On.High state:On.Low->state:On.High [i > 10]',
            'tr:On->On state:On->state:On [i > 100] / { o = 2; }',
            'tr:Off->On state:Off->state:On [i > 0] / o = 1;',
            'tr:On->Off state:On->state:Off [i < 0]',
            'tr:On->Off#1 state:On->state:Off [i == 0]',
            'tr:Off->On.High state:Off->state:On.High i',
        ]);
        // A transition between substates belongs to their state (its route is in that frame).
        expect((on.children ?? []).map((c) => c.id)).toContain('tr:On.Low->On.High');
        // Substates lie inside their state.
        const size = on.size as { width: number; height: number };
        for (const id of ['state:On.Low', 'state:On.High']) {
            const p = all.get(id)!.position as { x: number; y: number };
            expect(p.x).toBeGreaterThanOrEqual(0);
            expect(p.y).toBeGreaterThan(0);
            expect(p.x).toBeLessThan(size.width);
        }
    });

    test('is empty for a component without automaton', async () => {
        const ws = await diagramWorkspace();
        const model = await automatonModel(ws, 'toast/ArmController.arc');
        expect(model).toMatchObject({ type: 'graph', component: 'toast.ArmController', children: [] });
    });
});
