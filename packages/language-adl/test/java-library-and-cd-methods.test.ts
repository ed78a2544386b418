import { describe, expect, test } from 'vitest';
import { validate } from './helpers.js';

// The JDK library (types/builtin-library.ts) and methods declared in class diagrams (classes,
// interfaces, enums), as the checker resolves and types calls of them. Fields are the probe.

const types = `package t;
classdiagram Shapes {
  interface Measured { double area(); }
  class Rect implements Measured {
    double w; double h;
    double area();
    Rect scaled(double factor);
    static Rect square(double side);
    void resize(double w, double h);
  }
  enum Color {
    RED, GREEN;
    int code();
    static Color parse(String text);
  }
}`;

async function fieldErrors(fields: string): Promise<string[]> {
    const found = await validate({
        'Foo.arc': `import t.Shapes.*;\nimport java.util.*;\ncomponent Foo(Rect r, Measured m) {\n${fields}\n}`,
        't/Shapes.cd': types,
    });
    return found.filter((f) => f.severity === 'error').map((f) => `${f.code}: ${f.text}`);
}

describe('the JDK library', () => {
    test.each([
        [
            'java.util.Date by its qualified name',
            'java.util.Date d = java.util.Date.Date(5L); long t = d.getTime(); boolean b = d.before(Date.Date());',
        ],
        [
            'Map methods',
            'Map<String, Integer> mp = HashMap.HashMap(); boolean k = mp.containsKey("a"); Integer v = mp.getOrDefault("a", 0); Set<String> ks = mp.keySet(); Collection<Integer> vs = mp.values();',
        ],
        [
            'Number and box methods',
            'Number n = 3; int i = n.intValue(); double d = Integer.valueOf(4).doubleValue(); int p = Integer.parseInt("5"); int mx = Integer.MAX_VALUE;',
        ],
        [
            'Character classes and chars',
            "boolean dg = Character.isDigit('7'); char u = Character.toUpperCase('q'); char c = \"abc\".charAt(1);",
        ],
        [
            'List, Set, Iterator and Optional',
            'List<String> l = ArrayList.ArrayList(); String s = l.get(0); Iterator<String> it = l.iterator(); boolean h = it.hasNext(); String n = it.next(); Optional<String> o = Optional.of("x"); String e = o.orElse("y"); Set<Integer> st = HashSet.HashSet(); boolean a = st.add(3);',
        ],
        [
            'String and Math',
            'String s = "a".repeat(3).toUpperCase().substring(1); int ix = s.indexOf("A"); double root = Math.sqrt(Math.PI) + Math.max(1.5, 2.0); long rd = Math.round(2.5);',
        ],
    ])('%s type-check', async (_name, fields) => {
        expect(await fieldErrors(fields)).toEqual([]);
    });

    test.each([
        [
            'a method with the wrong number of arguments',
            'Map<String, Integer> mp = HashMap.HashMap(); boolean k = mp.containsKey();',
            'expr/unresolved-name: mp.containsKey',
        ],
        [
            'a method the type does not have',
            'java.util.Date d = java.util.Date.Date(); long t = d.getMillis();',
            'expr/unresolved-name: d.getMillis',
        ],
        ['an argument of the wrong type', 'Optional<String> o = Optional.of("x"); String e = o.orElse(3);', 'expr/type-mismatch: 3'],
        [
            'a result of the wrong type',
            'Map<String, Integer> mp = HashMap.HashMap(); String v = mp.get("a");',
            'arc/field-init-type-mismatch: mp.get("a")',
        ],
        ['long to int', 'java.util.Date d = java.util.Date.Date(); int t = d.getTime();', 'arc/field-init-type-mismatch: d.getTime()'],
        ['an unknown java.util type', 'java.util.Calendar c = null;', 'java.util.Calendar'],
    ])('%s is rejected', async (_name, fields, expected) => {
        const errors = await fieldErrors(fields);
        expect(
            errors.some((e) => e.includes(expected)),
            errors.join('\n'),
        ).toBe(true);
    });
});

describe('methods of class diagrams', () => {
    test.each([
        ['instance methods of a class', 'double a = r.area(); Rect s = r.scaled(2.0); double b = r.scaled(0.5).area();'],
        ['a static method of a class', 'Rect q = Rect.square(3.0);'],
        ['an interface method, also through an implementing class', 'double a = m.area(); Measured x = r; double b = x.area();'],
        ['methods of an enum', 'int c = Color.RED.code(); Color k = Color.parse("RED"); int d = k.code();'],
        ['int arguments widen to double parameters', 'Rect s = r.scaled(2);'],
    ])('%s type-check', async (_name, fields) => {
        expect(await fieldErrors(fields)).toEqual([]);
    });

    test.each([
        ['an undeclared method', 'double a = r.perimeter();', 'expr/unresolved-name: r.perimeter'],
        ['the wrong number of arguments', 'Rect s = r.scaled();', 'expr/unresolved-name: r.scaled'],
        ['an argument of the wrong type', 'Rect s = r.scaled("big");', 'expr/type-mismatch: "big"'],
        ['a result of the wrong type', 'int a = r.scaled(2.0);', 'arc/field-init-type-mismatch: r.scaled(2.0)'],
        ['an enum method the enum does not declare', 'int c = Color.RED.weight();', 'expr/unresolved-name: Color.RED.weight'],
        ['a void method used as a value', 'double v = r.resize(1.0, 2.0);', 'arc/field-init-type-mismatch: r.resize(1.0, 2.0)'],
        ['an enum constant that does not exist', 'Color k = Color.BLUE;', 'expr/unresolved-name: Color.BLUE'],
    ])('%s is rejected', async (_name, fields, expected) => {
        const errors = await fieldErrors(fields);
        expect(
            errors.some((e) => e.includes(expected)),
            errors.join('\n'),
        ).toBe(true);
    });

    test('enum bodies with methods parse; the members are not constants', async () => {
        const found = await validate({
            't/E.cd': 'package t;\nclassdiagram E {\n  enum Level { LOW, HIGH; int rank(); }\n  enum Empty { ; String describe(); }\n}',
            'Foo.arc': 'import t.E.*;\ncomponent Foo {\n  int r = Level.HIGH.rank();\n  String d = Level.rank;\n}',
        });
        const errors = found.filter((f) => f.severity === 'error').map((f) => `${f.code}: ${f.text}`);
        expect(errors.filter((e) => e.startsWith('syntax/'))).toEqual([]);
        expect(errors.some((e) => e.includes('Level.rank'))).toBe(true);
    });
});
