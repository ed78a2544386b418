import { describe, expect, test } from 'vitest';
import { dump, hits } from '../src/testing/index.js';
import { validate } from './helpers.js';

// Names, ports and block locals are looked up in tables (linking and the connector checks were
// quadratic); these tests hold the tables to the scanning semantics they replaced.
describe('lookups in large models', () => {
    test('3,000 connectors to a subcomponent: every end resolves, a wrong one is still reported', async () => {
        const n = 3_000;
        const ports = (pre: string, dir: string): string => Array.from({ length: n }, (_, i) => `  port ${dir} int ${pre}${i};`).join('\n');
        const sub = `component Sub {\n${ports('a', 'in')}\n${ports('b', 'out')}\n}\n`;
        const connectors = Array.from({ length: n }, (_, i) => `  i${i} -> s.a${i};\n  s.b${i} -> o${i};`).join('\n');
        const big = `component Big {\n${ports('i', 'in')}\n${ports('o', 'out')}\n  Sub s;\n${connectors}\n  i0 -> s.nope;\n}\n`;
        const found = await validate({ 'Sub.arc': sub, 'Big.arc': big });
        expect(hits(found, 'arc/missing-port'), dump(found)).toEqual(['arc/missing-port@nope']);
        expect(
            found.filter((f) => f.code !== 'arc/missing-port' && f.severity === 'error'),
            dump(found),
        ).toEqual([]);
    });

    test('a local variable is the nearest declaration before its use, in the innermost block', async () => {
        const found = await validate({
            'A.arc':
                'component A {\n  port out int o;\n  port out boolean b;\n  compute {\n    int x = 1;\n    o = x;\n    { boolean x = true; b = x; }\n    boolean y = true;\n    o = x;\n    b = y;\n  }\n}\n',
        });
        expect(found, dump(found)).toEqual([]);
        const wrong = await validate({ 'A.arc': 'component A {\n  port out int o;\n  compute {\n    o = x;\n    int x = 1;\n  }\n}\n' });
        expect(hits(wrong, 'expr/unresolved-name'), dump(wrong)).toEqual(['expr/unresolved-name@x']);
    });

    test('a feedback loop through an atomic subcomponent is found unless its output is delayed', async () => {
        const sub = (delayed: boolean): string =>
            `component Sub {\n  port in int a, in int c;\n  port ${delayed ? '<<delayed>> ' : ''}out int b;\n}\n`;
        const loop = 'component Top {\n  port in int i;\n  Sub s;\n  i -> s.c;\n  s.b -> s.a;\n}\n';
        expect(hits(await validate({ 'Sub.arc': sub(false), 'Top.arc': loop }), 'arc/feedback-not-causal')).toEqual([
            'arc/feedback-not-causal@s.b -> s.a;',
        ]);
        expect(hits(await validate({ 'Sub.arc': sub(true), 'Top.arc': loop }), 'arc/feedback-not-causal')).toEqual([]);
    });
});
