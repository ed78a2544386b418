// Issue 19's diagram polish in the model the diagram server sends: ports in declaration order, an
// atomic component shown on its own with its interface (port types) and its automaton or RobotArm
// programs, and the automaton's transitions numbered as a run's transition events number them.
import { describe, expect, test } from 'vitest';
import type { SModelElement, SModelRoot } from 'sprotty-protocol';
import { allTransitions, sourceOf, targetOf, statePath, type ast as automata } from '@maa/language-automata';
import { behaviorsOf, type ast as adl } from '@maa/language-adl';
import { AstUtils } from 'langium';
import { byId, diagramWorkspace, exampleFiles, TestClient, type DiagramWorkspace } from './diagram-helpers.js';

type Element = SModelElement & Record<string, unknown>;
const children = (e: Element): Element[] => (e.children ?? []) as Element[];

async function model(ws: DiagramWorkspace, diagramType: string, file: string, extra: Record<string, unknown> = {}): Promise<SModelRoot> {
    return new TestClient(ws.diagrams).requestModel({ diagramType, sourceUri: ws.uri(file), needsClientLayout: false, ...extra });
}

/** The names of a node's ports on one side, top to bottom. */
function sideOrder(node: Element, direction: 'in' | 'out'): string[] {
    return children(node)
        .filter((c) => c.type === 'port' && c.direction === direction)
        .sort((a, b) => (a.position as { y: number }).y - (b.position as { y: number }).y)
        .map((c) => String(c.name));
}

const PORTS = `package toast;

component Ordered {
  port in int zeta,
       in int alpha,
       in int mid,
       out int second,
       out int first;
}
`;

const USER = `package toast;

component UsesOrdered {
  port in int a, in int b, in int c, out int x, out int y;
  Ordered o;
  a -> o.zeta;
  b -> o.alpha;
  c -> o.mid;
  o.second -> x;
  o.first -> y;
}
`;

describe('ports', () => {
    test('are listed top to bottom in declaration order on both sides, shown alone, as a subcomponent and on the shown component', async () => {
        const ws = await diagramWorkspace({ ...exampleFiles(), 'toast/Ordered.arc': PORTS, 'toast/UsesOrdered.arc': USER });
        const alone = byId(await model(ws, 'maa-cc', 'toast/Ordered.arc')).get('root')!;
        expect(sideOrder(alone, 'in')).toEqual(['zeta', 'alpha', 'mid']);
        expect(sideOrder(alone, 'out')).toEqual(['second', 'first']);
        const all = byId(await model(ws, 'maa-cc', 'toast/UsesOrdered.arc'));
        expect(sideOrder(all.get('root.o')!, 'in')).toEqual(['zeta', 'alpha', 'mid']);
        expect(sideOrder(all.get('root.o')!, 'out')).toEqual(['second', 'first']);
        expect(sideOrder(all.get('root')!, 'in')).toEqual(['a', 'b', 'c']);
        expect(sideOrder(all.get('root')!, 'out')).toEqual(['x', 'y']);
        // The example's Controller (in ports: distance, color, armStatus).
        const ctrl = byId(await model(ws, 'maa-cc', 'toast/ToastServiceRobot.arc')).get('root.ctrl')!;
        expect(sideOrder(ctrl, 'in')).toEqual(['distance', 'color', 'armStatus']);
    });
});

describe('an atomic component shown on its own', () => {
    test('names its ports with their types and says what its automaton is, with a link to the automaton view', async () => {
        const ws = await diagramWorkspace();
        const all = byId(await model(ws, 'maa-cc', 'toast/Controller.arc'));
        expect(all.get('root:distance#name')!.text).toBe('distance: int');
        expect(all.get('root:arm#name')!.text).toBe('arm: ArmProgram');
        const lines = children(all.get('root')!).filter((c) => c.type === 'label:behavior');
        expect(lines[0]!.text).toMatch(/^automaton: \d+ states, \d+ transitions/);
        expect(lines[0]!.opens).toBe('automaton');
        expect(lines[1]!.text).toMatch(/^states: Idle/);
        // The behavior lines are traced to the automaton.
        expect(String(lines[0]!.trace)).toContain('Controller.arc');
    });

    test("lists a RobotArm component's programs with their steps", async () => {
        const ws = await diagramWorkspace();
        const root = byId(await model(ws, 'maa-cc', 'toast/ArmController.arc')).get('root')!;
        const lines = children(root)
            .filter((c) => c.type === 'label:behavior')
            .map((c) => String(c.text));
        expect(lines).toEqual(['RobotArm programs: 2', '▸ LoadBread (10 steps)', '▸ PickupAndDeploy (10 steps)']);
    });

    test('a subcomponent keeps plain port names and has no behavior lines; a compute component none either', async () => {
        const ws = await diagramWorkspace();
        const all = byId(await model(ws, 'maa-cc', 'toast/ToastServiceRobot.arc'));
        expect(all.get('root.ctrl:distance#name')!.text).toBe('distance');
        expect([...all.values()].some((e) => e.type === 'label:behavior')).toBe(false);
        const sensor = byId(await model(ws, 'maa-cc', 'toast/DistanceSensor.arc'));
        expect([...sensor.values()].some((e) => e.type === 'label:behavior')).toBe(false);
    });
});

describe('transitions in the automaton view', () => {
    test('carry their index in allTransitions order, and that transition is the one from source to target', async () => {
        const ws = await diagramWorkspace();
        const m = await model(ws, 'maa-automaton', 'toast/Controller.arc');
        const component = AstUtils.streamAst(ws.doc('toast/Controller.arc').parseResult.value).find(
            (n): n is adl.ComponentType => n.$type === 'ComponentType',
        )!;
        const automaton = behaviorsOf(component)
            .map((b) => b.behavior)
            .find((b) => b?.$type === 'Automaton') as unknown as automata.Automaton;
        const path = (s: automata.State | undefined): string =>
            s
                ? statePath(s)
                      .map((p) => p.name)
                      .join('.')
                : '';
        const expected = allTransitions(automaton).map((t, index) => ({ index, from: path(sourceOf(t)), to: path(targetOf(t)) }));
        const all = byId(m);
        const edges = [...all.values()].filter((e) => e.type === 'edge:transition');
        expect(edges.length).toBe(expected.length);
        const pathOf = (id: unknown): string => String(all.get(String(id))!.statePath);
        const got = edges
            .map((e) => ({ index: Number(e.transitionIndex), from: pathOf(e.sourceId), to: pathOf(e.targetId) }))
            .sort((a, b) => a.index - b.index);
        expect(got).toEqual(expected);
    });
});
