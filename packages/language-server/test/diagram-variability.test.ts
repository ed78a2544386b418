// The C&C diagram of a variable component (MontiArc's `varif`): every variation point is shown,
// its subcomponents, ports and connectors carry the condition under which they exist.
import { describe, expect, test } from 'vitest';
import type { SModelElement } from 'sprotty-protocol';
import { byId, diagramWorkspace, TestClient } from './diagram-helpers.js';

type Element = SModelElement & Record<string, unknown>;

const ROOM = `component Room {
  feature dim, eco;
  port in int level;
  port out int brightness;
  component Doubler {
    port in int i;
    port out int o;
    compute { o = i * 2; }
  }
  varif (dim) {
    Doubler doubler;
    level -> doubler.i;
    doubler.o -> brightness;
  } else varif (eco) {
    port in int limit;
    limit -> brightness;
  } else {
    level -> brightness;
  }
}
`;

describe('variation points in the C&C diagram', () => {
    test('elements of a varif carry its condition (else branches negated); the others none', async () => {
        const ws = await diagramWorkspace({ 'Room.arc': ROOM });
        const client = new TestClient(ws.diagrams);
        const model = await client.requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri('Room.arc'), needsClientLayout: false });
        const elements = [...byId(model).values()] as Element[];
        const doubler = elements.find((e) => e.type === 'node:component' && e.name === 'doubler');
        expect(doubler?.variationPoint).toBe('dim');
        const limit = elements.find((e) => e.type === 'port' && e.name === 'limit');
        expect(limit?.variationPoint).toBe('!(dim) && eco');
        const level = elements.find((e) => e.type === 'port' && e.name === 'level' && e.portPath === 'level');
        expect(level?.variationPoint).toBeUndefined();
        const edges = elements.filter((e) => e.type === 'edge:connector');
        expect(edges.map((e) => e.variationPoint).sort()).toEqual(['!(dim) && !(eco)', '!(dim) && eco', 'dim', 'dim']);
    });
});
