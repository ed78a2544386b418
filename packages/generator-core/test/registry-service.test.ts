import { ModelTestBench } from '@maa/language-adl/testing';
import { describe, expect, test } from 'vitest';
import { APP_DIAGNOSTICS, arcAppServices, configureGeneratorRegistry, GeneratorRegistry, generatorRegistryFor } from '../src/index.js';
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
});
