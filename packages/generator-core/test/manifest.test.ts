import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { URI } from 'langium';
import { NodeFileSystemProvider } from 'langium/node';
import { afterEach, describe, expect, test } from 'vitest';
import { discoverGenerators, GeneratorRegistry, installationRoot, ManifestError, validateManifest } from '../src/index.js';

const VALID = {
    component: {
        name: 'ros2.Components',
        kind: 'component',
        supports: ['compute'],
        output: { gpl: 'python', rte: 'maa-python-behavior' },
        entry: 'dist/c.js',
    },
    behavior: {
        name: 'ros2.AutomataBehavior',
        kind: 'behavior',
        language: 'automaton',
        output: { gpl: 'python', rte: 'maa-python-behavior' },
        checks: ['automata.Flat'],
        entry: 'dist/a.js',
        requires: ['ports', 'package'],
    },
    datatype: {
        name: 'ros2.DataTypes',
        kind: 'datatype',
        output: { gpl: 'python' },
        checks: ['datatypes.NoGenerics'],
        entry: 'dist/d.js',
        templates: 'templates/datatypes',
    },
};

function problem(json: unknown): string {
    try {
        validateManifest(json, { packageName: 'my-gens', file: '/x/package.json', field: 'maa.generators[1]' });
    } catch (e) {
        expect(e).toBeInstanceOf(ManifestError);
        return (e as Error).message;
    }
    throw new Error('the manifest was accepted');
}

describe('manifest validation', () => {
    test('accepts the three kinds and applies defaults', () => {
        const c = validateManifest(VALID.component, { packageName: 'p', file: 'f', field: '' });
        expect(c.kind).toBe('component');
        expect(c.checks).toEqual([]);
        expect(c.requires).toEqual([]);
        const d = validateManifest(VALID.datatype, { packageName: 'p', file: 'f', field: '' });
        expect(d.kind === 'datatype' && d.templates).toBe('templates/datatypes');
        const b = validateManifest(VALID.behavior, { packageName: 'p', file: 'f', field: '' });
        expect(b.kind === 'behavior' && b.language).toBe('automaton');
    });

    test.each([
        ['a missing field', { ...VALID.component, entry: undefined }, "maa.generators[1]: missing required field 'entry'"],
        [
            'an unknown kind',
            { ...VALID.component, kind: 'platform' },
            'maa.generators[1].kind: must be one of "component", "behavior", "datatype"',
        ],
        ['a name that is not qualified', { ...VALID.component, name: 'ros2 Components' }, 'maa.generators[1].name: must match pattern'],
        [
            'a behavior generator without language',
            { ...VALID.behavior, language: undefined },
            "maa.generators[1]: missing required field 'language'",
        ],
        [
            'a behavior generator without RTE',
            { ...VALID.behavior, output: { gpl: 'python' } },
            "maa.generators[1].output: missing required field 'rte'",
        ],
        [
            'a component generator without RTE',
            { ...VALID.component, output: { gpl: 'python' } },
            "maa.generators[1].output: missing required field 'rte'",
        ],
        [
            'a component generator with a language',
            { ...VALID.component, language: 'automaton' },
            'maa.generators[1].language: is not allowed for a component generator',
        ],
        [
            'a data type generator with supports',
            { ...VALID.datatype, supports: ['compute'] },
            'maa.generators[1].supports: is not allowed for a datatype generator',
        ],
        ['an unknown field', { ...VALID.datatype, entrypoint: 'x.js' }, "maa.generators[1]: unknown field 'entrypoint'"],
        ['a wrongly typed field', { ...VALID.datatype, checks: 'datatypes.NoGenerics' }, 'maa.generators[1].checks: must be array'],
        ['a bad check name', { ...VALID.datatype, checks: ['no generics'] }, 'maa.generators[1].checks[0]: must match pattern'],
        [
            'an unknown context requirement',
            { ...VALID.behavior, requires: ['ports', 'everything'] },
            'maa.generators[1].requires[1]: must be one of',
        ],
        ['an empty GPL', { ...VALID.datatype, output: { gpl: '' } }, 'maa.generators[1].output.gpl: must NOT have fewer than 1 characters'],
        ['not an object', 'ros2.Components', 'maa.generators[1]: must be object'],
    ])('reports %s, naming the package and the field', (_what, json, expected) => {
        const message = problem(JSON.parse(JSON.stringify(json)) as unknown);
        expect(message).toContain('generator package my-gens (/x/package.json): ');
        expect(message).toContain(expected);
    });
});

describe('discovery from installed packages', () => {
    let dir: string;
    const fs = new NodeFileSystemProvider();
    const write = (rel: string, content: unknown): void => {
        const file = path.join(dir, rel);
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, typeof content === 'string' ? content : JSON.stringify(content, null, 2));
    };
    afterEach(() => rmSync(dir, { recursive: true, force: true }));

    function setup(): void {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-discovery-'));
    }

    test("finds inline manifests and manifest files, in plain and scoped packages, and the project's own", () => {
        setup();
        write('node_modules/ros2-gens/package.json', {
            name: 'ros2-gens',
            version: '1.2.3',
            maa: { generators: [VALID.component, 'manifests/automata.json'] },
        });
        write('node_modules/ros2-gens/manifests/automata.json', VALID.behavior);
        write('node_modules/@acme/types/package.json', { name: '@acme/types', maa: { generators: [VALID.datatype] } });
        write('node_modules/unrelated/package.json', { name: 'unrelated', version: '1.0.0' });
        write('package.json', { name: 'project', maa: { generators: [{ ...VALID.datatype, name: 'local.DataTypes' }] } });
        const registry = discoverGenerators(fs, URI.file(path.join(dir, 'models', 'deep')), { extraRoots: [] });
        expect(registry.problems.map((p) => p.message)).toEqual([]);
        expect(registry.all().map((g) => `${g.manifest.name} ${g.source.packageName}`)).toEqual([
            'local.DataTypes project',
            'ros2.AutomataBehavior ros2-gens',
            'ros2.Components ros2-gens',
            'ros2.DataTypes @acme/types',
        ]);
        const automata = registry.get('ros2.AutomataBehavior')!;
        expect(automata.source.file).toBe(path.join(dir, 'node_modules/ros2-gens/manifests/automata.json'));
        expect(automata.source.packageVersion).toBe('1.2.3');
        expect(automata.source.packageDir).toBe(path.join(dir, 'node_modules/ros2-gens'));
    });

    test('a nearer package shadows a farther one of the same name', () => {
        setup();
        write('node_modules/gens/package.json', { name: 'gens', version: '1.0.0', maa: { generators: [VALID.datatype] } });
        write('app/node_modules/gens/package.json', { name: 'gens', version: '2.0.0', maa: { generators: [VALID.datatype] } });
        const registry = discoverGenerators(fs, URI.file(path.join(dir, 'app')), { extraRoots: [] });
        expect(registry.problems).toEqual([]);
        expect(registry.get('ros2.DataTypes')!.source.packageVersion).toBe('2.0.0');
    });

    test('invalid declarations become problems naming package and field; valid ones still load', () => {
        setup();
        write('node_modules/bad-array/package.json', { name: 'bad-array', maa: { generators: { name: 'x' } } });
        write('node_modules/bad-item/package.json', {
            name: 'bad-item',
            maa: { generators: [VALID.component, { ...VALID.behavior, kind: 'behaviour' }, 42] },
        });
        write('node_modules/bad-file/package.json', {
            name: 'bad-file',
            maa: { generators: ['missing.json', 'broken.json', '../escape.json'] },
        });
        write('node_modules/bad-file/broken.json', '{ "name": ');
        write('node_modules/dup/package.json', { name: 'dup', maa: { generators: [VALID.component] } });
        const registry = discoverGenerators(fs, URI.file(dir), { extraRoots: [] });
        const messages = registry.problems.map((p) => p.message.replace(dir, '<dir>'));
        expect(messages).toEqual([
            'generator package bad-array (<dir>/node_modules/bad-array/package.json): maa.generators: must be an array of manifests or manifest file paths',
            "generator package bad-file (<dir>/node_modules/bad-file/package.json): maa.generators[0]: cannot read manifest file 'missing.json'",
            expect.stringMatching(/^generator package bad-file \(<dir>\/node_modules\/bad-file\/broken.json\): invalid JSON/),
            "generator package bad-file (<dir>/node_modules/bad-file/package.json): maa.generators[2]: manifest file '../escape.json' lies outside the package",
            'generator package bad-item (<dir>/node_modules/bad-item/package.json): maa.generators[1].kind: must be one of "component", "behavior", "datatype"',
            'generator package bad-item (<dir>/node_modules/bad-item/package.json): maa.generators[2]: must be a manifest object or the path of a manifest file',
            "generator package dup (<dir>/node_modules/dup/package.json): maa.generators[0].name: generator 'ros2.Components' is already declared by package bad-item; this declaration is ignored",
        ]);
        expect(registry.all().map((g) => g.manifest.name)).toEqual(['ros2.Components']);
        expect(registry.problemsOf('bad-item')).toHaveLength(2);
    });

    test('by default, generators installed next to generator-core are found too', () => {
        setup();
        const registry = discoverGenerators(fs, URI.file(dir));
        const own = discoverGenerators(fs, URI.file(dir), { extraRoots: [] });
        expect(own.all()).toEqual([]);
        expect(registry.all().length).toBeGreaterThanOrEqual(own.all().length);
        expect(installationRoot()?.scheme).toBe('file');
    });

    test('a registry from given manifests validates them too', () => {
        const r = GeneratorRegistry.fromManifests([VALID.component, { ...VALID.datatype, output: {} }], 'tests');
        expect(r.all().map((g) => g.manifest.name)).toEqual(['ros2.Components']);
        expect(r.problems.map((p) => p.message)).toEqual([
            "generator package tests ((inline)): generators[1].output: missing required field 'gpl'",
        ]);
    });
});
