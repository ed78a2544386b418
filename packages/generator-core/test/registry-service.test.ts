import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { ModelTestBench } from '@maa/language-adl/testing';
import { URI } from 'langium';
import { NodeFileSystem } from 'langium/node';
import { describe, expect, test } from 'vitest';
import {
    APP_DIAGNOSTICS,
    arcAppServices,
    configureGeneratorRegistry,
    DEMO_GENERATOR_MANIFESTS,
    GeneratorRegistry,
    generatorRegistryFor,
} from '../src/index.js';
import { createTestFamily, DEMO_REGISTRY } from './helpers.js';

const files = APP_DIAGNOSTICS.entries.find((e) => e.code === 'app/unknown-generator')!.valid.files;

describe('the generator registry service', () => {
    test('is a service of each family: two families configured differently validate the same configuration differently', async () => {
        const a = new ModelTestBench(() => createTestFamily(), 'a');
        const b = new ModelTestBench(() => createTestFamily(), 'b');
        configureGeneratorRegistry(a.host.shared, DEMO_REGISTRY);
        arcAppServices(b.host.shared)!.generators.Registry.configure(GeneratorRegistry.EMPTY);
        const unknown = async (bench: ModelTestBench) =>
            (await bench.validate(files)).filter((f) => f.code === 'app/unknown-generator').map((f) => f.text);
        expect(await unknown(a)).toEqual([]);
        expect(await unknown(b)).toEqual(['py.Components', 'py.Automata', 'py.DataTypes']);
    });

    test('the .arcapp validator and generatorRegistryFor read the registry the service was configured with', async () => {
        const bench = new ModelTestBench(() => createTestFamily(), 'c');
        const service = arcAppServices(bench.host.shared)!.generators.Registry;
        service.configure(DEMO_REGISTRY);
        const { docs } = await bench.build(files);
        expect(generatorRegistryFor(bench.host.shared, docs[0]!.uri)).toBe(DEMO_REGISTRY);
        service.configure(() => GeneratorRegistry.EMPTY);
        expect(generatorRegistryFor(bench.host.shared, docs[0]!.uri)).toBe(GeneratorRegistry.EMPTY);
    });

    test('a family without the .arcapp language has no registry service', () => {
        const bench = new ModelTestBench(() => createTestFamily(), 'd');
        expect(arcAppServices(bench.host.shared)).toBeDefined();
        expect(() => configureGeneratorRegistry({ ...bench.host.shared, ServiceRegistry: { all: [] } } as never, DEMO_REGISTRY)).toThrow(
            /no \.arcapp language/,
        );
    });

    describe('discovery from installed packages, again after a workspace change', () => {
        /** A project folder; `install` puts a package declaring the demo generators into its node_modules. */
        function project(): { dir: string; app: URI; install(): void; remove(): void } {
            const dir = mkdtempSync(join(tmpdir(), 'maa-registry-'));
            return {
                dir,
                app: URI.file(join(dir, 'App.arcapp')),
                install() {
                    const pkg = join(dir, 'node_modules', 'demo-generators');
                    mkdirSync(pkg, { recursive: true });
                    const json = { name: 'demo-generators', version: '1.0.0', maa: { generators: DEMO_GENERATOR_MANIFESTS } };
                    writeFileSync(join(pkg, 'package.json'), JSON.stringify(json));
                },
                remove: () => rmSync(dir, { recursive: true, force: true }),
            };
        }

        async function afterInstallAndChange(rediscoverAfterMs: number): Promise<{ before: GeneratorRegistry; after: GeneratorRegistry }> {
            const p = project();
            try {
                const shared = createTestFamily(NodeFileSystem).shared;
                const service = arcAppServices(shared)!.generators.Registry;
                service.configure(undefined, { extraRoots: [], rediscoverAfterMs });
                const before = service.registryFor(p.app);
                p.install();
                await shared.workspace.DocumentBuilder.update([], []);
                return { before, after: service.registryFor(p.app) };
            } finally {
                p.remove();
            }
        }

        test('finds a generator installed since, once the last discovery is old enough', async () => {
            const { before, after } = await afterInstallAndChange(0);
            expect(before.all()).toEqual([]);
            expect(after.get('py.Components')?.source.packageName).toBe('demo-generators');
        });

        test('keeps a discovery younger than that across changes (typing does not read every package.json again)', async () => {
            const { before, after } = await afterInstallAndChange(60_000);
            expect(after).toBe(before);
            expect(after.get('py.Components')).toBeUndefined();
        });
    });
});
