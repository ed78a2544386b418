// Geometry of the laid-out diagrams (docs/ide.md, "Diagram protocol": the client shows the
// server's layout as it is): no overlapping nodes or labels, transition labels clear of the
// states, a compact C&C view of the example, ports on their borders, and a layout that stays
// put when a guard or a port name is edited.
import { describe, expect, test } from 'vitest';
import type { SModelElement, SModelRoot } from 'sprotty-protocol';
import { shortenTransitionLabel, textSize, FONTS, MAX_TRANSITION_LABEL_WIDTH } from '../src/diagram/sizes.js';
import { EXPAND_TOGGLE_ROOM } from '../src/diagram/layout.js';
import { byId, diagramWorkspace, exampleFiles, TestClient, type DiagramWorkspace } from './diagram-helpers.js';

type Element = SModelElement & Record<string, unknown>;
interface Box {
    x: number;
    y: number;
    width: number;
    height: number;
}
interface Point {
    x: number;
    y: number;
}

/** The C&C view of the example is at most this wide (it was about 2200 px before). */
const CC_MAX_WIDTH = 1000;

async function model(ws: DiagramWorkspace, diagramType: string, file: string, extra: Record<string, unknown> = {}): Promise<SModelRoot> {
    return new TestClient(ws.diagrams).requestModel({ diagramType, sourceUri: ws.uri(file), needsClientLayout: false, ...extra });
}

/**
 * Absolute boxes of every element with a position and size, and absolute routes of edges:
 * a node's children are relative to the node, an edge's routing points and labels relative
 * to the edge's parent.
 */
function geometry(root: SModelRoot): { boxes: Map<string, Box>; routes: Map<string, Point[]>; parents: Map<string, string> } {
    const boxes = new Map<string, Box>();
    const routes = new Map<string, Point[]>();
    const parents = new Map<string, string>();
    const walk = (e: Element, origin: Point): void => {
        const isEdge = String(e.type).startsWith('edge');
        const p = e.position as Point | undefined;
        const s = e.size as { width: number; height: number } | undefined;
        const here = p ? { x: origin.x + p.x, y: origin.y + p.y } : origin;
        if (p && s) boxes.set(e.id, { ...here, width: s.width, height: s.height });
        if (isEdge)
            routes.set(
                e.id,
                ((e.routingPoints ?? []) as Point[]).map((q) => ({ x: origin.x + q.x, y: origin.y + q.y })),
            );
        for (const c of (e.children ?? []) as Element[]) {
            parents.set(c.id, e.id);
            walk(c, isEdge ? origin : here);
        }
    };
    walk(root as Element, { x: 0, y: 0 });
    return { boxes, routes, parents };
}

/** Whether two boxes overlap by more than `tolerance` pixels in both directions. */
function overlap(a: Box, b: Box, tolerance = 0.5): boolean {
    return (
        a.x + a.width - tolerance > b.x &&
        b.x + b.width - tolerance > a.x &&
        a.y + a.height - tolerance > b.y &&
        b.y + b.height - tolerance > a.y
    );
}

/** Whether a segment passes through the inside of a box (shrunk by `inset`). */
function crosses(a: Point, b: Point, box: Box, inset = 1): boolean {
    const x0 = box.x + inset,
        x1 = box.x + box.width - inset,
        y0 = box.y + inset,
        y1 = box.y + box.height - inset;
    if (x1 <= x0 || y1 <= y0) return false;
    // Liang–Barsky clipping of the segment against the box.
    let t0 = 0,
        t1 = 1;
    const dx = b.x - a.x,
        dy = b.y - a.y;
    for (const [p, q] of [
        [-dx, a.x - x0],
        [dx, x1 - a.x],
        [-dy, a.y - y0],
        [dy, y1 - a.y],
    ] as const) {
        if (p === 0) {
            if (q < 0) return false;
            continue;
        }
        const r = q / p;
        if (p < 0) t0 = Math.max(t0, r);
        else t1 = Math.min(t1, r);
        if (t0 > t1) return false;
    }
    return true;
}

function nodesOf(root: SModelRoot, type: string): Element[] {
    return [...byId(root).values()].filter((e) => e.type === type);
}

/** Pairs of sibling nodes whose boxes overlap. */
function siblingOverlaps(root: SModelRoot): string[] {
    const found: string[] = [];
    for (const parent of byId(root).values()) {
        const nodes = ((parent.children ?? []) as Element[]).filter((c) => String(c.type).startsWith('node'));
        for (let i = 0; i < nodes.length; i++) {
            for (let j = i + 1; j < nodes.length; j++) {
                const a = nodes[i]!,
                    b = nodes[j]!;
                const ba = { ...(a.position as Point), ...(a.size as { width: number; height: number }) };
                const bb = { ...(b.position as Point), ...(b.size as { width: number; height: number }) };
                if (overlap(ba, bb)) found.push(`${a.id} / ${b.id}`);
            }
        }
    }
    return found;
}

/** Whether `ancestor` contains `id` in the model tree. */
function isAncestor(parents: Map<string, string>, ancestor: string, id: string): boolean {
    for (let p = parents.get(id); p; p = parents.get(p)) if (p === ancestor) return true;
    return false;
}

/** Problems of an automaton layout: labels over states or over each other, edges through the initial marker. */
function automatonProblems(root: SModelRoot): string[] {
    const { boxes, routes, parents } = geometry(root);
    const states = nodesOf(root, 'node:state');
    const labels = nodesOf(root, 'label:transition');
    const problems: string[] = [];
    for (const label of labels) {
        const box = boxes.get(label.id);
        if (!box) {
            problems.push(`${label.id} has no box`);
            continue;
        }
        for (const state of states) {
            // A label of a transition inside a state lies within that state's box, rightly.
            if (isAncestor(parents, state.id, label.id)) continue;
            if (overlap(box, boxes.get(state.id)!)) problems.push(`${label.id} overlaps ${state.id}`);
        }
        for (const other of labels)
            if (other.id < label.id && overlap(box, boxes.get(other.id)!)) problems.push(`${label.id} overlaps ${other.id}`);
        // Labels do not lie across other transitions' routes.
        for (const [edge, route] of routes) {
            if (edge === parents.get(label.id)) continue;
            for (let i = 1; i < route.length; i++) if (crosses(route[i - 1]!, route[i]!, box)) problems.push(`${edge} crosses ${label.id}`);
        }
    }
    // The client draws the initial marker at x -20..0, y 10..18 of an initial state.
    for (const state of states.filter((s) => s.initial)) {
        const b = boxes.get(state.id)!;
        const marker = { x: b.x - 22, y: b.y + 8, width: 22, height: 12 };
        for (const other of states)
            if (other.id !== state.id && !isAncestor(parents, other.id, state.id) && overlap(marker, boxes.get(other.id)!))
                problems.push(`the marker of ${state.id} overlaps ${other.id}`);
        for (const label of labels)
            if (overlap(marker, boxes.get(label.id)!)) problems.push(`the marker of ${state.id} overlaps ${label.id}`);
        for (const [edge, route] of routes) {
            for (let i = 1; i < route.length; i++)
                if (crosses(route[i - 1]!, route[i]!, marker, 0.5)) problems.push(`${edge} crosses the marker of ${state.id}`);
        }
    }
    return problems;
}

/** Problems of a C&C layout: ports off their borders, labels outside their node or over each other, connectors through nodes. */
function componentProblems(root: SModelRoot): string[] {
    const { boxes, routes } = geometry(root);
    const all = byId(root);
    const problems: string[] = [];
    for (const node of nodesOf(root, 'node:component')) {
        const size = node.size as { width: number; height: number };
        const box = boxes.get(node.id)!;
        const texts: Array<{ id: string; box: Box }> = [];
        for (const c of (node.children ?? []) as Element[]) {
            if (String(c.type).startsWith('label')) texts.push({ id: c.id, box: boxes.get(c.id)! });
            if (c.type !== 'port') continue;
            const p = c.position as Point;
            const s = c.size as { width: number; height: number };
            const centre = p.x + s.width / 2;
            const border = c.direction === 'in' ? 0 : size.width;
            if (Math.abs(centre - border) > 0.5)
                problems.push(`${c.id} (${String(c.direction)}) is off its border: ${centre} vs ${border}`);
            if (p.y < 0 || p.y + s.height > size.height) problems.push(`${c.id} is above or below its node`);
            for (const l of (c.children ?? []) as Element[]) texts.push({ id: l.id, box: boxes.get(l.id)! });
        }
        for (const t of texts) {
            const inside =
                t.box.x >= box.x &&
                t.box.y >= box.y &&
                t.box.x + t.box.width <= box.x + box.width &&
                t.box.y + t.box.height <= box.y + box.height;
            if (!inside) problems.push(`${t.id} sticks out of ${node.id}`);
            for (const u of texts) if (u.id < t.id && overlap(t.box, u.box)) problems.push(`${t.id} overlaps ${u.id}`);
            // Labels of a node are not covered by its children.
            for (const c of ((node.children ?? []) as Element[]).filter((x) => x.type === 'node:component')) {
                if (overlap(t.box, boxes.get(c.id)!)) problems.push(`${t.id} is covered by ${c.id}`);
            }
        }
    }
    // A connector passes through no node but those of its ends (and their ancestors).
    for (const edge of nodesOf(root, 'edge:connector')) {
        const route = routes.get(edge.id)!;
        const ends = new Set<string>();
        for (const end of [String(edge.sourceId), String(edge.targetId)]) {
            const nodeId = end.split(':')[0]!;
            for (let id = nodeId; ; id = id.slice(0, id.lastIndexOf('.'))) {
                ends.add(id);
                if (!id.includes('.')) break;
            }
        }
        for (const node of nodesOf(root, 'node:component')) {
            if (ends.has(node.id)) continue;
            for (let i = 1; i < route.length; i++)
                if (crosses(route[i - 1]!, route[i]!, boxes.get(node.id)!)) problems.push(`${edge.id} crosses ${node.id}`);
        }
        // Nor through a label.
        for (const label of [...all.values()].filter((e) => String(e.type).startsWith('label'))) {
            for (let i = 1; i < route.length; i++)
                if (crosses(route[i - 1]!, route[i]!, boxes.get(label.id)!)) problems.push(`${edge.id} crosses ${label.id}`);
        }
        if (!all.has(String(edge.sourceId))) problems.push(`${edge.id} has no source`);
    }
    return problems;
}

function positions(root: SModelRoot, type: string): Map<string, Point> {
    const { boxes } = geometry(root);
    return new Map(nodesOf(root, type).map((n) => [n.id, boxes.get(n.id)!]));
}

function moved(before: Map<string, Point>, after: Map<string, Point>, except: readonly string[] = []): string[] {
    const out: string[] = [];
    for (const [id, p] of before) {
        if (except.includes(id)) continue;
        const q = after.get(id);
        if (!q || Math.abs(p.x - q.x) > 3 || Math.abs(p.y - q.y) > 3) out.push(`${id}: (${p.x},${p.y}) -> (${q?.x},${q?.y})`);
    }
    return out;
}

describe('the automaton layout', () => {
    for (const [name, file] of [
        ['toast.Controller', 'toast/Controller.arc'],
        ['toast.ToasterController', 'toast/ToasterController.arc'],
    ] as const) {
        test(`of ${name}: no overlapping states, no transition label over a state, a label or a route, room for the initial marker`, async () => {
            const ws = await diagramWorkspace();
            const m = await model(ws, 'maa-automaton', file);
            expect(nodesOf(m, 'node:state').length).toBeGreaterThan(1);
            expect(siblingOverlaps(m)).toEqual([]);
            expect(automatonProblems(m)).toEqual([]);
            // Every transition has its label, at most MAX_TRANSITION_LABEL_WIDTH wide.
            for (const t of nodesOf(m, 'edge:transition')) {
                const label = (t.children as Element[]).find((c) => c.type === 'label:transition')!;
                expect((label.size as { width: number }).width, t.id).toBeLessThanOrEqual(MAX_TRANSITION_LABEL_WIDTH);
                expect(label.position, t.id).toBeDefined();
            }
        });
    }

    test('reads from the top: the initial state of the Controller first, then the states in the order of its cycle', async () => {
        const ws = await diagramWorkspace();
        const m = await model(ws, 'maa-automaton', 'toast/Controller.arc');
        const p = positions(m, 'node:state');
        const y = (id: string): number => p.get(id)!.y;
        expect(y('state:Idle')).toBeLessThan(y('state:Loading'));
        expect(y('state:Loading')).toBeLessThan(y('state:Toasting'));
        expect(y('state:Toasting')).toBeLessThan(y('state:Serving'));
        // Not one long row: the diagram is taller than wide is not required, but it is not a strip.
        const { boxes } = geometry(m);
        const right = Math.max(...[...boxes.values()].map((b) => b.x + b.width));
        expect(right).toBeLessThan(800);
    });

    test('shortens long transition labels, keeping their whole text in the edge and the label', async () => {
        const ws = await diagramWorkspace();
        const m = await model(ws, 'maa-automaton', 'toast/Controller.arc');
        const edge = byId(m).get('tr:Toasting->Serving')!;
        const label = byId(m).get('tr:Toasting->Serving#label')!;
        expect(edge.label).toBe('[color == ToastColor.GOLDEN] / { toaster = ToasterCmd.STOP; arm = ArmProgram.PICKUP_AND_DEPLOY; }');
        expect(label.fullText).toBe(edge.label);
        expect(String(label.text)).toMatch(/^\[color == ToastColor\.GOLDEN\] \/ toaster =.*…$/);
        // A block action that then fits loses just its braces.
        const served = byId(m).get('tr:Serving->Idle#label')!;
        expect(served.text).toBe('[armStatus == ArmStatus.DONE] / served++;');
        expect(served.fullText).toBe('[armStatus == ArmStatus.DONE] / { served++; }');
        // A short one stays as it is.
        const toaster = await model(ws, 'maa-automaton', 'toast/ToasterController.arc');
        expect(byId(toaster).get('tr:Off->On#label')).toMatchObject({ text: '[cmd == ToasterCmd.START]' });
        expect(byId(toaster).get('tr:Off->On#label')!.fullText).toBeUndefined();
    });

    test('shortenTransitionLabel keeps trigger and guard, shortens the action, and cuts what is left too long', () => {
        const fits = (t: string): boolean => textSize(t, FONTS.transition).width <= MAX_TRANSITION_LABEL_WIDTH;
        expect(shortenTransitionLabel('go [x > 0] / y = 1;')).toBe('go [x > 0] / y = 1;');
        const action = shortenTransitionLabel(`go [x > 0] / { ${'value = value + 1; '.repeat(10)}}`);
        expect(action).toMatch(/^go \[x > 0\] \/ value = value \+ 1;.*…$/);
        expect(fits(action)).toBe(true);
        // A division in the guard is not the action's slash.
        const division = shortenTransitionLabel(`[x / 2 > 1] / { ${'value = value + 1; '.repeat(10)}}`);
        expect(division).toMatch(/^\[x \/ 2 > 1\] \/ value = value \+ 1;.*…$/);
        const guard = shortenTransitionLabel(`go [${'someLongCondition && '.repeat(10)}true] / { a = 1; }`);
        expect(guard).toMatch(/^go \[someLongCondition &&.*…$/);
        expect(fits(guard)).toBe(true);
    });

    test('with substates: the nested states inside their parent, nothing overlapping', async () => {
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
      Low -> High [i > 10] / { o = 3; };
      High -> Low [i < 5];
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
        const m = await model(ws, 'maa-automaton', 'toast/Modes.arc');
        expect(siblingOverlaps(m)).toEqual([]);
        expect(automatonProblems(m)).toEqual([]);
        const { boxes } = geometry(m);
        const on = boxes.get('state:On')!;
        for (const id of ['state:On.Low', 'state:On.High', 'tr:On.Low->On.High#label']) {
            const b = boxes.get(id)!;
            expect(b.x, id).toBeGreaterThanOrEqual(on.x);
            expect(b.y, id).toBeGreaterThan(on.y);
            expect(b.x + b.width, id).toBeLessThanOrEqual(on.x + on.width);
            expect(b.y + b.height, id).toBeLessThanOrEqual(on.y + on.height);
        }
    });

    test('keeps its ids and the positions of the states when a guard is edited', async () => {
        const ws = await diagramWorkspace();
        const before = await model(ws, 'maa-automaton', 'toast/Controller.arc');
        await ws.edit('toast/Controller.arc', (t) =>
            t.replace('[armStatus == ArmStatus.DONE] / { served++; }', '[armStatus == ArmStatus.DONE && served >= 0] / { served++; }'),
        );
        const after = await model(ws, 'maa-automaton', 'toast/Controller.arc');
        expect([...byId(after).keys()]).toEqual([...byId(before).keys()]);
        expect(byId(after).get('tr:Serving->Idle')!.label).toBe('[armStatus == ArmStatus.DONE && served >= 0] / { served++; }');
        expect(moved(positions(before, 'node:state'), positions(after, 'node:state'))).toEqual([]);
        expect(automatonProblems(after)).toEqual([]);
    });

    test('is deterministic: the same model, the same layout', async () => {
        const ws = await diagramWorkspace();
        const a = await model(ws, 'maa-automaton', 'toast/ToasterController.arc');
        const b = await model(ws, 'maa-automaton', 'toast/ToasterController.arc');
        expect(b).toEqual(a);
    });
});

describe('the C&C layout', () => {
    test(`of the ToastServiceRobot is at most ${CC_MAX_WIDTH} px wide, without overlaps, ports on their borders`, async () => {
        const ws = await diagramWorkspace();
        const m = await model(ws, 'maa-cc', 'toast/ToastServiceRobot.arc');
        const root = byId(m).get('root')!;
        const size = root.size as { width: number; height: number };
        expect(size.width).toBeLessThanOrEqual(CC_MAX_WIDTH);
        expect(size.height).toBeLessThanOrEqual(600);
        expect(siblingOverlaps(m)).toEqual([]);
        expect(componentProblems(m)).toEqual([]);
    });

    test('with composed subcomponents, closed and open: no overlaps, ports on their borders', async () => {
        const files = {
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
            'toast/Robot2.arc': `package toast;

component Robot2 {
  Sensing sensing;
  PlateLocator plate;
  Controller ctrl;
  ToasterController toasterCtrl;
  ToasterActuator act;
  ArmController arm;

  sensing.distance -> ctrl.distance;
  sensing.color -> ctrl.color;
  ctrl.toaster -> toasterCtrl.cmd;
  toasterCtrl.leverDown -> act.leverDown;
  ctrl.arm -> arm.cmd;
  plate.angle -> arm.angle;
  plate.height -> arm.height;
  arm.status -> ctrl.armStatus;
}
`,
        };
        const ws = await diagramWorkspace(files);
        const closed = await model(ws, 'maa-cc', 'toast/Robot2.arc');
        expect(siblingOverlaps(closed)).toEqual([]);
        expect(componentProblems(closed)).toEqual([]);
        expect((byId(closed).get('root')!.size as { width: number }).width).toBeLessThanOrEqual(CC_MAX_WIDTH);
        const open = await model(ws, 'maa-cc', 'toast/Robot2.arc', { expanded: ['sensing'] });
        expect(siblingOverlaps(open)).toEqual([]);
        expect(componentProblems(open)).toEqual([]);
        // A composed component shown as the diagram, with ports of its own.
        const sensing = await model(ws, 'maa-cc', 'toast/Sensing.arc');
        expect(siblingOverlaps(sensing)).toEqual([]);
        expect(componentProblems(sensing)).toEqual([]);
    });

    test("keeps room right of a composed subcomponent's type for the expand/collapse button", async () => {
        // A type name longer than instance name and badge together: the type row sets the width.
        const files = {
            ...exampleFiles(),
            'toast/DistanceSensingAssemblyUnit.arc':
                'package toast;\n\ncomponent DistanceSensingAssemblyUnit {\n  port out int distance;\n  DistanceSensor dist;\n  dist.value -> distance;\n}\n',
            'toast/Robot3.arc': 'package toast;\n\ncomponent Robot3 {\n  DistanceSensingAssemblyUnit u;\n}\n',
        };
        const ws = await diagramWorkspace(files);
        for (const expanded of [[], ['u']]) {
            const all = byId(await model(ws, 'maa-cc', 'toast/Robot3.arc', { expanded }));
            const node = all.get('root.u')!.size as { width: number };
            const type = all.get('root.u#type')!;
            const typeRight = (type.position as { x: number }).x + (type.size as { width: number }).width;
            expect(node.width - typeRight, `expanded: ${expanded.join()}`).toBeGreaterThanOrEqual(EXPAND_TOGGLE_ROOM);
        }
    });

    test('keeps ids and the positions of the other instances when a port is renamed', async () => {
        const ws = await diagramWorkspace();
        const before = await model(ws, 'maa-cc', 'toast/ToastServiceRobot.arc');
        await ws.edit('toast/Controller.arc', (t) =>
            t.replace('in int distance', 'in int dist').replace('[distance < threshold]', '[dist < threshold]'),
        );
        await ws.edit('toast/ToastServiceRobot.arc', (t) => t.replace('-> ctrl.distance', '-> ctrl.dist'));
        const after = await model(ws, 'maa-cc', 'toast/ToastServiceRobot.arc');
        const renamed = (id: string): string => id.replace('ctrl:distance', 'ctrl:dist').replace('ctrl.distance', 'ctrl.dist');
        expect([...byId(after).keys()]).toEqual([...byId(before).keys()].map(renamed));
        expect(moved(positions(before, 'node:component'), positions(after, 'node:component'))).toEqual([]);
        expect(componentProblems(after)).toEqual([]);
    });

    test('keeps the positions when a guard of an automaton is edited', async () => {
        const ws = await diagramWorkspace();
        const before = await model(ws, 'maa-cc', 'toast/ToastServiceRobot.arc');
        await ws.edit('toast/Controller.arc', (t) => t.replace('[distance < threshold]', '[distance <= threshold]'));
        const after = await model(ws, 'maa-cc', 'toast/ToastServiceRobot.arc');
        expect([...byId(after).keys()]).toEqual([...byId(before).keys()]);
        expect(moved(positions(before, 'node:component'), positions(after, 'node:component'))).toEqual([]);
        expect(moved(positions(before, 'port'), positions(after, 'port'))).toEqual([]);
    });
});
