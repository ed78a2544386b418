import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { type ast, allPorts, behaviorsOf, elementsOf, subcomponentType, subcomponentsOf } from '@maa/language-adl';
import { type AnyTransition, allTransitions, sourceOf, statePath, substates, targetOf } from '@maa/language-automata';
import { IDE_DIAGRAM_CSS, loadDiagramWorkspace, workspaceComponents } from '@maa/language-server';
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import { ModelDir, requireBuiltCli, runCli, runCliInProcess } from './helpers.js';
import { descendants, modelIds, parseSvg, type SvgNode, withClass } from './svg-tree.js';

// `maa-gen diagram`: the IDE's C&C and automaton views of a component as SVG (checked element by
// element against the model's AST) and PNG. That the SVG holds what the IDE's Export SVG holds
// for the same component is checked in the e2e suite (e2e/scenarios.mjs, "diagram export").
// maa-gen runs in a warm worker thread (runCliInProcess; a cold diagram process costs about three
// seconds of CPU), except for the default output file, an SVG on stdout, and a usage error.

const REPO = fileURLToPath(new URL('../../../', import.meta.url));
const EXAMPLE = path.join(REPO, 'examples', 'toast-service');

/** Nested composed components: Top > mid: Mid > low: Low > leaf: Leaf, with an automaton in Leaf. */
const NESTED: Record<string, string> = {
    'maa.json': '{}\n',
    'nest/Top.arc': 'package nest;\n\ncomponent Top {\n  port in int i;\n  port out int o;\n  Mid mid;\n  i -> mid.i;\n  mid.o -> o;\n}\n',
    'nest/Mid.arc': 'package nest;\n\ncomponent Mid {\n  port in int i;\n  port out int o;\n  Low low;\n  i -> low.i;\n  low.o -> o;\n}\n',
    'nest/Low.arc':
        'package nest;\n\ncomponent Low {\n  port in int i;\n  port out int o;\n  Leaf leaf;\n  i -> leaf.i;\n  leaf.o -> o;\n}\n',
    'nest/Leaf.arc': [
        'package nest;',
        '',
        'component Leaf {',
        '  port in int i;',
        '  port out int o;',
        '  automaton {',
        '    initial { o = 0; } state Off;',
        '    state On {',
        '      initial state Low;',
        '      state High;',
        '      Low -> High [i > 10];',
        '    };',
        '    Off -> On [i > 0] / { o = 1; };',
        '    On -> Off [i < 0] / { o = 0; };',
        '    On -> On [i == 5];',
        '  }',
        '}',
        '',
    ].join('\n'),
};

let dir: ModelDir | undefined;
afterEach(() => {
    dir?.dispose();
    dir = undefined;
});

beforeAll(() => requireBuiltCli());

async function diagramSvg(args: string[]): Promise<{ svg: SvgNode; text: string; stderr: string }> {
    dir ??= new ModelDir();
    const out = dir.path(`out-${Math.random().toString(36).slice(2)}.svg`);
    const result = await runCliInProcess(['diagram', ...args, '--out', out], REPO);
    expect(result.stderr).toMatch(/C&C view of|state machine of/);
    expect(result.code, result.stderr).toBe(0);
    const text = readFileSync(out, 'utf8');
    return { svg: parseSvg(text), text, stderr: result.stderr };
}

async function component(root: string, name: string): Promise<ast.ComponentType> {
    const ws = await loadDiagramWorkspace(root);
    const found = workspaceComponents(ws.family.shared.workspace.LangiumDocuments).find((c) => c.name === name);
    if (!found) throw new Error(`no component ${name} in ${root}`);
    return found.node;
}

describe('maa-gen diagram: the C&C view', () => {
    it("holds every subcomponent instance, port and connector of the example's ToastServiceRobot", async () => {
        const robot = await component(EXAMPLE, 'toast.ToastServiceRobot');
        const { svg, stderr } = await diagramSvg(['toast.ToastServiceRobot', '--root', EXAMPLE]);
        const instances = new Set(withClass(svg, 'maa-component').map((n) => n.attrs['data-instance-path']));
        const ports = new Set(withClass(svg, 'maa-port').map((n) => n.attrs['data-port-path']));
        const ids = new Set(modelIds(svg));

        const subs = subcomponentsOf(robot);
        expect(subs.length).toBeGreaterThan(5);
        expect(instances).toEqual(new Set(['', ...subs.map((s) => s.name)]));
        const expectedPorts = [
            ...allPorts(robot).map((p) => p.name),
            ...subs.flatMap((s) => allPorts(subcomponentType(s).decl!).map((p) => `${s.name}.${p.name}`)),
        ];
        expect(ports).toEqual(new Set(expectedPorts));
        const portName = (a: ast.PortAccess): string =>
            a.subcomponent ? `${a.subcomponent.$refText}.${a.port.$refText}` : a.port.$refText;
        const connectors = elementsOf(robot).flatMap((e) =>
            e.$type === 'Connector' ? e.targets.map((t) => `conn:root:${portName(e.source)}->${portName(t)}`) : [],
        );
        expect(connectors.length).toBeGreaterThan(5);
        for (const c of connectors) expect(ids, c).toContain(c);
        expect(withClass(svg, 'maa-connector')).toHaveLength(connectors.length);
        // Each connector is drawn as a path with an arrow head.
        for (const c of withClass(svg, 'maa-connector')) {
            expect(c.children[0]?.attrs['d']).toMatch(/^M [\d.-]+,[\d.-]+( L [\d.-]+,[\d.-]+)+$/);
            expect(withClass(c, 'maa-arrow')).toHaveLength(1);
        }
        // Names, types and behavior badges as the IDE labels them.
        const labels = (cls: string): string[] => withClass(svg, cls).map((n) => n.text.trim());
        expect(labels('maa-label-name')).toEqual(expect.arrayContaining(['ToastServiceRobot', ...subs.map((s) => s.name)]));
        expect(labels('maa-label-type')).toEqual(expect.arrayContaining(['ArmController', 'Controller']));
        expect(withClass(svg, 'maa-badge-robotarm')).toHaveLength(1);
        expect(svg.attrs['viewBox']).toMatch(/^[\d.-]+ [\d.-]+ [\d.]+ [\d.]+$/);
        expect(stderr).toContain(`${subs.length + 1} components, ${expectedPorts.length} ports, ${connectors.length} connectors`);
    });

    it('writes COMPONENT.svg by default, takes a simple name and a model file, and carries the IDE stylesheet', async () => {
        dir = new ModelDir();
        const byName = await runCli(['diagram', 'Controller', '--root', EXAMPLE], dir.dir);
        expect(byName.code, byName.stderr).toBe(0);
        const text = readFileSync(dir.path('Controller.svg'), 'utf8');
        const byFile = await runCli(['diagram', path.join(EXAMPLE, 'toast', 'Controller.arc'), '--out', '-'], dir.dir);
        expect(byFile.code, byFile.stderr).toBe(0);
        expect(byFile.stdout).toBe(text);
        const svg = parseSvg(text);
        expect(svg.attrs['xmlns']).toBe('http://www.w3.org/2000/svg');
        const style = [...descendants(svg)].find((n) => n.name === 'style')?.text ?? '';
        expect(style).toContain('.maa-component.maa-kind-automaton > .maa-component-body { fill: #eef7ee; stroke: #3f7a45; }');
        expect(style).not.toContain('var(');
    });

    it('--depth limits the nesting: 1 as the IDE opens a diagram, each level more opens the composed subcomponents', async () => {
        dir = new ModelDir();
        for (const [file, text] of Object.entries(NESTED)) dir.write(file, text);
        const instances = async (depth: string): Promise<string[]> => {
            const out = await runCliInProcess(['diagram', 'nest.Top', '--depth', depth, '--out', '-'], dir!.dir);
            expect(out.code, out.stderr).toBe(0);
            return withClass(parseSvg(out.stdout), 'maa-component')
                .map((n) => n.attrs['data-instance-path']!)
                .sort();
        };
        expect(await instances('1')).toEqual(['', 'mid']);
        expect(await instances('2')).toEqual(['', 'mid', 'mid.low']);
        expect(await instances('3')).toEqual(['', 'mid', 'mid.low', 'mid.low.leaf']);
        expect(await instances('all')).toEqual(['', 'mid', 'mid.low', 'mid.low.leaf']);
        const two = parseSvg((await runCliInProcess(['diagram', 'nest.Top', '--depth', '2', '--out', '-'], dir.dir)).stdout);
        const mid = withClass(two, 'maa-component').find((n) => n.attrs['data-instance-path'] === 'mid')!;
        expect(mid.attrs['class']).toContain('maa-expanded');
        // The opened subcomponent's connectors are drawn inside it.
        expect(modelIds(two)).toEqual(expect.arrayContaining(['conn:root.mid:i->low.i', 'conn:root.mid:low.o->o']));
        const bad = await runCliInProcess(['diagram', 'nest.Top', '--depth', '0'], dir.dir);
        expect(bad.code).toBe(2);
        expect(bad.stderr).toContain('--depth takes a number from 1 or "all"');
    });
});

describe('maa-gen diagram --automaton', () => {
    const stateNames = (level: Parameters<typeof substates>[0]): string[] =>
        substates(level).flatMap((s) => [
            statePath(s)
                .map((p) => p.name)
                .join('.'),
            ...stateNames(s),
        ]);
    const pathOf = (s: ReturnType<typeof sourceOf>): string =>
        statePath(s!)
            .map((p) => p.name)
            .join('.');

    async function expectEveryStateAndTransition(root: string, name: string, args: string[]): Promise<SvgNode> {
        const type = await component(root, name);
        const automaton = behaviorsOf(type)
            .map((b) => b.behavior as { $type: string } | undefined)
            .find((b) => b?.$type === 'Automaton') as Parameters<typeof allTransitions>[0];
        const { svg } = await diagramSvg(args);
        const states = stateNames(automaton);
        expect(states.length).toBeGreaterThan(2);
        expect(new Set(withClass(svg, 'maa-state').map((n) => n.attrs['data-state-path']))).toEqual(new Set(states));
        const transitions: AnyTransition[] = allTransitions(automaton);
        const drawn = withClass(svg, 'maa-transition').map((n) => n.attrs['id']!.slice(n.attrs['id']!.indexOf('_') + 1));
        expect(drawn).toHaveLength(transitions.length);
        for (const t of transitions)
            expect(drawn.some((id) => id.startsWith(`tr:${pathOf(sourceOf(t))}->${pathOf(targetOf(t))}`))).toBe(true);
        expect(withClass(svg, 'maa-initial-marker').length).toBeGreaterThan(0);
        return svg;
    }

    it("shows every state and transition of the example's Controller, with their labels", async () => {
        const svg = await expectEveryStateAndTransition(EXAMPLE, 'toast.Controller', [
            'toast.Controller',
            '--automaton',
            '--root',
            EXAMPLE,
        ]);
        expect(svg.attrs['class']).toBe('sprotty-graph maa-graph');
        const labels = withClass(svg, 'maa-label-transition').map((n) => n.attrs['data-full-text'] ?? n.text.trim());
        expect(labels).toEqual(expect.arrayContaining(['[armStatus == ArmStatus.DONE] / { served++; }']));
    });

    it('shows substates nested in their state and a loop', async () => {
        dir = new ModelDir();
        for (const [file, text] of Object.entries(NESTED)) dir.write(file, text);
        const svg = await expectEveryStateAndTransition(dir.dir, 'nest.Leaf', ['nest.Leaf', '--automaton', '--root', dir.dir]);
        const on = withClass(svg, 'maa-state').find((n) => n.attrs['data-state-path'] === 'On')!;
        expect(withClass(on, 'maa-state').map((n) => n.attrs['data-state-path'])).toEqual(['On.Low', 'On.High']);
        expect(modelIds(svg)).toContain('tr:On->On');
    });

    it('is a usage error (exit 2) for a component without an automaton', async () => {
        const result = await runCli(['diagram', 'toast.ToastServiceRobot', '--automaton', '--root', EXAMPLE, '--out', '-'], REPO);
        expect(result.code).toBe(2);
        expect(result.stderr).toContain('maa-gen: error: toast.ToastServiceRobot has no automaton and no mode automaton');
        expect(result.stdout).toBe('');
    });
});

describe('maa-gen diagram: PNG and errors', () => {
    it('writes a PNG of the SVG size times --scale', async () => {
        dir = new ModelDir();
        const svgRun = await runCliInProcess(['diagram', 'toast.ToastServiceRobot', '--root', EXAMPLE, '--out', 'robot.svg'], dir.dir);
        expect(svgRun.code, svgRun.stderr).toBe(0);
        const svg = parseSvg(readFileSync(dir.path('robot.svg'), 'utf8'));
        const width = Number(svg.attrs['width']);
        const height = Number(svg.attrs['height']);
        for (const [args, scale] of [
            [['--out', 'robot.png'], 2],
            [['--format', 'png', '--scale', '1', '--out', 'one.bin'], 1],
        ] as const) {
            const result = await runCliInProcess(['diagram', 'toast.ToastServiceRobot', '--root', EXAMPLE, ...args], dir.dir);
            expect(result.code, result.stderr).toBe(0);
            const png = readFileSync(dir.path(args[args.length - 1]!));
            expect(png.subarray(0, 8)).toEqual(Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]));
            expect(png.subarray(12, 16).toString('ascii')).toBe('IHDR');
            expect(png.readUInt32BE(16)).toBe(Math.round(width * scale));
            expect(png.readUInt32BE(20)).toBe(Math.round(height * scale));
        }
    });

    it('an unknown component is a usage error (exit 2) that names the components there are', async () => {
        const result = await runCliInProcess(['diagram', 'toast.ToastRobot', '--root', EXAMPLE], REPO);
        expect(result.code).toBe(2);
        expect(result.stderr).toMatch(/^maa-gen: error: unknown component "toast\.ToastRobot"; similar: .*toast\.ToastServiceRobot/m);
        const none = await runCliInProcess(['diagram', 'Nothing', '--root', EXAMPLE], REPO);
        expect(none.code).toBe(2);
        expect(none.stderr).toContain('unknown component "Nothing"; the model root has: toast.ArmController');
    });

    it('draws a model with errors, marks them as the IDE does and says so', async () => {
        dir = new ModelDir();
        dir.write('maa.json', '{}\n');
        dir.write('Broken.arc', 'component Broken {\n  port in Missing x;\n  port out int o;\n}\n');
        const result = await runCliInProcess(['diagram', 'Broken', '--out', '-'], dir.dir);
        expect(result.code, result.stderr).toBe(0);
        const port = withClass(parseSvg(result.stdout), 'maa-port').find((n) => n.attrs['data-port-path'] === 'x');
        expect(port?.attrs['class']).toContain('maa-error');
        expect(result.stderr).toMatch(/^note: the model root has 1 error \(maa-gen check lists them\); the diagram marks them$/m);
    });

    it('an output that cannot be written is an I/O problem (exit 2)', async () => {
        dir = new ModelDir();
        dir.write('blocker', 'a file, not a folder\n');
        const result = await runCliInProcess(['diagram', 'Controller', '--root', EXAMPLE, '--out', 'blocker/x.svg'], dir.dir);
        expect(result.code).toBe(2);
        expect(result.stderr).toContain('maa-gen: error: cannot write blocker/x.svg');
    });
});

describe("the SVG writer's stylesheet", () => {
    it('is the one diagram stylesheet, which the IDE imports (and does not copy)', () => {
        const sheet = readFileSync(path.join(REPO, 'packages/language-server/styles/diagram-svg.css'), 'utf8');
        expect(IDE_DIAGRAM_CSS.trimEnd()).toBe(sheet.slice(sheet.indexOf('/* ---- SVG ---- */')).trimEnd());
        const ide = readFileSync(path.join(REPO, 'packages/diagram-view/src/index.ts'), 'utf8');
        expect(ide).toContain("import '@maa/language-server/diagram-svg.css';");
        const ideCss = readFileSync(path.join(REPO, 'packages/diagram-view/src/diagram.css'), 'utf8');
        expect(ideCss).not.toContain('.maa-component-body');
    });
});
