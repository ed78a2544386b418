import { EmptyFileSystem, type ValidationAcceptor } from 'langium';
import { afterEach, describe, expect, test, vi } from 'vitest';
import type { PortDeclaration } from '../src/generated/ast.js';
import { createAdlServices } from '../src/index.js';
import { dump, ModelTestBench } from '../src/testing/index.js';
import { validate } from './helpers.js';

/** A check with a bug: it throws on every port declaration whose name starts with `bad` or `worse`. */
class BrokenChecks {
    checkPorts(d: PortDeclaration, _accept: ValidationAcceptor): void {
        if (d.ports.some((p) => /^(bad|worse)/.test(p.name))) throw new Error(`boom on ${d.ports[0]!.name.replace(/\d+$/, '')}`);
    }
}

function benchWithBrokenCheck(): ModelTestBench {
    return new ModelTestBench(() => {
        const s = createAdlServices(EmptyFileSystem);
        const broken = new BrokenChecks();
        s.Arc.validation.ValidationRegistry.register({ PortDeclaration: (d, accept) => broken.checkPorts(d, accept) });
        return s;
    }, 'broken');
}

describe('an exception in a check becomes one internal/check-failed diagnostic', () => {
    const bench = benchWithBrokenCheck();
    afterEach(() => {
        vi.restoreAllMocks();
    });

    test('named after the check, once per document, the other checks still report', async () => {
        const log = vi.spyOn(console, 'error').mockImplementation(() => undefined);
        const found = await bench.validate({
            'Wrong.arc': 'component A {\n  port in int bad1;\n  port in int bad2;\n  port in Missing m;\n}',
        });
        const failed = found.filter((f) => f.code === 'internal/check-failed');
        expect(failed, dump(found)).toHaveLength(1);
        expect(failed[0]!.message).toContain('BrokenChecks.checkPorts');
        expect(failed[0]!.message).toContain('boom');
        expect(failed[0]!.message).not.toContain('An error occurred');
        expect(found.map((f) => f.code)).toEqual(expect.arrayContaining(['arc/file-name-mismatch', 'arc/unresolved-type']));
        expect(log.mock.calls.filter((c) => String(c[0]).includes('BrokenChecks.checkPorts'))).toHaveLength(1);
    });

    test('logged once per check and message, not on every rebuild (keystroke)', async () => {
        const log = vi.spyOn(console, 'error').mockImplementation(() => undefined);
        const model = { 'A.arc': 'component A {\n  port in int worse9;\n}' };
        for (let i = 0; i < 5; i++) {
            const found = await bench.validate(model);
            expect(found.filter((f) => f.code === 'internal/check-failed')).toHaveLength(1);
        }
        expect(log.mock.calls.filter((c) => String(c[0]).includes('BrokenChecks.checkPorts'))).toHaveLength(1);
    });

    test('an asynchronous check that rejects is reported the same way', async () => {
        vi.spyOn(console, 'error').mockImplementation(() => undefined);
        const asyncBench = new ModelTestBench(() => {
            const s = createAdlServices(EmptyFileSystem);
            const broken = new BrokenChecks();
            s.Arc.validation.ValidationRegistry.register({
                PortDeclaration: async (d, accept) => {
                    await Promise.resolve();
                    broken.checkPorts(d, accept);
                },
            });
            return s;
        }, 'broken-async');
        const found = await asyncBench.validate({ 'A.arc': 'component A {\n  port in int bad1;\n  port in Missing m;\n}' });
        const failed = found.filter((f) => f.code === 'internal/check-failed');
        expect(failed, dump(found)).toHaveLength(1);
        expect(failed[0]!.message).toContain('boom');
        expect(found.map((f) => f.code)).toContain('arc/unresolved-type');
    });

    test('a model the check does not fail on has no internal/check-failed', async () => {
        const found = await bench.validate({ 'A.arc': 'component A {\n  port in int good;\n}' });
        expect(found, dump(found)).toEqual([]);
    });
});

/** A name lookup with a bug. */
class BuggyResolver {
    resolveComponent(): never {
        throw new Error('lookup bug');
    }
}

describe('a name lookup that throws becomes internal/check-failed, not a link error', () => {
    afterEach(() => {
        vi.restoreAllMocks();
    });

    test('the failing lookup is named; other references still resolve', async () => {
        vi.spyOn(console, 'error').mockImplementation(() => undefined);
        const bench = new ModelTestBench(() => {
            const s = createAdlServices(EmptyFileSystem);
            const resolver = s.Arc.maa.NameResolver;
            const original = resolver.resolveComponent.bind(resolver);
            resolver.resolveComponent = (context, name) =>
                name === 'Bug' ? new BuggyResolver().resolveComponent() : original(context, name);
            return s;
        }, 'lookup');
        const found = await bench.validate({
            'A.arc': 'component A {\n  Bug b;\n  B ok;\n}',
            'B.arc': 'component B { }',
        });
        const failed = found.filter((f) => f.code === 'internal/check-failed');
        expect(failed, dump(found)).toHaveLength(1);
        expect(failed[0]!.text).toBe('Bug');
        expect(failed[0]!.message).toContain('BuggyResolver.resolveComponent');
        expect(failed[0]!.message).toContain('lookup bug');
        expect(
            found.filter((f) => f.code.startsWith('link/') || f.code === 'arc/missing-component-type'),
            dump(found),
        ).toEqual([]);
    });
});

describe('partially parsed models the checks used to throw on', () => {
    test('an import without a name (NameResolver.resolveGlobal)', async () => {
        const found = await validate({ 'A.arc': 'import ;\ncomponent A {\n  port in Speed s;\n}' });
        expect(
            found.filter((f) => f.code.startsWith('internal/')),
            dump(found),
        ).toEqual([]);
        expect(found.map((f) => f.code)).toEqual(expect.arrayContaining(['syntax/unexpected-token', 'arc/unresolved-type']));
    });

    test('an expression the parser left without its type (ExpressionTyper.value)', async () => {
        const found = await validate({
            'A.arc': 'component A {\n  port in int i;\n  port out int o;\n  compute { o = (); o = i + ; o = - ; }\n}',
        });
        expect(
            found.filter((f) => f.code.startsWith('internal/')),
            dump(found),
        ).toEqual([]);
        expect(found.some((f) => f.code.startsWith('syntax/'))).toBe(true);
    });

    test('a connector without its ports (ConnectorChecks)', async () => {
        const found = await validate({
            'A.arc': 'component A {\n  port in int i;\n  B b;\n  i -> b.;\n  -> b.x;\n}',
            'B.arc': 'component B { port in int x; }',
        });
        expect(
            found.filter((f) => f.code.startsWith('internal/')),
            dump(found),
        ).toEqual([]);
    });

    test('every truncation and token deletion of a model with all host constructs', async () => {
        const model =
            'package p;\nimport java.util.*;\ncomponent A<T extends Number>(int k = 2) extends B {\n  port in int i;\n  port out List<Integer> o;\n  B b(k = 1);\n  i -> b.x;\n  int f = 0;\n  compute { if (i > k) { f += i * -2; } else f = (i < 0 ? 1 : 2); }\n}\n';
        const tokens = model.match(/\w+|\s+|./g)!;
        const variants: string[] = [];
        for (let n = 0; n <= model.length; n += 3) variants.push(model.substring(0, n));
        for (let t = 0; t < tokens.length; t++) if (!/^\s+$/.test(tokens[t]!)) variants.push(tokens.filter((_, j) => j !== t).join(''));
        for (const text of variants) {
            const found = await validate({ 'p/A.arc': text, 'p/B.arc': 'package p;\ncomponent B { port in int x; }' });
            expect(
                found.filter((f) => f.code.startsWith('internal/')),
                `${JSON.stringify(text)}: ${dump(found)}`,
            ).toEqual([]);
        }
    });
});
