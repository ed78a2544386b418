import { existsSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { AstUtils } from 'langium';
import { NodeFileSystem } from 'langium/node';
import { afterEach, describe, expect, test } from 'vitest';
import type { GenerateOptions, GenerationDiagnostic } from '../src/node.js';
import { GenerateInputError, TRACE_FILE } from '../src/node.js';
import { createRun, type GenerationRun, type StageResult } from '../src/orchestrator/run.js';
import { check } from '../src/orchestrator/stages/check.js';
import { configure } from '../src/orchestrator/stages/configure.js';
import { generateFiles } from '../src/orchestrator/stages/generate.js';
import { load, type Loaded } from '../src/orchestrator/stages/load.js';
import { select } from '../src/orchestrator/stages/select.js';
import { write } from '../src/orchestrator/stages/write.js';
import { createTestFamily } from './helpers.js';
import { createGenerators, MANIFESTS, MODELS, Workspace } from './test-generators.js';

/**
 * Each stage of the generation pipeline (src/orchestrator/stages/) on its own: with a valid input
 * it returns its product, with an invalid one a failure with the diagnostics that stop generation.
 */
let spaces: Workspace[] = [];
afterEach(() => {
    for (const w of spaces) w.dispose();
    spaces = [];
});

function workspace(files: Record<string, string> = MODELS, manifests: unknown[] = MANIFESTS): Workspace {
    const w = new Workspace(files, manifests);
    spaces.push(w);
    return w;
}

function runOf(w: Workspace, options: Partial<GenerateOptions> = {}): GenerationRun {
    const modules = createGenerators(w.rec);
    const appFile = path.join(w.models, 'App.arcapp');
    return createRun(
        {
            services: createTestFamily(NodeFileSystem),
            appFile,
            outDir: path.join(w.dir, 'out'),
            registry: w.registry(),
            loadModule: async (url) => {
                const base = url.substring(url.lastIndexOf('/') + 1);
                if (!(base in modules)) throw new Error(`no test module ${base}`);
                return { default: modules[base] };
            },
            ...options,
        },
        appFile,
        w.models,
    );
}

function value<T>(r: StageResult<T>): T {
    if (!r.ok) throw new Error(`stage failed: ${codes(r.diagnostics).join(', ')}`);
    return r.value;
}

function codes(ds: readonly GenerationDiagnostic[]): string[] {
    return ds.filter((d) => d.severity === 'error').map((d) => `${path.basename(d.file)}:${d.line} ${d.code}`);
}

/** The stages up to (and with) check. */
async function checked(w: Workspace, options: Partial<GenerateOptions> = {}) {
    const run = runOf(w, options);
    const loaded = value(await load(run));
    return { run, loaded, checked: value(check(run, loaded)) };
}

async function configured(w: Workspace, options: Partial<GenerateOptions> = {}) {
    const c = await checked(w, options);
    const selected = value(select(c.loaded, c.checked));
    return { ...c, selected, configured: value(await configure(c.run, c.checked, selected)) };
}

function withApp(text: string): Record<string, string> {
    return { ...MODELS, 'App.arcapp': text };
}

describe('load', () => {
    test('loads the model root and finds the application; the registry service holds the generators', async () => {
        const w = workspace();
        const run = runOf(w);
        const loaded: Loaded = value(await load(run));
        expect(loaded.app.name).toBe('Demo');
        expect(loaded.registry.all().map((g) => g.manifest.name)).toEqual(['t.Automata', 't.Components', 't.DataTypes']);
        expect(loaded.arcApp.generators.Registry.registryFor(AstUtils.getDocument(loaded.app).uri)).toBe(loaded.registry);
        expect(codes(loaded.found)).toEqual([]);
    });

    test('a configuration without an application is a failure (gen/no-application)', async () => {
        const w = workspace(withApp('// nothing configured yet\n'));
        const r = await load(runOf(w));
        expect(r.ok).toBe(false);
        expect(codes(r.diagnostics)).toEqual(['App.arcapp:1 gen/no-application']);
    });
});

describe('check', () => {
    test('checks the application once: the architecture and the findings are those of its analysis', async () => {
        const w = workspace();
        const run = runOf(w, { platforms: ['alpha'] });
        const loaded = value(await load(run));
        const analyzer = loaded.arcApp.generators.Applications;
        // The document validator analyzed the application while loading; the check stage reuses it.
        const analysis = analyzer.analyze(loaded.app);
        const result = value(check(run, loaded));
        expect(result.platforms.map((p) => p.name)).toEqual(['alpha']);
        expect(result.architecture).toBe(analysis.architecture);
        expect(analyzer.analyze(loaded.app)).toBe(analysis);
        expect(result.architecture.root.qualifiedName).toBe('robot.Robot');
    });

    test('a platform without a data type generator is a failure; the other platform is not reported', async () => {
        const app = MODELS['App.arcapp']!.replace(/(platform alpha \{[^}]*?)\s+t\.DataTypes;/, '$1').replace(
            'platform beta {',
            'platform beta {\n    t.Unknown;',
        );
        const w = workspace(withApp(app));
        const run = runOf(w, { platforms: ['alpha'] });
        const r = check(run, value(await load(run)));
        expect(r.ok).toBe(false);
        expect(codes(r.diagnostics)).toEqual(['App.arcapp:2 app/missing-datatype-generator']);
    });

    test('an unknown platform is an input error', async () => {
        const w = workspace();
        const run = runOf(w, { platforms: ['gamma'] });
        const loaded = value(await load(run));
        expect(() => check(run, loaded)).toThrow(GenerateInputError);
    });
});

describe('select', () => {
    test('sorts the generators of each platform into their roles', async () => {
        const w = workspace();
        const c = await checked(w);
        const { selections } = value(select(c.loaded, c.checked));
        expect([...selections.keys()].map((p) => p.name)).toEqual(['alpha', 'beta']);
        const alpha = [...selections.values()][0]!;
        expect(alpha.component?.manifest.name).toBe('t.Components');
        expect(alpha.datatype?.manifest.name).toBe('t.DataTypes');
        expect([...alpha.behaviors].map(([l, g]) => `${l}: ${g.manifest.name}`)).toEqual(['automaton: t.Automata']);
    });

    test('leaves out a name the registry does not know (the check stage reports it)', async () => {
        const w = workspace(withApp(MODELS['App.arcapp']!.replace('platform beta {', 'platform beta {\n    t.Unknown;')));
        const run = runOf(w, { platforms: ['alpha'] });
        const loaded = value(await load(run));
        const c = value(check(run, loaded));
        const beta = loaded.app.platforms.find((p) => p.name === 'beta')!;
        const { selections } = value(select({ ...loaded }, { ...c, platforms: [beta] }));
        expect(selections.get(beta)!.references.map((r) => r.generator.manifest.name)).toEqual([
            't.Components',
            't.Automata',
            't.DataTypes',
        ]);
    });
});

describe('configure', () => {
    test('instantiates each selected generator once', async () => {
        const w = workspace();
        const { configured: result } = await configured(w);
        expect([...result.instances.keys()].sort()).toEqual(['t.Automata', 't.Components', 't.DataTypes']);
        expect(result.instances.get('t.Components')!.generator.kind).toBe('component');
    });

    test('a generator that cannot be loaded is a failure (gen/load-failed)', async () => {
        const w = workspace();
        const c = await checked(w, { platforms: ['alpha'], loadModule: async () => ({}) });
        const r = await configure(c.run, c.checked, value(select(c.loaded, c.checked)));
        expect(r.ok).toBe(false);
        expect(codes(r.diagnostics)).toEqual([
            'App.arcapp:3 gen/load-failed',
            'App.arcapp:4 gen/load-failed',
            'App.arcapp:5 gen/load-failed',
        ]);
    });

    test('a check that neither the standard rules nor the generator define is a failure (gen/unknown-check)', async () => {
        const manifests = MANIFESTS.map((m) =>
            m.name === 't.DataTypes' ? { ...m, checks: ['datatypes.NoGenerics', 'datatypes.Nonexistent'] } : m,
        );
        const w = workspace(MODELS, manifests);
        const c = await checked(w, { platforms: ['alpha'] });
        const r = await configure(c.run, c.checked, value(select(c.loaded, c.checked)));
        expect(r.ok).toBe(false);
        expect(codes(r.diagnostics)).toEqual(['App.arcapp:5 gen/unknown-check']);
    });
});

describe('generate', () => {
    test('generates the files of every platform in memory, writing nothing', async () => {
        const w = workspace();
        const c = await configured(w, { platforms: ['alpha'] });
        const { outputs } = value(await generateFiles(c.run, c.loaded, c.checked, c.selected, c.configured));
        expect(outputs.map((o) => o.platform.name)).toEqual(['alpha']);
        expect(outputs[0]!.files.map((f) => f.path)).toContain('components/ctrl.py');
        expect(existsSync(w.out())).toBe(false);
    });

    test('a generator that throws is a failure (gen/generator-failed)', async () => {
        const w = workspace();
        w.rec.failIn = 'components';
        const c = await configured(w, { platforms: ['alpha'] });
        const r = await generateFiles(c.run, c.loaded, c.checked, c.selected, c.configured);
        expect(r.ok).toBe(false);
        expect(codes(r.diagnostics)).toEqual(['App.arcapp:3 gen/generator-failed']);
    });
});

describe('write', () => {
    test('writes every platform with its trace file', async () => {
        const w = workspace();
        const c = await configured(w, { platforms: ['alpha'] });
        const generated = value(await generateFiles(c.run, c.loaded, c.checked, c.selected, c.configured));
        const platforms = value(write(c.run, c.loaded, c.checked, c.selected, c.configured, generated));
        expect(platforms.map((p) => [p.platform, p.written.length])).toEqual([['alpha', 7]]);
        expect(readFileSync(w.out('alpha/components/robot.py'), 'utf8')).toContain('# robot.Robot');
        expect(JSON.parse(readFileSync(w.out(`alpha/${TRACE_FILE}`), 'utf8'))).toMatchObject({ application: 'Demo', platform: 'alpha' });
    });

    test('an output that cannot be written is a failure (gen/write-failed), and nothing is written', async () => {
        const w = workspace();
        w.write('out/alpha', 'a file where the platform folder belongs\n');
        const c = await configured(w, { platforms: ['alpha'] });
        const generated = value(await generateFiles(c.run, c.loaded, c.checked, c.selected, c.configured));
        const r = write(c.run, c.loaded, c.checked, c.selected, c.configured, generated);
        expect(r.ok).toBe(false);
        expect(codes(r.diagnostics)).toEqual(['App.arcapp:1 gen/write-failed']);
        expect(readFileSync(w.out('alpha'), 'utf8')).toBe('a file where the platform folder belongs\n');
    });
});
