import { existsSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { traceFileContract } from '@maa/protocol';
import { afterEach, describe, expect, test } from 'vitest';
import { GenerateInputError, TRACE_FILE, type GenerateResult } from '../src/node.js';
import { MANIFESTS, MODELS, snapshot, Workspace } from './test-generators.js';

let spaces: Workspace[] = [];
function workspace(...args: ConstructorParameters<typeof Workspace>): Workspace {
    const w = new Workspace(...args);
    spaces.push(w);
    return w;
}
afterEach(() => {
    for (const w of spaces) w.dispose();
    spaces = [];
});

function errors(r: GenerateResult): string[] {
    return r.diagnostics.filter((d) => d.severity === 'error').map((d) => `${path.basename(d.file)}:${d.line} ${d.code} ${d.message}`);
}

describe('the generation pipeline', () => {
    test('runs the data type generator first, then the component generator, which delegates behaviors by language', async () => {
        const w = workspace();
        const r = await w.generate({ platforms: ['alpha'] });
        expect(errors(r)).toEqual([]);
        expect(r.ok).toBe(true);
        expect(w.rec.log).toEqual([
            'datatypes',
            'components:start:robot.types.Types.Mode',
            'automata:robot.Ctrl:automaton',
            'components:robot.Ctrl:delegated:t.Automata',
            'components:robot.Filter:own:compute',
            'components:robot.Robot:none',
            'components:robot.Sensor:none',
            'components:end:t.Components',
        ]);
        expect(r.platforms.map((p) => p.platform)).toEqual(['alpha']);
        expect(r.platforms[0]!.generators).toEqual([
            { name: 't.Components', kind: 'component', files: 5 },
            { name: 't.Automata', kind: 'behavior', files: 1 },
            { name: 't.DataTypes', kind: 'datatype', files: 1 },
        ]);
        expect(r.platforms[0]!.files).toEqual([
            'behaviors/ctrl_automaton.py',
            'components/ctrl.py',
            'components/filter.py',
            'components/robot.py',
            'components/sensor.py',
            'types.py',
            'user/sensor_impl.py',
        ]);
        expect(readFileSync(w.out('alpha/components/ctrl.py'), 'utf8')).toBe(
            [
                '# robot.Ctrl',
                'class Ctrl:',
                '    distance: "int"  # in',
                '    mode: "Mode"  # out',
                'BEHAVIOR = "behaviors.ctrl_automaton"',
                '# PROTECTED REGION BEGIN extra',
                '# your code here',
                '# PROTECTED REGION END extra',
                '',
            ].join('\n'),
        );
        expect(readFileSync(w.out('alpha/behaviors/ctrl_automaton.py'), 'utf8')).toContain('STATE_Idle = "Idle"');
        expect(existsSync(w.out('beta'))).toBe(false);
    });

    test('a behavior generator gets exactly the context its manifest requires', async () => {
        const w = workspace();
        await w.generate({ platforms: ['alpha'] });
        expect(w.rec.contexts).toEqual([{ component: 'robot.Ctrl', keys: ['out', 'packageName', 'ports', 'templates'] }]);
    });

    test('generates every platform when none is named, each into its own folder', async () => {
        const w = workspace();
        const r = await w.generate();
        expect(r.ok).toBe(true);
        expect(r.platforms.map((p) => path.relative(w.dir, p.outDir))).toEqual([path.join('out', 'alpha'), path.join('out', 'beta')]);
        const a = snapshot(w.out('alpha'));
        const b = snapshot(w.out('beta'));
        expect(Object.keys(b)).toEqual(Object.keys(a));
        expect(b['types.py']).toBe(a['types.py']!.replace('for alpha', 'for beta'));
    });

    test('an unknown platform is an input error', async () => {
        const w = workspace();
        await expect(w.generate({ platforms: ['gamma'] })).rejects.toThrow(GenerateInputError);
        await expect(w.generate({ platforms: ['gamma'] })).rejects.toThrow(
            "application 'Demo' has no platform 'gamma' (platforms: alpha, beta)",
        );
    });
});

describe('the trace file', () => {
    test("maps generated line ranges to model elements (file, range, AST path), in @maa/protocol's format (0-based)", async () => {
        const w = workspace();
        await w.generate({ platforms: ['alpha'] });
        const trace = traceFileContract.parse(JSON.parse(readFileSync(w.out(`alpha/${TRACE_FILE}`), 'utf8')), TRACE_FILE);
        expect(trace).toMatchObject({
            version: 2,
            application: 'Demo',
            platform: 'alpha',
            rootComponent: 'robot.Robot',
            modelRoot: '../../models',
        });
        expect(trace.generators.map((g) => g.name)).toEqual(['t.Components', 't.Automata', 't.DataTypes']);
        const ctrl = trace.files.find((f) => f.path === 'components/ctrl.py')!;
        expect(ctrl.generator).toBe('t.Components');
        expect(ctrl.lines).toBe(8);
        // Generated lines and model positions are 0-based; a range's end is exclusive.
        const short = ctrl.traces.map(
            (t) =>
                `${t.lines.first}-${t.lines.last} ${t.element.type} ${t.element.name ?? ''} ${t.element.file}:${t.element.range!.start.line}`,
        );
        expect(short).toEqual([
            '0-3 ComponentType Ctrl robot/Ctrl.arc:4',
            '2-2 Port distance robot/Ctrl.arc:5',
            '3-3 Port mode robot/Ctrl.arc:6',
        ]);
        expect(ctrl.traces[1]!.element.range).toEqual({ start: { line: 5, character: 7 }, end: { line: 5, character: 22 } });
        expect(ctrl.traces[1]!.element.path).toMatch(/^\/component\/body\/elements@\d+\/ports@0$/);
        const automaton = trace.files.find((f) => f.path === 'behaviors/ctrl_automaton.py')!;
        expect(automaton.traces.map((t) => `${t.lines.first} ${t.element.name} ${t.generator}`)).toEqual([
            '2 Idle t.Automata',
            '3 Busy t.Automata',
        ]);
        const filter = trace.files.find((f) => f.path === 'components/filter.py')!;
        expect(filter.traces.some((t) => t.element.type === 'ComputeBlock')).toBe(true);
        const types = trace.files.find((f) => f.path === 'types.py')!;
        expect(types.traces.map((t) => `${t.lines.first}-${t.lines.last} ${t.element.type} ${t.element.file}`)).toEqual([
            '1-3 CDEnum robot/types/Types.cd',
        ]);
        expect(trace.files.find((f) => f.path === 'user/sensor_impl.py')!.userFile).toBe(true);
    });
});

describe('writing', () => {
    test('is deterministic: a second run changes nothing, and another folder gets identical bytes', async () => {
        const w = workspace();
        const first = await w.generate();
        const before = snapshot(w.out());
        const second = await w.generate();
        expect(second.ok).toBe(true);
        expect(second.platforms.flatMap((p) => p.written)).toEqual([]);
        expect(snapshot(w.out())).toEqual(before);
        expect(first.platforms[0]!.written.length).toBeGreaterThan(0);
        const other = await w.generate({ outDir: path.join(w.dir, 'out2') });
        expect(other.ok).toBe(true);
        expect(snapshot(path.join(w.dir, 'out2'))).toEqual(before);
    });

    test.each(['datatypes', 'components', 'automata'] as const)(
        'a failing generator (%s) leaves the output folder untouched',
        async (where) => {
            const w = workspace();
            expect((await w.generate()).ok).toBe(true);
            writeFileSync(w.out('alpha/user/sensor_impl.py'), '# my code\n');
            const before = snapshot(w.out());
            w.write('models/robot/Filter.arc', MODELS['robot/Filter.arc']!.replace('raw / 2', 'raw / 3'));
            w.rec.failIn = where;
            const r = await w.generate();
            expect(r.ok).toBe(false);
            const generator = { datatypes: 't.DataTypes', components: 't.Components', automata: 't.Automata' }[where];
            expect(errors(r)).toEqual([
                expect.stringMatching(
                    new RegExp(
                        `^App\\.arcapp:\\d+ gen/generator-failed Generator '${generator.replace('.', '\\.')}' failed: ${where} exploded`,
                    ),
                ),
            ]);
            expect(snapshot(w.out())).toEqual(before);
            expect(r.platforms).toEqual([]);
        },
    );

    test('a failing generator creates no output folder', async () => {
        const w = workspace();
        w.rec.failIn = 'automata';
        const r = await w.generate();
        expect(r.ok).toBe(false);
        expect(existsSync(w.out())).toBe(false);
        expect(existsSync(w.dir) && snapshot(w.dir)['out/']).toBeUndefined();
    });

    test('user files are created once and never overwritten; protected regions and foreign files survive', async () => {
        const w = workspace();
        await w.generate({ platforms: ['alpha'] });
        writeFileSync(w.out('alpha/user/sensor_impl.py'), '# my sensor driver\n');
        const filter = readFileSync(w.out('alpha/components/filter.py'), 'utf8');
        writeFileSync(w.out('alpha/components/filter.py'), filter.replace('# your code here', 'import numpy  # mine'));
        writeFileSync(w.out('alpha/NOTES.md'), 'my notes\n');
        w.write('models/robot/Filter.arc', MODELS['robot/Filter.arc']!.replace('raw / 2', 'raw / 4'));
        const r = await w.generate({ platforms: ['alpha'] });
        expect(r.ok).toBe(true);
        expect(r.platforms[0]!.kept).toEqual(['user/sensor_impl.py']);
        expect(r.platforms[0]!.preservedRegions).toBe(1);
        expect(readFileSync(w.out('alpha/user/sensor_impl.py'), 'utf8')).toBe('# my sensor driver\n');
        const regenerated = readFileSync(w.out('alpha/components/filter.py'), 'utf8');
        expect(regenerated).toContain('raw / 4');
        expect(regenerated).toContain('# PROTECTED REGION BEGIN extra\nimport numpy  # mine\n# PROTECTED REGION END extra');
        expect(readFileSync(w.out('alpha/NOTES.md'), 'utf8')).toBe('my notes\n');
    });

    test('files the previous generation wrote and this one does not are removed', async () => {
        const w = workspace();
        await w.generate({ platforms: ['alpha'] });
        writeFileSync(w.out('alpha/NOTES.md'), 'my notes\n');
        w.rec.fewer = true;
        const r = await w.generate({ platforms: ['alpha'] });
        expect(r.platforms[0]!.removed).toEqual(['components/robot.py', 'components/sensor.py']);
        expect(existsSync(w.out('alpha/components/robot.py'))).toBe(false);
        expect(existsSync(w.out('alpha/user/sensor_impl.py'))).toBe(true);
        expect(existsSync(w.out('alpha/NOTES.md'))).toBe(true);
    });

    test('user content in a protected region is never lost: a dropped region stops generation, a stale file is kept', async () => {
        const w = workspace();
        await w.generate({ platforms: ['alpha'] });
        const robot = readFileSync(w.out('alpha/components/robot.py'), 'utf8');
        writeFileSync(w.out('alpha/components/robot.py'), robot.replace('# your code here', 'START = 1'));
        const before = snapshot(w.out());
        w.rec.fewer = true; // robot.py is no longer generated
        const r = await w.generate({ platforms: ['alpha'] });
        expect(r.ok).toBe(true);
        expect(r.diagnostics.filter((d) => d.code.startsWith('gen/')).map((d) => `${d.severity} ${d.code}`)).toEqual([
            'warning gen/stale-file-kept',
        ]);
        expect(r.platforms[0]!.keptStale).toEqual(['components/robot.py']);
        expect(r.platforms[0]!.removed).toEqual(['components/sensor.py']);
        expect(readFileSync(w.out('alpha/components/robot.py'), 'utf8')).toBe(before['alpha/components/robot.py']);

        // A region that holds user content and that the generator no longer emits.
        w.rec.fewer = false;
        await w.generate({ platforms: ['alpha'] });
        const ctrl = readFileSync(w.out('alpha/components/ctrl.py'), 'utf8');
        writeFileSync(w.out('alpha/components/ctrl.py'), ctrl.replace('# your code here', 'KEEP = 1').replace(/extra/g, 'mine'));
        const mid = snapshot(w.out());
        const again = await w.generate({ platforms: ['alpha'] });
        expect(again.ok).toBe(false);
        expect(errors(again)).toEqual([expect.stringContaining("gen/protected-region-dropped Platform 'alpha':")]);
        expect(errors(again)[0]).toContain("has user content in protected region 'mine'");
        expect(snapshot(w.out())).toEqual(mid);
    });

    test.each([
        ['../escape.py', "writes '../escape.py', which leaves the output folder"],
        ['/etc/passwd', "writes '/etc/passwd': output paths are relative"],
        ['types.py', "generator 't.Components' writes 'types.py', which generator 't.DataTypes' has already written"],
    ])('rejects the output path %s', async (bad, message) => {
        const w = workspace();
        w.rec.badPath = bad;
        const r = await w.generate({ platforms: ['alpha'] });
        expect(r.ok).toBe(false);
        expect(errors(r)).toEqual([expect.stringContaining(`gen/invalid-output`)]);
        expect(errors(r)[0]).toContain(message);
        expect(existsSync(w.out())).toBe(false);
    });
});

describe('write failures', () => {
    test('gen/write-failed names the path as displayPath shows it, and nothing changes', async () => {
        const w = workspace();
        expect((await w.generate({ platforms: ['alpha'] })).ok).toBe(true);
        const before = snapshot(w.out());
        w.write('models/robot/Filter.arc', MODELS['robot/Filter.arc']!.replace('raw / 2', 'raw / 5'));
        // The user put a file where generated files need a folder.
        rmSync(w.out('alpha/components/filter.py'));
        const components = readFileSync(w.out('alpha/components/ctrl.py'), 'utf8');
        rmSync(w.out('alpha/components'), { recursive: true });
        writeFileSync(w.out('alpha/components'), components);
        const blocked = snapshot(w.out());
        const r = await w.generate({ platforms: ['alpha'], displayPath: (p) => path.relative(w.dir, p) });
        expect(r.ok).toBe(false);
        expect(errors(r)).toEqual([
            `App.arcapp:1 gen/write-failed Cannot write the output: ${path.join('out', 'alpha', 'components')}: is a file where generated files need a folder. Nothing was changed.`,
        ]);
        expect(snapshot(w.out())).toEqual(blocked);
        expect(blocked).not.toEqual(before);
    });
});

describe('checks before generation', () => {
    test('configuration problems of the selected platform stop generation before any generator runs', async () => {
        const w = workspace({
            ...MODELS,
            'App.arcapp': MODELS['App.arcapp']!.replace(
                '    t.Automata;\n    t.DataTypes;\n  }\n  platform beta',
                '    t.DataTypes;\n  }\n  platform beta',
            ),
        });
        const r = await w.generate({ platforms: ['alpha'] });
        expect(errors(r)).toEqual([
            expect.stringMatching(
                /^App\.arcapp:2 app\/uncovered-behavior-language Platform 'alpha' has no generator for the behavior language 'automaton' \(used by robot\.Ctrl\)/,
            ),
        ]);
        expect(w.rec.log).toEqual([]);
        // The other platform is fine.
        expect((await w.generate({ platforms: ['beta'] })).ok).toBe(true);
    });

    test('errors in the models stop generation; problems of other files of the root do not', async () => {
        const w = workspace({ ...MODELS, 'other/Broken.arc': 'package other;\ncomponent Broken {' });
        expect((await w.generate({ platforms: ['alpha'] })).ok).toBe(true);
        w.write('models/robot/Ctrl.arc', MODELS['robot/Ctrl.arc']!.replace('state Busy;', 'state Busy;\n    Busy -> Nowhere;'));
        const r = await w.generate({ platforms: ['alpha'] });
        expect(r.ok).toBe(false);
        expect(errors(r)).toEqual([expect.stringMatching(/^Ctrl\.arc:12 automaton\/missing-state/)]);
    });

    test('a violated standard rule is reported on the model element, naming the generator', async () => {
        const manifests = MANIFESTS.map((m) => (m.name === 't.Components' ? { ...m, checks: ['components.NoInheritance'] } : m));
        const w = workspace(
            {
                ...MODELS,
                'robot/Base.arc': 'package robot;\n\ncomponent Base { }\n',
                'robot/Sensor.arc': MODELS['robot/Sensor.arc']!.replace('Sensor {', 'Sensor extends Base {'),
            },
            manifests,
        );
        const r = await w.generate({ platforms: ['alpha'] });
        expect(errors(r)).toEqual([
            "Sensor.arc:3 app/generator-rule-violated Generator 't.Components' requires components.NoInheritance (component types extend no other component type), but component type 'robot.Sensor' extends robot.Base.",
        ]);
        expect(w.rec.log).toEqual([]);
    });

    test('rules defined by the generator code are checked after loading it; unknown rules are errors', async () => {
        const manifests = MANIFESTS.map((m) => (m.name === 't.Automata' ? { ...m, checks: ['t.NoBusyState', 't.Unknown'] } : m));
        const w = workspace(MODELS, manifests);
        const modules = (await import('./test-generators.js')).createGenerators(w.rec);
        const automata = modules['automata.js']!;
        modules['automata.js'] = (i) => ({
            ...(automata(i) as object),
            rules: [
                {
                    name: 't.NoBusyState',
                    description: 'No state is called Busy.',
                    *check(scope: { behaviors: ReadonlyArray<{ node: { elements: Array<{ $type: string; name?: string }> } }> }) {
                        for (const b of scope.behaviors) {
                            for (const s of b.node.elements) if (s.name === 'Busy') yield { node: s, message: 'there is a state Busy' };
                        }
                    },
                },
            ],
        });
        const r = await w.generate({ platforms: ['alpha'] }, modules);
        expect(errors(r)).toEqual([
            "App.arcapp:4 gen/unknown-check Generator 't.Automata' declares the check 't.Unknown', which neither the standard rules nor the generator define.",
            "Ctrl.arc:11 app/generator-rule-violated Generator 't.Automata' requires t.NoBusyState (no state is called Busy), but there is a state Busy.",
        ]);
        expect(w.rec.log).toEqual([]);
    });

    test('generators that cannot be loaded are reported on their reference', async () => {
        const w = workspace();
        const modules = (await import('./test-generators.js')).createGenerators(w.rec);
        modules['datatypes.js'] = () => ({
            kind: 'component',
            generate() {
                /* wrong kind */
            },
        });
        modules['automata.js'] = () => ({ nothing: true });
        const r = await w.generate({ platforms: ['alpha'] }, modules);
        expect(errors(r)).toEqual([
            "App.arcapp:4 gen/load-failed Generator 't.Automata' (package test-gens) cannot be loaded: its export 'default' is not a generator (an object with a generate function, or a function returning one)",
            "App.arcapp:5 gen/load-failed Generator 't.DataTypes' (package test-gens) cannot be loaded: its code implements a component generator, but its manifest declares kind 'datatype'",
        ]);
    });

    test('without a loader hook, generators are imported from their package (entry relative to the package)', async () => {
        const w = workspace();
        w.write(
            'gens/datatypes.js',
            'export default { kind: "datatype", generate(ctx) { ctx.out.file("dt.txt").line("types: " + ctx.dataTypes.map((t) => t.name).join(",")); } };\n',
        );
        w.write(
            'gens/automata.js',
            'export function create() { return { generate(b, ctx) { ctx.out.file("a.txt").line(b.language); return { ok: "yes" }; } }; }\n',
        );
        w.write(
            'gens/components.js',
            'export default () => ({ async generate(ctx) { for (const c of ctx.architecture.components) { const d = await ctx.behavior(c); ctx.out.file(c.name + ".txt").line(d ? d.handledBy : "none"); } } });\n',
        );
        w.manifests = MANIFESTS.map((m) => (m.name === 't.Automata' ? { ...m, export: 'create' } : m));
        const r = await w.generate({ platforms: ['alpha'], loadModule: undefined });
        expect(errors(r)).toEqual([]);
        expect(readFileSync(w.out('alpha/dt.txt'), 'utf8')).toBe('types: Mode\n');
        expect(readFileSync(w.out('alpha/Ctrl.txt'), 'utf8')).toBe('behavior-generator\n');
        expect(readFileSync(w.out('alpha/Filter.txt'), 'utf8')).toBe('component-generator\n');
        expect(readFileSync(w.out('alpha/Sensor.txt'), 'utf8')).toBe('none\n');
    });
});
