import { EmptyFileSystem } from 'langium';
import { describe, expect, test } from 'vitest';
import { ModelTestBench } from '../src/testing/index.js';
import {
    ConstantEvaluationError,
    EMPTY_CONSTANT_ENV,
    constantEnv,
    createAdlServices,
    evaluateConstant,
    type ConstantValue,
    type SymType,
    type ast,
} from '../src/index.js';

const bench = new ModelTestBench(() => createAdlServices(EmptyFileSystem), 'constants');

const TYPES = `package t;
classdiagram Types {
  enum Color { RED, GREEN, BLUE; }
}`;

/** The parameters of `component Foo(<params>)` with the enum type Color. */
async function parameters(params: string): Promise<{ params: ast.Parameter[]; color: SymType }> {
    const { docs } = await bench.build({ 'Foo.arc': `import t.Types.*;\ncomponent Foo(${params}) { }`, 't/Types.cd': TYPES });
    const foo = docs.find((d) => d.uri.path.endsWith('Foo.arc'))!.parseResult.value as ast.ArcModel;
    const cd = docs.find((d) => d.uri.path.endsWith('Types.cd'))!.parseResult.value as ast.CDModel;
    const decl = cd.diagram.elements.find((t): t is ast.CDEnum => t.$type === 'CDEnum' && t.name === 'Color')!;
    return { params: foo.component!.params, color: { kind: 'object', decl, args: [] } };
}

async function evaluated(params: string, env = EMPTY_CONSTANT_ENV): Promise<ConstantValue> {
    const { params: ps, color } = await parameters(params);
    const last = ps[ps.length - 1]!;
    return evaluateConstant(last.default!, env, color);
}

describe('constant evaluation on the AST', () => {
    test.each<[string, ConstantValue['kind'], unknown]>([
        ['int a = 42', 'int', 42],
        ['int a = 0x1F', 'int', 31],
        ['long a = 5L', 'int', 5],
        ['int a = -7', 'int', -7],
        ['double a = 1.5f', 'float', 1.5],
        ['double a = -2.0', 'float', -2],
        ['double a = 1e3', 'float', 1000],
        ['boolean a = true', 'boolean', true],
        ['boolean a = !false && (1 < 2)', 'boolean', true],
        ['String a = "a\\tb"', 'string', 'a\tb'],
        ["char a = 'x'", 'char', 'x'],
        ["char a = '\\n'", 'char', '\n'],
        ['int a = 2 * 3 + 7 / 2 - 10 % 4', 'int', 7],
        ['double a = 7 / 2.0', 'float', 3.5],
        ['int a = 1 > 0 ? 4 : 5', 'int', 4],
        ['String a = "n" + 1 + 2.0', 'string', 'n12.0'],
    ])('%s', async (params, kind, value) => {
        const v = await evaluated(params);
        expect(v.kind).toBe(kind);
        expect(v.value).toEqual(value);
    });

    test('enum constants of the expected enum evaluate to their ordinal, written qualified or not', async () => {
        expect(await evaluated('Color a = Color.BLUE')).toMatchObject({ kind: 'enum', value: 'BLUE', ordinal: 2 });
        expect(await evaluated('Color a = GREEN')).toMatchObject({ kind: 'enum', value: 'GREEN', ordinal: 1 });
    });

    test("names take the values of the environment (the enclosing instance's parameters)", async () => {
        const env = constantEnv(new Map<string, ConstantValue>([['speed', { kind: 'int', value: 4 }]]));
        expect(await evaluated('int a = speed * 2 + 1', env)).toEqual({ kind: 'int', value: 9 });
    });

    test.each([
        ['int a = unknown', "'unknown' is not a constant"],
        ['int a = Math.max(1, 2)', "'Math.max(1, 2)' is not a constant expression"],
        ['int a = 1 / 0', "'1 / 0' divides by zero"],
        ['int a = -true', "'-true' applies '-' to a boolean"],
        ['Color a = Color.PINK', "'Color.PINK' is not a constant"],
    ])('%s is not constant: a ConstantEvaluationError on the expression', async (params, message) => {
        const { params: ps, color } = await parameters(params);
        const expr = ps[0]!.default!;
        let error: unknown;
        try {
            evaluateConstant(expr, EMPTY_CONSTANT_ENV, color);
        } catch (e) {
            error = e;
        }
        expect(error).toBeInstanceOf(ConstantEvaluationError);
        expect((error as ConstantEvaluationError).message).toContain(message);
        expect((error as ConstantEvaluationError).node).toBeDefined();
    });
});
