// The component & connector diagram (docs/ide.md, "Diagram protocol") of the ToastServiceRobot
// example and of a nested fixture, as the IDE's client receives it from the diagram server:
// elements, properties, traces, diagnostics, server-side layout, stable ids and updates.
import { describe, expect, test } from 'vitest';
import type { ActionMessage, SModelElement, SModelRoot } from 'sprotty-protocol';
import { byId, diagramWorkspace, exampleFiles, TestClient, type DiagramWorkspace } from './diagram-helpers.js';

type Element = SModelElement & Record<string, unknown>;

async function ccModel(
    ws: DiagramWorkspace,
    file = 'toast/ToastServiceRobot.arc',
    extra: Record<string, unknown> = {},
): Promise<{ model: SModelRoot; client: TestClient }> {
    const client = new TestClient(ws.diagrams);
    const model = await client.requestModel({ diagramType: 'maa-cc', sourceUri: ws.uri(file), needsClientLayout: false, ...extra });
    return { model, client };
}

function of(model: SModelRoot, type: string): Element[] {
    return [...byId(model).values()].filter((e) => e.type === type);
}

/** In ports are centred on the left border of their node, out ports on the right one. */
function expectPortsOnBorders(model: SModelRoot): void {
    const nodes = of(model, 'node:component');
    expect(nodes.length).toBeGreaterThan(0);
    for (const node of nodes) {
        const size = node.size as { width: number; height: number };
        expect(size.width, node.id).toBeGreaterThan(0);
        for (const port of (node.children ?? []).filter((c) => c.type === 'port') as Element[]) {
            const p = port.position as { x: number; y: number };
            const s = port.size as { width: number; height: number };
            const centre = p.x + s.width / 2;
            if (port.direction === 'in') expect(centre, port.id).toBeCloseTo(0, 0);
            else expect(centre, port.id).toBeCloseTo(size.width, 0);
            expect(p.y, port.id).toBeGreaterThanOrEqual(0);
            expect(p.y + s.height, port.id).toBeLessThanOrEqual(size.height);
        }
    }
}

function child(element: SModelElement, id: string): Element {
    const found = (element.children ?? []).find((c) => c.id === id);
    if (!found) throw new Error(`${element.id} has no child ${id}: ${(element.children ?? []).map((c) => c.id).join(', ')}`);
    return found as Element;
}

describe('the C&C diagram of the ToastServiceRobot', () => {
    test('shows the component, its instances with behavior kinds, their ports and the connectors', async () => {
        const ws = await diagramWorkspace();
        const { model } = await ccModel(ws);
        expect(model).toMatchObject({ type: 'graph', id: 'graph:toast.ToastServiceRobot', component: 'toast.ToastServiceRobot' });
        const root = child(model, 'root');
        expect(root).toMatchObject({
            type: 'node:component',
            name: 'ToastServiceRobot',
            componentType: 'toast.ToastServiceRobot',
            instancePath: '',
            behaviorKind: 'composed',
            composed: true,
            expanded: true,
        });

        const instances = Object.fromEntries(
            (root.children ?? [])
                .filter((c) => c.type === 'node:component')
                .map((c) => {
                    const n = c as Element;
                    return [n.instancePath, `${String(n.componentType)} ${String(n.behaviorKind)}`];
                }),
        );
        expect(instances).toEqual({
            dist: 'toast.DistanceSensor handwritten',
            color: 'toast.ColorSensor handwritten',
            plate: 'toast.PlateLocator handwritten',
            ctrl: 'toast.Controller automaton',
            toasterCtrl: 'toast.ToasterController automaton',
            toaster: 'toast.ToasterActuator handwritten',
            arm: 'toast.ArmController robotarm',
        });

        const ctrl = child(root, 'root.ctrl');
        expect(ctrl).toMatchObject({ name: 'ctrl', composed: false, expanded: false });
        expect(child(ctrl, 'root.ctrl:arm')).toMatchObject({
            type: 'port',
            name: 'arm',
            direction: 'out',
            portType: 'ArmProgram',
            portPath: 'ctrl.arm',
        });
        expect(child(ctrl, 'root.ctrl:distance')).toMatchObject({
            type: 'port',
            direction: 'in',
            portType: 'int',
            portPath: 'ctrl.distance',
        });
        expect(child(ctrl, 'root.ctrl#badge')).toMatchObject({ type: 'label:badge', text: 'automaton' });
        expect(child(child(root, 'root.arm'), 'root.arm#badge')).toMatchObject({ text: 'robotarm' });
        expect((ctrl.children ?? []).filter((c) => c.type === 'port').map((c) => c.id)).toEqual([
            'root.ctrl:distance',
            'root.ctrl:color',
            'root.ctrl:armStatus',
            'root.ctrl:toaster',
            'root.ctrl:arm',
        ]);

        const connectors = of(model, 'edge:connector').map((e) => `${e.sourceId} -> ${e.targetId} (${String(e.sourcePortPath)})`);
        expect(connectors).toEqual([
            'root.dist:value -> root.ctrl:distance (dist.value)',
            'root.color:value -> root.ctrl:color (color.value)',
            'root.ctrl:toaster -> root.toasterCtrl:cmd (ctrl.toaster)',
            'root.toasterCtrl:leverDown -> root.toaster:leverDown (toasterCtrl.leverDown)',
            'root.ctrl:arm -> root.arm:cmd (ctrl.arm)',
            'root.plate:angle -> root.arm:angle (plate.angle)',
            'root.plate:height -> root.arm:height (plate.height)',
            'root.arm:status -> root.ctrl:armStatus (arm.status)',
        ]);
        expect(of(model, 'edge:connector')[0]!.id).toBe('conn:root:dist.value->ctrl.distance');
        // Connectors are children of the component that declares them.
        expect((root.children ?? []).filter((c) => c.type === 'edge:connector')).toHaveLength(8);
    });

    test('traces every node, port, connector and label to its source range', async () => {
        const ws = await diagramWorkspace();
        const { model } = await ccModel(ws);
        const elements = [...byId(model).values()].filter((e) => e.type !== 'graph');
        for (const e of elements) expect(e.trace, e.id).toMatch(/^file:\/\/\/.+\?\d+%3A\d+-\d+%3A\d+#/);
        const trace = (id: string): string => decodeURIComponent(String(byId(model).get(id)!.trace));
        // The instance traces to its declaration, its port to the port in Controller.arc.
        expect(trace('root.ctrl')).toContain(`${ws.uri('toast/ToastServiceRobot.arc')}?14:13-14:21`);
        expect(trace('root.ctrl:arm')).toMatch(new RegExp(`^${ws.uri('toast/Controller.arc')}\\?10:\\d+-10:\\d+#`));
        expect(trace('conn:root:ctrl.arm->arm.cmd')).toContain(`${ws.uri('toast/ToastServiceRobot.arc')}?23:2-23:22#`);
    });

    test('is laid out in the server: in ports on the left border, out ports on the right, edges routed', async () => {
        const ws = await diagramWorkspace();
        const { model } = await ccModel(ws);
        expect(of(model, 'node:component').length).toBe(8);
        expectPortsOnBorders(model);
        // Routes start at their source port, in the frame of the edge's parent (the root node).
        const all = byId(model);
        for (const edge of of(model, 'edge:connector')) {
            const points = edge.routingPoints as Array<{ x: number; y: number }>;
            expect(points.length, edge.id).toBeGreaterThanOrEqual(2);
            const port = all.get(String(edge.sourceId))!;
            const node = all.get(String(edge.sourceId).split(':')[0]!)!;
            const px = (node.position as { x: number }).x + (port.position as { x: number }).x;
            const py = (node.position as { y: number }).y + (port.position as { y: number }).y;
            expect(points[0]!.x, edge.id).toBeGreaterThanOrEqual(px - 1);
            expect(points[0]!.x, edge.id).toBeLessThanOrEqual(px + 11);
            expect(points[0]!.y, edge.id).toBeGreaterThanOrEqual(py - 1);
            expect(points[0]!.y, edge.id).toBeLessThanOrEqual(py + 11);
        }
        // Data flows left to right: the sensors stand left of the controller, the actuator right of it.
        const x = (id: string): number => (byId(model).get(id)!.position as { x: number }).x;
        expect(x('root.dist')).toBeLessThan(x('root.ctrl'));
        expect(x('root.ctrl')).toBeLessThan(x('root.toasterCtrl'));
        expect(x('root.toasterCtrl')).toBeLessThan(x('root.toaster'));
    });

    test('marks the instance of a component with an error, and a port whose declaration has one', async () => {
        const files = exampleFiles();
        files['toast/Controller.arc'] = files['toast/Controller.arc']!.replace('ToastColor.GOLDEN', 'ToastColor.GOLD').replace(
            'in ToastColor color',
            'in ToastColour color',
        );
        const ws = await diagramWorkspace(files);
        const { model } = await ccModel(ws);
        const severities = Object.fromEntries(of(model, 'node:component').map((n) => [n.id, n.severity]));
        expect(severities).toEqual({
            root: undefined,
            'root.dist': undefined,
            'root.color': undefined,
            'root.plate': undefined,
            'root.ctrl': 'error',
            'root.toasterCtrl': undefined,
            'root.toaster': undefined,
            'root.arm': undefined,
        });
        const ports = of(model, 'port')
            .filter((p) => p.severity !== undefined)
            .map((p) => `${p.id} ${String(p.severity)}`);
        expect(ports).toEqual(['root.ctrl:color error']);
    });

    test('keeps the ids of everything but the renamed port and its connector when a port is renamed', async () => {
        const ws = await diagramWorkspace();
        const { model: before } = await ccModel(ws);
        await ws.edit('toast/Controller.arc', (t) =>
            t.replace('in int distance', 'in int range').replace('[distance < threshold]', '[range < threshold]'),
        );
        await ws.edit('toast/ToastServiceRobot.arc', (t) => t.replace('-> ctrl.distance', '-> ctrl.range'));
        const { model: after } = await ccModel(ws);
        const idsBefore = new Set(byId(before).keys());
        const idsAfter = new Set(byId(after).keys());
        const gone = [...idsBefore].filter((id) => !idsAfter.has(id)).sort();
        const added = [...idsAfter].filter((id) => !idsBefore.has(id)).sort();
        expect(gone).toEqual(['conn:root:dist.value->ctrl.distance', 'root.ctrl:distance', 'root.ctrl:distance#name']);
        expect(added).toEqual(['conn:root:dist.value->ctrl.range', 'root.ctrl:range', 'root.ctrl:range#name']);
        expect(byId(after).get('root.ctrl:range')).toMatchObject({ name: 'range', portPath: 'ctrl.range', direction: 'in' });
    });

    test('sends an update after an edit of another file of the shown component, and none while the source does not parse', async () => {
        const ws = await diagramWorkspace();
        const { client } = await ccModel(ws);
        const mark = client.received.length;
        await ws.edit('toast/Controller.arc', (t) => t.replace('ToastColor.GOLDEN', 'ToastColor.GOLD'));
        // The markers come with the update after the build's validation.
        const marks = (id: string) => (k: string, m: ActionMessage) =>
            k === 'updateModel' && byId((m.action as unknown as { newRoot: SModelRoot }).newRoot).get(id)?.severity === 'error';
        const update = await client.next(mark, marks('root.ctrl'));
        const action = update.action as unknown as { newRoot: SModelRoot; animate: boolean };
        expect(action.animate).toBe(true);
        expect(byId(action.newRoot).get('root.ctrl')!.severity).toBe('error');
        expect(byId(action.newRoot).get('root.dist')!.severity).toBeUndefined();

        // A change in another language's file (the class diagram) updates the diagram too.
        const mark1 = client.received.length;
        expect(byId(action.newRoot).get('root.toasterCtrl')!.severity).toBeUndefined();
        await ws.edit('toast/types/Types.cd', (t) => t.replace('enum ToasterCmd { START, STOP; }', 'enum ToasterCmd { BEGIN, STOP; }'));
        const update1 = await client.next(mark1, marks('root.toasterCtrl'));
        expect(byId((update1.action as unknown as { newRoot: SModelRoot }).newRoot).get('root.toasterCtrl')!.severity).toBe('error');

        const mark2 = client.received.length;
        await ws.edit('toast/ToastServiceRobot.arc', (t) => t.replace('ArmController arm;', 'ArmController arm'));
        await new Promise((r) => setTimeout(r, 600));
        expect(client.received.slice(mark2).map((m) => m.action.kind)).toEqual([]);
    });
});

/** Composed subcomponents: sensors behind a composed `Sensing`, a lever behind a composed `Relay`. */
function nestedFiles(): Record<string, string> {
    return {
        ...exampleFiles(),
        'toast/Sensing.arc': `package toast;

import toast.types.*;

component Sensing {
  port out int distance,
       out ToastColor color;

  DistanceSensor dist;
  ColorSensor col;

  dist.value -> distance;
  col.value -> color;
}
`,
        'toast/Relay.arc': `package toast;

import toast.types.*;

component Relay {
  port in ToasterCmd cmd,
       out boolean lever;

  ToasterController tc;

  cmd -> tc.cmd;
  tc.leverDown -> lever;
}
`,
        'toast/Robot2.arc': `package toast;

component Robot2 {
  Sensing sensing;
  PlateLocator plate;
  Controller ctrl;
  Relay relay;
  ToasterActuator act;
  ArmController arm;

  sensing.distance -> ctrl.distance;
  sensing.color -> ctrl.color;
  ctrl.toaster -> relay.cmd;
  relay.lever -> act.leverDown;
  ctrl.arm -> arm.cmd;
  plate.angle -> arm.angle;
  plate.height -> arm.height;
  arm.status -> ctrl.armStatus;
}
`,
    };
}

describe('composed subcomponents in the C&C diagram', () => {
    test('are closed by default; connectors name the atomic out port behind a chain', async () => {
        const ws = await diagramWorkspace(nestedFiles());
        const { model } = await ccModel(ws, 'toast/Robot2.arc');
        const sensing = byId(model).get('root.sensing')!;
        expect(sensing).toMatchObject({ componentType: 'toast.Sensing', behaviorKind: 'composed', composed: true, expanded: false });
        expect((sensing.children ?? []).filter((c) => c.type === 'node:component')).toEqual([]);
        expect((sensing.children ?? []).filter((c) => c.type === 'port').map((c) => c.id)).toEqual([
            'root.sensing:distance',
            'root.sensing:color',
        ]);
        const sources = Object.fromEntries(of(model, 'edge:connector').map((e) => [e.id, e.sourcePortPath]));
        expect(sources).toMatchObject({
            'conn:root:sensing.distance->ctrl.distance': 'sensing.dist.value',
            'conn:root:sensing.color->ctrl.color': 'sensing.col.value',
            'conn:root:ctrl.toaster->relay.cmd': 'ctrl.toaster',
            'conn:root:relay.lever->act.leverDown': 'relay.tc.leverDown',
        });
    });

    test('open when their instance path is in the `expanded` option, with their own instances and connectors', async () => {
        const ws = await diagramWorkspace(nestedFiles());
        const { model } = await ccModel(ws, 'toast/Robot2.arc', { expanded: ['sensing', 'relay'] });
        const relay = byId(model).get('root.relay')!;
        expect(relay).toMatchObject({ composed: true, expanded: true });
        expect(child(relay, 'root.relay.tc')).toMatchObject({
            instancePath: 'relay.tc',
            componentType: 'toast.ToasterController',
            behaviorKind: 'automaton',
        });
        expect(child(child(relay, 'root.relay.tc'), 'root.relay.tc:leverDown')).toMatchObject({ portPath: 'relay.tc.leverDown' });
        const inner = (relay.children ?? [])
            .filter((c) => c.type === 'edge:connector')
            .map((c) => {
                const e = c as Element;
                return `${e.id} ${String(e.sourcePortPath)}`;
            });
        // The relay's in port carries what the controller sends: the chain is followed outwards too.
        expect(inner).toEqual(['conn:root.relay:cmd->tc.cmd ctrl.toaster', 'conn:root.relay:tc.leverDown->lever relay.tc.leverDown']);
        expect(byId(model).get('conn:root.sensing:dist.value->distance')).toMatchObject({
            sourceId: 'root.sensing.dist:value',
            targetId: 'root.sensing:distance',
            sourcePortPath: 'sensing.dist.value',
        });
        expectPortsOnBorders(model);
        // Nested nodes lie inside their parent.
        const size = relay.size as { width: number; height: number };
        const tc = byId(model).get('root.relay.tc')!;
        const p = tc.position as { x: number; y: number };
        const s = tc.size as { width: number; height: number };
        expect(p.x).toBeGreaterThan(0);
        expect(p.x + s.width).toBeLessThan(size.width);
        expect(p.y + s.height).toBeLessThan(size.height);
        // Other ids do not depend on what is open.
        const { model: closed } = await ccModel(ws, 'toast/Robot2.arc');
        for (const id of byId(closed).keys()) expect(byId(model).has(id), id).toBe(true);
    });

    test('can show a component named by the `component` option from another file', async () => {
        const ws = await diagramWorkspace(nestedFiles());
        const { model } = await ccModel(ws, 'TR.arcapp', { component: 'toast.Relay' });
        expect(byId(model).get('root')).toMatchObject({ name: 'Relay', componentType: 'toast.Relay', behaviorKind: 'composed' });
        expect(of(model, 'edge:connector').map((e) => e.sourcePortPath)).toEqual(['', 'tc.leverDown']);
        expect(byId(model).get('root:cmd')).toMatchObject({ direction: 'in', portPath: 'cmd' });
        expectPortsOnBorders(model);
    });
});
