// The C&C diagram of a variable component (MontiArc's `varif`): every variation point is shown,
// its subcomponents, ports and connectors carry the condition under which they exist. Asked for
// one feature configuration (option `features`), it shows only the elements that configuration
// admits.
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

    test('by default every variation point is shown and the graph lists the features', async () => {
        const ws = await diagramWorkspace({ 'Room.arc': ROOM });
        const client = new TestClient(ws.diagrams);
        const model = (await client.requestModel({
            diagramType: 'maa-cc',
            sourceUri: ws.uri('Room.arc'),
            needsClientLayout: false,
        })) as Element;
        expect(model.features).toEqual(['dim', 'eco']);
        expect(model.configuration).toBeUndefined();
        expect(model.configurationRejected).toBeUndefined();
        const elements = [...byId(model).values()] as Element[];
        expect(elements.some((e) => e.type === 'node:component' && e.name === 'doubler')).toBe(true);
        expect(elements.some((e) => e.type === 'port' && e.name === 'limit')).toBe(true);
        expect(elements.filter((e) => e.type === 'edge:connector')).toHaveLength(4);
    });

    test('asked for one configuration, only its elements are laid out', async () => {
        const ws = await diagramWorkspace({ 'Room.arc': ROOM });
        const client = new TestClient(ws.diagrams);
        const base = { diagramType: 'maa-cc', sourceUri: ws.uri('Room.arc'), needsClientLayout: false };
        const eco = (await client.requestModel({ ...base, features: { dim: false, eco: true } })) as Element;
        expect(eco.configuration).toEqual({ dim: false, eco: true });
        let elements = [...byId(eco).values()] as Element[];
        expect(elements.some((e) => e.type === 'node:component' && e.name === 'doubler')).toBe(false);
        expect(elements.some((e) => e.type === 'port' && e.name === 'limit')).toBe(true);
        let edges = elements.filter((e) => e.type === 'edge:connector');
        expect(edges.map((e) => e.variationPoint)).toEqual(['!(dim) && eco']);

        // `dim` wins over `eco` (else varif): eco's value is not asked, the first admitted configuration's is shown.
        const dim = (await client.requestModel({ ...base, features: { dim: true } })) as Element;
        expect(dim.configuration).toEqual({ dim: true, eco: false });
        elements = [...byId(dim).values()] as Element[];
        expect(elements.some((e) => e.type === 'node:component' && e.name === 'doubler')).toBe(true);
        expect(elements.some((e) => e.type === 'port' && e.name === 'limit')).toBe(false);
        edges = elements.filter((e) => e.type === 'edge:connector');
        expect(edges.map((e) => e.variationPoint)).toEqual(['dim', 'dim']);
    });

    test('a configuration the constraints exclude is rejected and every variation point is shown', async () => {
        const text = ROOM.replace('feature dim, eco;', 'feature dim, eco;\n  constraint (!dim || eco);');
        const ws = await diagramWorkspace({ 'Room.arc': text });
        const client = new TestClient(ws.diagrams);
        const base = { diagramType: 'maa-cc', sourceUri: ws.uri('Room.arc'), needsClientLayout: false };
        const rejected = (await client.requestModel({ ...base, features: { dim: true, eco: false } })) as Element;
        expect(rejected.configurationRejected).toBe(true);
        expect(rejected.configuration).toBeUndefined();
        expect(([...byId(rejected).values()] as Element[]).filter((e) => e.type === 'edge:connector')).toHaveLength(4);
        // Only `dim` asked: the constraint makes `eco` true.
        const admitted = (await client.requestModel({ ...base, features: { dim: true } })) as Element;
        expect(admitted.configuration).toEqual({ dim: true, eco: true });
    });

    test("a subcomponent's variation points follow its own feature binding in the shown configuration", async () => {
        const text = `component House {
  feature bright;
  port in int level;
  port out int brightness;
  component Lamp {
    feature dim;
    port in int level;
    port out int brightness;
    varif (dim) {
      port in int limit;
    }
    level -> brightness;
  }
  Lamp lamp(dim = bright);
  level -> lamp.level;
  lamp.brightness -> brightness;
}
`;
        const ws = await diagramWorkspace({ 'House.arc': text });
        const client = new TestClient(ws.diagrams);
        const base = { diagramType: 'maa-cc', sourceUri: ws.uri('House.arc'), needsClientLayout: false };
        const hasLimit = (m: Element): boolean => ([...byId(m).values()] as Element[]).some((e) => e.type === 'port' && e.name === 'limit');
        expect(hasLimit((await client.requestModel(base)) as Element)).toBe(true);
        expect(hasLimit((await client.requestModel({ ...base, features: { bright: true } })) as Element)).toBe(true);
        expect(hasLimit((await client.requestModel({ ...base, features: { bright: false } })) as Element)).toBe(false);
    });
});
