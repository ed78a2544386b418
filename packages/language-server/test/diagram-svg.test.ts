// The diagram as standalone SVG without a browser (src/diagram/svg, src/diagram/standalone.ts):
// the model the IDE gets for the same request, rendered with the IDE views' elements, ids and
// classes; edges routed from port border to port border as Sprotty routes them; texts escaped.
// maa-gen diagram's tests (packages/cli/test/diagram.test.ts) check the example end to end, the
// e2e scenario "diagram export" against the IDE's Export SVG.
import { describe, expect, test } from 'vitest';
import type { SModelElement } from 'sprotty-protocol';
import {
    DEFAULT_ID_PREFIX,
    expandedToDepth,
    renderDiagramSvg,
    standaloneDiagram,
    standaloneStylesheet,
    workspaceComponents,
    type MaaGraph,
} from '../src/diagram/index.js';
import { DiagramGeometry, rectangleAnchor } from '../src/diagram/svg/geometry.js';
import { byId, diagramWorkspace, type DiagramWorkspace } from './diagram-helpers.js';

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
  }
}
`;
const GUARDED = `component Guarded {
  port in int a, in int b;
  port out boolean o;
  automaton {
    initial { o = false; } state S;
    state T;
    S -> T [a < b && b > 0] / { o = true; };
  }
}
`;
const WRAP =
    'component Wrap {\n  port in int i;\n  port in boolean f;\n  port out int o;\n  Shift s;\n  i -> s.i;\n  f -> s.flip;\n  s.o -> o;\n}\n';

async function diagram(ws: DiagramWorkspace, name: string, diagramType: 'maa-cc' | 'maa-automaton', depth = 1): Promise<MaaGraph> {
    const component = workspaceComponents(ws.family.shared.workspace.LangiumDocuments).find((c) => c.name === name)?.node;
    if (!component) throw new Error(`no component ${name}`);
    return standaloneDiagram(ws.diagrams, { component, diagramType, expanded: expandedToDepth(component, depth) });
}

/** The attributes of the element with a model id. */
function element(svg: string, id: string): Record<string, string> {
    const escaped = `${DEFAULT_ID_PREFIX}${id}`
        .replace(/&/g, '&amp;')
        .replace(/>/g, '&gt;')
        .replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
    const tag = new RegExp(`<[\\w:-]+\\b[^>]*\\sid="${escaped}"[^>]*>`).exec(svg)?.[0];
    if (!tag) throw new Error(`no element ${id}`);
    return Object.fromEntries([...tag.matchAll(/([\w:-]+)="([^"]*)"/g)].map((m) => [m[1]!, m[2]!]));
}

const files = { 'Pass.arc': PASS, 'Shift.arc': SHIFT, 'Guarded.arc': GUARDED, 'Wrap.arc': WRAP };

describe('standalone diagrams', () => {
    test('the mode automaton of a decomposed component: modes as states, mode transitions with labels', async () => {
        const ws = await diagramWorkspace(files);
        const svg = renderDiagramSvg(await diagram(ws, 'Shift', 'maa-automaton'));
        expect(element(svg, 'state:Up')).toMatchObject({ class: 'maa-state maa-state-initial state', 'data-state-path': 'Up' });
        expect(element(svg, 'state:Down')).toMatchObject({ class: 'maa-state state' });
        expect(element(svg, 'tr:Up->Down')['class']).toBe('sprotty-edge maa-transition transition');
        expect(svg).toMatch(/id="maa-diagram_tr:Down-&gt;Up#label"[^>]*>Tick</);
    });

    test('the C&C view shows the subcomponents of every mode, marked with their mode; --depth opens them', async () => {
        const ws = await diagramWorkspace(files);
        const shift = renderDiagramSvg(await diagram(ws, 'Shift', 'maa-cc'));
        expect(element(shift, 'root.p')).toMatchObject({ 'data-instance-path': 'p', 'data-mode': 'Up' });
        expect(element(shift, 'root.q')).toMatchObject({ 'data-instance-path': 'q', 'data-mode': 'Down' });
        const closed = renderDiagramSvg(await diagram(ws, 'Wrap', 'maa-cc', 1));
        expect(element(closed, 'root.s')['class']).toBe('maa-component maa-composed maa-kind-mode component');
        expect(closed).not.toContain('data-instance-path="s.p"');
        const open = renderDiagramSvg(await diagram(ws, 'Wrap', 'maa-cc', 2));
        expect(element(open, 'root.s')['class']).toBe('maa-component maa-composed maa-expanded maa-kind-mode component');
        expect(element(open, 'root.s.p')).toMatchObject({ 'data-instance-path': 's.p', 'data-mode': 'Up' });
    });

    test('a component that contains itself (an error) is opened once at any depth', async () => {
        const ws = await diagramWorkspace({
            'Loop.arc': 'component Loop {\n  port in int i;\n  Inner n;\n}\n',
            'Inner.arc': 'component Inner {\n  port in int i;\n  Loop back;\n}\n',
        });
        const loop = workspaceComponents(ws.family.shared.workspace.LangiumDocuments).find((c) => c.name === 'Loop')!.node;
        expect(expandedToDepth(loop, Number.POSITIVE_INFINITY)).toEqual(['n']);
        expect(expandedToDepth(loop, 1)).toEqual([]);
        const svg = renderDiagramSvg(await diagram(ws, 'Loop', 'maa-cc', Number.POSITIVE_INFINITY));
        expect(element(svg, 'root.n.back')['data-instance-path']).toBe('n.back');
    });

    test('texts are escaped: a guard with < and && reads back as written', async () => {
        const ws = await diagramWorkspace(files);
        const svg = renderDiagramSvg(await diagram(ws, 'Guarded', 'maa-automaton'));
        expect(svg).toContain('>[a &lt; b &amp;&amp; b &gt; 0] / { o = true; }</text>');
        expect(svg).toContain('id="maa-diagram_tr:S-&gt;T"');
        expect(svg).not.toMatch(/<[^>]*<(?![/\w!?])/); // no raw < inside a tag or text
    });

    test('connectors run from the border of their source port to that of their target port', async () => {
        const ws = await diagramWorkspace(files);
        const graph = await diagram(ws, 'Wrap', 'maa-cc', 2);
        const geometry = new DiagramGeometry(graph);
        const edges = [...byId(graph).values()].filter((e) => e.type === 'edge:connector') as Array<
            SModelElement & { sourceId: string; targetId: string }
        >;
        expect(edges.length).toBeGreaterThan(3);
        for (const edge of edges) {
            const route = geometry.route(edge as Parameters<DiagramGeometry['route']>[0]);
            const origin = geometry.origin(geometry.parentId(edge.id));
            const onBorder = (p: { x: number; y: number }, id: string): boolean => {
                const b = geometry.absoluteBounds(id)!;
                const x = p.x + origin.x;
                const y = p.y + origin.y;
                const inside = x >= b.x - 0.01 && x <= b.x + b.width + 0.01 && y >= b.y - 0.01 && y <= b.y + b.height + 0.01;
                const edge =
                    [b.x, b.x + b.width].some((v) => Math.abs(x - v) < 0.01) || [b.y, b.y + b.height].some((v) => Math.abs(y - v) < 0.01);
                return inside && edge;
            };
            expect(route.length, edge.id).toBeGreaterThanOrEqual(2);
            expect(onBorder(route[0]!, edge.sourceId), edge.id).toBe(true);
            expect(onBorder(route[route.length - 1]!, edge.targetId), edge.id).toBe(true);
        }
    });

    test('the rectangular anchor: where the line from the centre towards a point leaves the box', () => {
        const box = { x: 0, y: 0, width: 10, height: 10 };
        expect(rectangleAnchor(box, { x: 30, y: 5 })).toEqual({ x: 10, y: 5 });
        expect(rectangleAnchor(box, { x: 5, y: -20 })).toEqual({ x: 5, y: 0 });
        expect(rectangleAnchor(box, { x: -5, y: 15 })).toEqual({ x: 0, y: 10 });
        expect(rectangleAnchor(box, { x: 5, y: 5 })).toEqual({ x: 5, y: 5 }); // the centre itself
    });

    test('the stylesheet resolves every custom property to its light fallback', () => {
        expect(standaloneStylesheet('.a { fill: var(--x, #fff); stroke: var(--y-z,  #123456 ); }')).toBe(
            '.a { fill: #fff; stroke: #123456; }',
        );
        expect(standaloneStylesheet()).not.toContain('var(');
    });
});
