import { EmptyFileSystem } from 'langium';
import { describe, expect, test } from 'vitest';
import { ModelTestBench } from '../src/testing/index.js';
import { configurationSpace, createAdlServices, elementsOf, withVariant, type ast } from '../src/index.js';
import { validate, type Finding } from './helpers.js';

const bench = new ModelTestBench(() => createAdlServices(EmptyFileSystem), 'variability');

function codes(found: Finding[]): string[] {
    return found.map((f) => f.code);
}

const SUB = `
  component Src {
    port out int o;
  }
  component Dst {
    port in int i;
  }`;

describe('variability: parsing and names', () => {
    test('features, constraints and varif with else and else-if parse and resolve', async () => {
        const found = await validate({
            'Foo.arc': `component Foo(boolean verbose) {
  feature fast, safe;
  constraint(!(fast && safe) || verbose);
  port out int o;${SUB}
  varif (fast) {
    Src s;
    s.o -> o;
  } else varif (safe) {
    Src s;
    s.o -> o;
  } else {
    port in int i;
    i -> o;
  }
}`,
        });
        expect(
            found.filter((f) => f.code.startsWith('syntax/') || f.code.startsWith('link/') || f.severity === 'error'),
            JSON.stringify(found),
        ).toEqual([]);
    });

    test('feature and constraint stay usable as names', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {
  port in int feature;
  port out int constraint;
  feature constraint2;
  compute {
    constraint = feature;
  }
}`,
        });
        expect(
            found.filter((f) => f.severity === 'error'),
            JSON.stringify(found),
        ).toEqual([]);
    });

    test('a feature of a subcomponent is named sub.f; an unknown one is not', async () => {
        const ok = await validate({
            'Foo.arc': `component Foo {\n  component In {\n    feature f;\n  }\n  In sub;\n  constraint(sub.f);\n}`,
        });
        expect(
            ok.filter((f) => f.severity === 'error'),
            JSON.stringify(ok),
        ).toEqual([]);
        const bad = await validate({
            'Foo.arc': `component Foo {\n  component In {\n    feature f;\n  }\n  In sub;\n  constraint(sub.g);\n}`,
        });
        expect(codes(bad)).toContain('expr/unresolved-name');
    });

    test('elementsOf: every variation point without a configuration, the selected branch with one', async () => {
        const { docs } = await bench.build({
            'Foo.arc': `component Foo {\n  feature f;\n  varif (f) {\n    port in int a;\n  } else {\n    port out int b;\n  }\n}`,
        });
        const c = (docs[0]!.parseResult.value as ast.ArcModel).component!;
        const ports = (): string[] => elementsOf(c).flatMap((e) => (e.$type === 'PortDeclaration' ? e.ports.map((p) => p.name) : []));
        expect(ports()).toEqual(['a', 'b']);
        const space = configurationSpace(c);
        expect(space.configurations.length).toBe(2);
        const seen = space.variants.map((a) => withVariant(space.env(a), ports).join(','));
        expect(seen.sort()).toEqual(['a', 'b']);
    });
});

describe('variability: constraints', () => {
    test('unsatisfiable own, parameter and instance constraints; satisfiable ones are fine', async () => {
        expect(codes(await validate({ 'Foo.arc': 'component Foo {\n  feature f;\n  constraint(f && !f);\n}' }))).toContain(
            'variability/constraint-unsatisfied',
        );
        expect(codes(await validate({ 'Foo.arc': 'component Foo(boolean p) {\n  constraint(p);\n  constraint(!p);\n}' }))).toContain(
            'variability/constraint-unsatisfied',
        );
        expect(
            codes(
                await validate({ 'Foo.arc': 'component Foo {\n  component In(boolean p) {\n    constraint(p);\n  }\n  In sub(false);\n}' }),
            ),
        ).toContain('variability/constraint-unsatisfied');
        expect(
            codes(
                await validate({ 'Foo.arc': 'component Foo {\n  component In(boolean p) {\n    constraint(p);\n  }\n  In sub(true);\n}' }),
            ),
        ).not.toContain('variability/constraint-unsatisfied');
        expect(codes(await validate({ 'Foo.arc': 'component Foo {\n  feature f, g;\n  constraint(f != g);\n}' }))).not.toContain(
            'variability/constraint-unsatisfied',
        );
    });

    test('inherited constraints and those of subcomponents of subcomponents count', async () => {
        const files = {
            'a/A.arc': 'package a;\ncomponent A {\n  feature ff;\n  constraint(ff);\n}',
            'a/C.arc': 'package a;\ncomponent C {\n  feature ff;\n  a.A b;\n  constraint(ff == b.ff);\n}',
            'a/D.arc': 'package a;\ncomponent D extends a.C {\n}',
        };
        expect(codes(await validate({ ...files, 'Foo.arc': 'component Foo {\n  a.D d;\n  constraint(!d.ff);\n}' }))).toContain(
            'variability/constraint-unsatisfied',
        );
        expect(codes(await validate({ ...files, 'Foo.arc': 'component Foo {\n  a.D d;\n  constraint(d.ff);\n}' }))).not.toContain(
            'variability/constraint-unsatisfied',
        );
    });

    test('subcomponent features must be fixed by the enclosing component', async () => {
        const inner = '\n  component In {\n    feature f;\n  }';
        expect(codes(await validate({ 'Foo.arc': `component Foo {${inner}\n  In b;\n}` }))).toContain(
            'variability/subcomponent-features-unconstrained',
        );
        expect(
            codes(await validate({ 'Foo.arc': `component Foo {\n  feature f;${inner}\n  In b;\n  constraint(!f || b.f);\n}` })),
        ).toContain('variability/subcomponent-features-unconstrained');
        expect(
            codes(
                await validate({
                    'Foo.arc': `component Foo {\n  feature f;${inner}\n  In b1, b2;\n  constraint(b1.f == b2.f && b2.f == f);\n}`,
                }),
            ),
        ).not.toContain('variability/subcomponent-features-unconstrained');
    });

    test('conditions: no assignments or increments, no method calls', async () => {
        expect(codes(await validate({ 'Foo.arc': 'component Foo(int p) {\n  constraint((p += 1) > 1);\n}' }))).toContain(
            'arc/assignment-in-argument',
        );
        expect(codes(await validate({ 'Foo.arc': 'component Foo(int p) {\n  varif (p++ > 0) { }\n}' }))).toContain(
            'arc/assignment-in-argument',
        );
        expect(codes(await validate({ 'Foo.arc': 'component Foo(int p) {\n  varif (Math.abs(p) > 0) { }\n}' }))).toContain(
            'variability/expression-not-checkable',
        );
        const fine = codes(
            await validate({ 'Foo.arc': 'component Foo(int p) {\n  feature f;\n  constraint(p > 0 || !f);\n  varif (f || !f) { }\n}' }),
        );
        expect(fine).not.toContain('arc/assignment-in-argument');
        expect(fine).not.toContain('variability/expression-not-checkable');
    });

    test('more than 16 deciding variables: one warning, checked with every variation point', async () => {
        const names = Array.from({ length: 17 }, (_, i) => `f${i}`).join(', ');
        expect(codes(await validate({ 'Foo.arc': `component Foo {\n  feature ${names};\n}` }))).toContain('variability/too-many-features');
    });

    test('duplicate features', async () => {
        expect(codes(await validate({ 'Foo.arc': 'component Foo {\n  feature f;\n  feature f;\n}' }))).toContain('arc/duplicate-name');
    });
});

describe('variability: structural checks hold in every configuration', () => {
    test('a direction error only in a selectable configuration is reported, with the configuration', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {\n  port in int i;\n  feature f;${SUB}\n  varif (f) {\n    Src s;\n    i -> s.o;\n  }\n}`,
        });
        const d = found.find((f) => f.code === 'arc/target-direction-mismatch');
        expect(d?.message).toContain('f = true');
    });

    test('a configuration the constraints exclude is not checked', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {\n  feature f;\n  constraint(!f);${SUB}\n  varif (f) {\n    port in int i;\n    Src s;\n    i -> s.o;\n  }\n}`,
        });
        expect(codes(found)).not.toContain('arc/target-direction-mismatch');
    });

    test('ports in both branches of a varif are no duplicates; the interface of a subcomponent follows its features', async () => {
        const files = {
            'a/D.arc':
                'package a;\ncomponent D {\n  feature ff;\n  varif (ff) {\n    port in int io;\n  } else {\n    port out int io;\n  }\n}',
        };
        const ok = await validate({
            ...files,
            'Foo.arc': 'component Foo {\n  port in int i;\n  a.D sub;\n  i -> sub.io;\n  constraint(sub.ff);\n}',
        });
        expect(
            codes(ok).filter((c) => c.startsWith('arc/') && c !== 'arc/naming-convention'),
            JSON.stringify(ok),
        ).toEqual([]);
        const bad = await validate({
            ...files,
            'Foo.arc': 'component Foo {\n  port in int i;\n  a.D sub;\n  i -> sub.io;\n  constraint(!sub.ff);\n}',
        });
        expect(codes(bad)).toContain('arc/target-direction-mismatch');
    });

    test('a port that a configuration lacks', async () => {
        const found = await validate({
            'a/M.arc': 'package a;\ncomponent M {\n  feature ff;\n  varif (ff) {\n    port in int i;\n  }\n}',
            'Foo.arc': `component Foo extends a.M {${SUB}\n  Dst sub;\n  i -> sub.i;\n}`,
        });
        expect(found.find((f) => f.code === 'arc/missing-port')?.message).toContain('ff = false');
    });

    test('behaviors in exclusive branches are no multiple behaviors; in overlapping ones they are', async () => {
        expect(
            codes(
                await validate({
                    'Foo.arc': 'component Foo {\n  feature f;\n  varif (f) {\n    compute { }\n  } else {\n    compute { }\n  }\n}',
                }),
            ),
        ).not.toContain('arc/multiple-behaviors');
        expect(
            codes(await validate({ 'Foo.arc': 'component Foo {\n  feature f;\n  varif (f) {\n    compute { }\n  }\n  compute { }\n}' })),
        ).toContain('arc/multiple-behaviors');
    });
});

describe('variability: feature bindings on instantiation', () => {
    const D = {
        'a/D.arc':
            'package a;\ncomponent D {\n  feature ff;\n  varif (ff) {\n    port in int io;\n  } else {\n    port out int io;\n  }\n}',
    };

    test('sub(ff = true) fixes the feature: no unconstrained feature, the interface of that configuration', async () => {
        const ok = await validate({ ...D, 'Foo.arc': 'component Foo {\n  port in int i;\n  a.D sub(ff = true);\n  i -> sub.io;\n}' });
        expect(
            codes(ok).filter(
                (c) => (c.startsWith('arc/') && c !== 'arc/naming-convention') || c.startsWith('variability/') || c.startsWith('link/'),
            ),
            JSON.stringify(ok),
        ).toEqual([]);
        const bad = await validate({ ...D, 'Foo.arc': 'component Foo {\n  port in int i;\n  a.D sub(ff = false);\n  i -> sub.io;\n}' });
        expect(codes(bad)).toContain('arc/target-direction-mismatch');
    });

    test('a binding needs a boolean, and an unknown key is still refused', async () => {
        expect(codes(await validate({ ...D, 'Foo.arc': 'component Foo {\n  a.D sub(ff = 1);\n}' }))).toContain(
            'arc/argument-type-mismatch',
        );
        expect(codes(await validate({ ...D, 'Foo.arc': 'component Foo {\n  a.D sub(gg = true);\n}' }))).toContain(
            'arc/unknown-argument-key',
        );
    });

    test("a binding may follow the enclosing component's own feature", async () => {
        const found = await validate({ ...D, 'Foo.arc': 'component Foo {\n  feature f;\n  a.D sub(ff = f);\n}' });
        expect(codes(found)).not.toContain('variability/subcomponent-features-unconstrained');
    });
});
