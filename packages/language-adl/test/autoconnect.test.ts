import { EmptyFileSystem } from 'langium';
import { describe, expect, test } from 'vitest';
import { ModelTestBench, hits } from '../src/testing/index.js';
import { createAdlServices, impliedConnectors, type ast } from '../src/index.js';
import { validate } from './helpers.js';

const bench = new ModelTestBench(() => createAdlServices(EmptyFileSystem), 'autoconnect');

/** The connectors a component's autoconnect implies, as `source -> target` strings. */
async function implied(text: string): Promise<string[]> {
    const { docs } = await bench.build({ 'Foo.arc': text });
    const c = (docs[0]!.parseResult.value as ast.ArcModel).component!;
    const name = (sub: { name: string } | undefined, port: string): string => (sub ? `${sub.name}.${port}` : port);
    return impliedConnectors(c).map((i) => `${name(i.source.sub, i.source.info.name)} -> ${name(i.target.sub, i.target.info.name)}`);
}

const INNER = `
  component Inc {
    port in int i;
    port out int o;
  }`;

describe('autoconnect: parsing', () => {
    test('port, type and off parse; type and off stay usable as names', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {
  port in int type;
  port out int off;
  int port2 = 0;${INNER}
  Inc inc;
  type -> inc.i;
  inc.o -> off;
  autoconnect off;
}`,
        });
        expect(
            found.filter((f) => f.severity === 'error'),
            JSON.stringify(found),
        ).toEqual([]);
    });

    test('an unknown autoconnect mode is a syntax error', async () => {
        const found = await validate({ 'Foo.arc': `component Foo {${INNER}\n  Inc inc;\n  autoconnect all;\n}` });
        expect(found.some((f) => f.code.startsWith('syntax/'))).toBe(true);
    });
});

describe('autoconnect: implied connectors', () => {
    test('port: same name and type, between the component and its subcomponents and between subcomponents', async () => {
        expect(
            await implied(`component Foo {
  port in int i;
  port out int o;
  component A { port in int i; port out int x; }
  component B { port in int x; port out int o; }
  A a;
  B b;
  autoconnect port;
}`),
        ).toEqual(['b.o -> o', 'i -> a.i', 'a.x -> b.x']);
    });

    test('port: a written connector wins, a different type or an ambiguous source implies nothing', async () => {
        expect(
            await implied(`component Foo {
  port in int i, in int j;
  port out String o;
  component A { port in int i; port in int j; port out int o; }
  component B { port in int i; port out int o; }
  A a;
  B b;
  j -> a.i;
  autoconnect port;
}`),
        ).toEqual(['j -> a.j', 'i -> b.i']);
    });

    test('type: the only source of the same type, whatever its name; int and Integer are one type', async () => {
        expect(
            await implied(`component Foo {
  port in Integer speed;
  port in String label;
  port out boolean alarm;
  component A { port in int value; port in String text; port out boolean high; }
  A a;
  autoconnect type;
}`),
        ).toEqual(['a.high -> alarm', 'speed -> a.value', 'label -> a.text']);
    });

    test('type: two sources of one type make it ambiguous; off and no autoconnect imply nothing', async () => {
        const model = (mode: string): string => `component Foo {
  port in int x, in int y;${INNER}
  Inc inc;
  ${mode}
}`;
        expect(await implied(model('autoconnect type;'))).toEqual([]);
        expect(await implied(model('autoconnect off;'))).toEqual([]);
        expect(await implied(model(''))).toEqual([]);
    });
});

describe('autoconnect: the implied connectors in the connector checks', () => {
    test('valid: implied connectors connect every port, so there is no connectedness finding', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {
  port in int i;
  port out int o;${INNER}
  Inc inc;
  autoconnect port;
}`,
        });
        expect(found, JSON.stringify(found)).toEqual([]);
    });

    test('invalid: autoconnect off leaves the subcomponent unconnected', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {
  port in int i;
  port out int o;${INNER}
  Inc inc;
  autoconnect off;
}`,
        });
        expect(hits(found, 'arc/unconnected-sub-in-port', 'arc/unused-in-port', 'arc/unused-out-port').sort()).toEqual([
            'arc/unconnected-sub-in-port@inc',
            'arc/unused-in-port@i',
            'arc/unused-out-port@o',
        ]);
    });

    test('invalid: a feedback loop made of implied connectors must be delayed', async () => {
        const loop = (delayed: string): Record<string, string> => ({
            'Foo.arc': `component Foo {
  component A { port in int x; port ${delayed}out int y; }
  component B { port in int y; port out int x; }
  A a;
  B b;
  autoconnect port;
}`,
        });
        expect(hits(await validate(loop('')), 'arc/feedback-not-causal')).toEqual(['arc/feedback-not-causal@autoconnect port;']);
        expect(hits(await validate(loop('<<delayed>> ')), 'arc/feedback-not-causal')).toEqual([]);
    });
});

describe('autoconnect: context conditions', () => {
    test('arc/autoconnect-in-atomic: invalid in an atomic component, valid in a decomposed one', async () => {
        for (const kind of ['port', 'type', 'off']) {
            const found = await validate({ 'Foo.arc': `component Foo {\n  autoconnect ${kind};\n}` });
            expect(hits(found, 'arc/autoconnect-in-atomic')).toEqual([`arc/autoconnect-in-atomic@autoconnect ${kind};`]);
        }
        const inner = await validate({ 'Foo.arc': `component Foo {\n  component Inner {\n    autoconnect port;\n  }\n  Inner sub;\n}` });
        expect(hits(inner, 'arc/autoconnect-in-atomic')).toEqual(['arc/autoconnect-in-atomic@autoconnect port;']);
        const valid = await validate({ 'Foo.arc': `component Foo {${INNER}\n  Inc inc;\n  autoconnect port;\n}` });
        expect(hits(valid, 'arc/autoconnect-in-atomic')).toEqual([]);
    });

    test('arc/multiple-autoconnects: the second and later are reported, one is valid', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {${INNER}\n  Inc inc;\n  autoconnect port;\n  autoconnect type;\n  autoconnect off;\n}`,
        });
        expect(hits(found, 'arc/multiple-autoconnects')).toEqual([
            'arc/multiple-autoconnects@autoconnect type;',
            'arc/multiple-autoconnects@autoconnect off;',
        ]);
        const valid = await validate({ 'Foo.arc': `component Foo {${INNER}\n  Inc inc;\n  autoconnect type;\n}` });
        expect(hits(valid, 'arc/multiple-autoconnects')).toEqual([]);
    });
});

describe('arc/behavior-in-decomposed', () => {
    test('invalid: a compute block beside subcomponents', async () => {
        const found = await validate({
            'Foo.arc': `component Foo {\n  port in int i;\n  port out int o;${INNER}\n  Inc inc;\n  i -> inc.i;\n  inc.o -> o;\n  compute {\n    o = i;\n  }\n}`,
        });
        expect(hits(found, 'arc/behavior-in-decomposed')).toEqual(['arc/behavior-in-decomposed@compute {\n    o = i;\n  }']);
        expect(found.find((f) => f.code === 'arc/behavior-in-decomposed')!.message).toContain("'compute'");
    });

    test('valid: an atomic component with a behavior, a decomposed one without (init blocks are not behaviors)', async () => {
        const atomic = await validate({
            'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = i;\n  }\n}',
        });
        expect(hits(atomic, 'arc/behavior-in-decomposed')).toEqual([]);
        const withInit = await validate({
            'Foo.arc': `component Foo {\n  port in int i;\n  port out int o;\n  int n = 0;${INNER}\n  Inc inc;\n  i -> inc.i;\n  inc.o -> o;\n  init {\n    n = 1;\n  }\n}`,
        });
        expect(hits(withInit, 'arc/behavior-in-decomposed')).toEqual([]);
    });
});
