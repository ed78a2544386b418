import { AstUtils, URI } from 'langium';
import { describe, expect, test } from 'vitest';
import {
    APP_DIAGNOSTICS,
    DEMO_GENERATOR_MANIFESTS,
    generatorDefinition,
    GeneratorRegistry,
    isGeneratorDeclarationNode,
    type appAst,
} from '../src/index.js';
import { DEMO_REGISTRY, dump, services, validate } from './helpers.js';

const entry = (code: string) => APP_DIAGNOSTICS.entries.find((e) => e.code === code)!;

describe('app checks', () => {
    test('a violated rule names the generator, the rule and the model element (message and related information)', async () => {
        const found = await validate(entry('app/generator-rule-violated').invalid.files);
        expect(found).toHaveLength(1);
        expect(found[0]!.message).toBe(
            "Generator 'py.FlatAutomata' requires automata.Flat (automata have no hierarchical states), but state 'Driving' of 'robot.Robot' is hierarchical (Robot.arc:8).",
        );
        expect(found[0]!.related).toEqual(["Robot.arc:8 violates automata.Flat of generator 'py.FlatAutomata'"]);
    });

    test('a GPL mismatch is not reported again as an RTE mismatch', async () => {
        const files = entry('app/gpl-mismatch').invalid.files;
        const found = await validate(files);
        expect(found.map((f) => f.code)).toEqual(['app/gpl-mismatch']);
        expect(found[0]!.message).toBe(
            "Generator 'java.Automata' produces java, but 'py.Components' produces python: all generators of platform 'python' must produce the same language.",
        );
    });

    test('with an unresolved component only the roles are checked', async () => {
        const found = await validate({ 'App.arcapp': 'application App for robot.Nothing {\n  platform p {\n    py.Automata;\n  }\n}' });
        expect(found.map((f) => `${f.code}@${f.text}`).sort()).toEqual([
            'app/missing-component-generator@p',
            'app/missing-datatype-generator@p',
            'app/unknown-component@robot.Nothing',
        ]);
    });

    test('an empty registry makes every generator unknown, and nothing else', async () => {
        const files = entry('app/unknown-generator').valid.files;
        const found = await validate(files, GeneratorRegistry.EMPTY);
        expect(found.map((f) => `${f.code}@${f.text}`)).toEqual([
            'app/unknown-generator@py.Components',
            'app/unknown-generator@py.Automata',
            'app/unknown-generator@py.DataTypes',
        ]);
    });

    test('the role and compatibility checks of a platform report each problem once, in order, with its message', async () => {
        const files = entry('app/rte-mismatch').valid.files;
        const generators = [
            'py.Components',
            'py.TracingComponents',
            'py.Components',
            'py.DataTypes',
            'py.Dataclasses',
            'py.Automata',
            'py.LegacyAutomata',
            'java.Automata',
        ];
        const appText = [
            'application App for robot.Robot {',
            '  platform p {',
            ...generators.map((g) => `    ${g};`),
            '  }',
            '  platform q {',
            '    py.DataTypes;',
            '  }',
            '  platform r {',
            '    py.Components;',
            '  }',
            '}',
        ].join('\n');
        const found = await validate({ ...files, 'App.arcapp': appText });
        const behaviors = "('py.Automata', 'py.LegacyAutomata', 'java.Automata')";
        expect(found.map((f) => `${f.severity} ${f.code}@${f.text}: ${f.message}`)).toEqual([
            "warning app/repeated-generator@py.Components: Generator 'py.Components' is listed more than once in platform 'p'.",
            "error app/duplicate-component-generator@py.TracingComponents: Platform 'p' has more than one component generator ('py.Components', 'py.TracingComponents'); keep exactly one.",
            "error app/duplicate-datatype-generator@py.Dataclasses: Platform 'p' has more than one data type generator ('py.DataTypes', 'py.Dataclasses'); keep exactly one.",
            `error app/duplicate-behavior-generator@py.LegacyAutomata: Platform 'p' has more than one behavior generator for 'automaton' ${behaviors}; keep exactly one.`,
            `error app/duplicate-behavior-generator@java.Automata: Platform 'p' has more than one behavior generator for 'automaton' ${behaviors}; keep exactly one.`,
            "error app/gpl-mismatch@java.Automata: Generator 'java.Automata' produces java, but 'py.Components' produces python: all generators of platform 'p' must produce the same language.",
            "error app/rte-mismatch@py.LegacyAutomata: Behavior generator 'py.LegacyAutomata' writes against the run-time environment 'legacy-rte', but component generator 'py.Components' wraps 'py-rte'.",
            "error app/missing-component-generator@q: Platform 'q' has no component generator: add one (e.g. 'py.Components').",
            "error app/missing-datatype-generator@r: Platform 'r' has no data type generator: add one (e.g. 'py.DataTypes').",
            "error app/uncovered-behavior-language@r: Platform 'r' has no generator for the behavior language 'automaton' (used by robot.Robot): add a behavior generator for 'automaton' (installed: 'java.Automata', 'py.Automata', 'py.FlatAutomata', 'py.LegacyAutomata').",
        ]);
    });

    test('every prefix of a configuration is checked without a failing check', async () => {
        const files = entry('app/generator-rule-violated').invalid.files;
        const text = files['App.arcapp']!;
        for (let i = 0; i <= text.length; i += 3) {
            const found = await validate({ ...files, 'App.arcapp': text.substring(0, i) }, DEMO_REGISTRY);
            expect(
                found.filter((f) => f.code.startsWith('internal/')),
                dump(found),
            ).toEqual([]);
        }
    });
});

describe('names in configurations', () => {
    test('generator and component references resolve, and their scopes offer the candidates for completion', async () => {
        await validate(entry('app/unknown-generator').valid.files);
        const s = services();
        const doc = s.shared.workspace.LangiumDocuments.all
            .filter((d) => d.uri.path.endsWith('.arcapp'))
            .toArray()
            .pop()!;
        const app = (doc.parseResult.value as appAst.ArcAppModel).application!;
        expect(app.component.ref?.name).toBe('Robot');
        const ref = AstUtils.streamAllContents(app).find((n): n is appAst.AppGeneratorRef => n.$type === 'AppGeneratorRef')!;
        const target = ref.generator.ref;
        expect(isGeneratorDeclarationNode(target)).toBe(true);
        if (!isGeneratorDeclarationNode(target)) return;
        expect(target.generator.manifest.kind).toBe('component');
        expect((target as unknown as { $comment: string }).$comment).toContain('component generator');
        const arcapp = s.languages.get('arcapp')!;
        const generators = arcapp.references.ScopeProvider.getScope({ container: ref, property: 'generator', reference: ref.generator })
            .getAllElements()
            .map((d) => d.name)
            .toArray();
        expect(generators).toEqual(DEMO_GENERATOR_MANIFESTS.map((m) => m.name).sort());
        const components = arcapp.references.ScopeProvider.getScope({ container: app, property: 'component', reference: app.component })
            .getAllElements()
            .map((d) => d.name)
            .toArray();
        expect(components).toContain('robot.Robot');
        expect(URI.parse(ref.generator.$nodeDescription!.documentUri.toString()).scheme).toBe('maa-generator');
    });

    test("go-to-definition target: the manifest's name in its file", () => {
        const r = GeneratorRegistry.fromManifests(DEMO_GENERATOR_MANIFESTS, 'demo', '/d');
        const node = { $type: 'GeneratorDeclaration', name: 'py.Automata', generator: r.get('py.Automata')! } as const;
        const text = '{\n  "maa": { "generators": [\n    { "name": "py.Automata", "kind": "behavior" }\n  ] }\n}\n';
        expect(generatorDefinition(node as never, text).range).toEqual({
            start: { line: 2, character: 15 },
            end: { line: 2, character: 26 },
        });
    });
});
