// The automaton view of a mode automaton (mode-diagram.ts): the modes as states, the initial one
// marked, the mode transitions with `trigger [guard]` labels; the C&C view flags the component.
import { describe, expect, test } from 'vitest';
import type { SModelElement } from 'sprotty-protocol';
import { byId, diagramWorkspace, TestClient } from './diagram-helpers.js';

type Element = SModelElement & Record<string, unknown>;

const PASS = 'component Pass {\n  port in int i;\n  port out int o;\n  <<sync>> compute {\n    o = i;\n  }\n}\n';
const SHIFT = `component Shift {
  port in int i;
  port in boolean flip;
  port out int o;
  mode automaton {
    initial mode Up {
      Pass p;
      i -> p.i;
      p.o -> o;
    }
    mode Down {
      Pass q;
      i -> q.i;
      q.o -> o;
    }
    Up -> Down [flip] flip;
    Down -> Up Tick;
    Down -> Up [i >   0];
  }
}
`;

describe('the automaton view of a mode automaton', () => {
    test('shows the modes as states and the mode transitions with their labels', async () => {
        const ws = await diagramWorkspace({ 'Pass.arc': PASS, 'Shift.arc': SHIFT });
        const client = new TestClient(ws.diagrams);
        const model = await client.requestModel({ diagramType: 'maa-automaton', sourceUri: ws.uri('Shift.arc'), needsClientLayout: false });
        const all = [...byId(model).values()] as Element[];
        // statePath is the mode's name: the IDE highlights the current mode of a run like a state
        expect(all.filter((e) => e.type === 'node:state').map((s) => `${s.id} ${String(s.statePath)} ${String(s.initial)}`)).toEqual([
            'state:Up Up true',
            'state:Down Down false',
        ]);
        expect(all.filter((e) => e.type === 'edge:transition').map((t) => `${t.id}: ${String(t.label)}`)).toEqual([
            'tr:Up->Down: flip [flip]',
            'tr:Down->Up: Tick',
            'tr:Down->Up#1: [i > 0]',
        ]);
        for (const e of all.filter((x) => x.type !== 'graph')) expect(e.trace, e.id).toMatch(/Shift\.arc\?\d+/);
        for (const s of all.filter((x) => x.type === 'node:state')) expect(s.position, s.id).toBeDefined();
    });

    test('the C&C view flags a component with a mode automaton (modeAutomaton), not others', async () => {
        const ws = await diagramWorkspace({ 'Pass.arc': PASS, 'Shift.arc': SHIFT });
        const client = new TestClient(ws.diagrams);
        const shift = await client.requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri('Shift.arc'), needsClientLayout: false });
        expect(byId(shift).get('root')).toMatchObject({ composed: true, modeAutomaton: true });
        expect(byId(shift).get('root.p')?.['modeAutomaton']).toBeUndefined();
        const pass = await client.requestModel({ diagramType: 'maa-automaton', sourceUri: ws.uri('Pass.arc'), needsClientLayout: false });
        expect([...byId(pass).values()].filter((e) => e.type === 'node:state')).toEqual([]);
    });
});
