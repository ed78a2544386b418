import { describe, expect, test } from 'vitest';
import { validate } from './helpers.js';

const types = `package t;
classdiagram Types {
  enum Color { RED, GREEN; }
  class Shape { double area; }
  class Circle extends Shape { double radius; }
  class Box<T> { T content; }
  interface Named;
  class Robot implements Named { String name; }
}`;

async function fieldErrors(fields: string): Promise<string[]> {
    const found = await validate({
        'Foo.arc': `import t.Types.*;\nimport java.util.*;\ncomponent Foo(Circle c, Box<Integer> b) {\n${fields}\n}`,
        't/Types.cd': types,
    });
    return found.filter((f) => f.severity === 'error').map((f) => `${f.code}: ${f.text}`);
}

describe('assignability (fields as the probe)', () => {
    test.each([
        ['numeric widening', "long a = 1; double d = 1.5f; float f = 'c';"],
        ['boxing and unboxing', 'Integer a = 1; int v = Integer.valueOf(2); Object o = 3; Number n = 4; Comparable<Integer> ci = 5;'],
        ['subtyping of class-diagram types', 'Shape s = c; Named n = Robot.Robot(); Object o = c;'],
        ['generic arguments and wildcards', 'Box<Integer> x = b; Box<? extends Number> y = b; List<Integer> l = Collections.emptyList();'],
        ['enum constants and member access', 'Color k = Color.RED; double r = c.radius + c.area; Integer i = b.content;'],
        [
            'strings and arithmetic',
            'String s = "a" + 1; int m = 7 % 3 * 2; boolean q = 1 < 2 && !(3 >= 4) || 1 == 1; int sh = 1 << 3 >> 1;',
        ],
        ['conditional and null', 'String s = 1 > 0 ? "y" : null; double d = true ? 1 : 2.5;'],
    ])('%s', async (_name, fields) => {
        expect(await fieldErrors(fields)).toEqual([]);
    });

    test.each([
        ['narrowing', 'int a = 1L;', 'arc/field-init-type-mismatch: 1L'],
        ['boxing to a different box', 'Integer a = 1L;', 'arc/field-init-type-mismatch: 1L'],
        ['supertype to subtype', 'Circle x = Shape.Shape();', 'arc/field-init-type-mismatch: Shape.Shape()'],
        ['invariant generic arguments', 'Box<Number> x = b;', 'arc/field-init-type-mismatch: b'],
        ['boolean from number', 'boolean x = 1 + 2;', 'arc/field-init-type-mismatch: 1 + 2'],
        ['bad operand position', 'int x = 1 + true;', 'expr/type-mismatch: 1 + true'],
        ['unknown enum constant', 'Color k = Color.BLUE;', 'expr/unresolved-name: Color.BLUE'],
        ['unknown name', 'int x = y;', 'expr/unresolved-name: y'],
    ])('%s is rejected at the right place', async (_name, field, expected) => {
        expect(await fieldErrors(field)).toContain(expected);
    });
});
