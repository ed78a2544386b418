import type { DiagnosticCatalog } from './catalog.js';
import { NESTING_LIMIT } from '../parser/nesting-limit.js';
import { SIZE_LIMIT } from '../parser/guarded-lexer.js';

const lib = {
    'a/b/A.arc': 'package a.b;\ncomponent A { }',
    'a/b/B.arc': 'package a.b;\ncomponent B(int p) {\n  port in int i;\n  port out int o;\n}',
    'a/b/Gen.arc': 'package a.b;\ncomponent Gen<T extends Number> {\n  port in T i;\n  port out T o;\n}',
};

/** The host language's diagnostics (`syntax/`, `link/`, `arc/`, `expr/`, `cd/`). */
export const ADL_DIAGNOSTICS: DiagnosticCatalog = {
    title: 'Components, connectors and expressions',
    intro:
        "Checks of the host language (`.arc`), after MontiArc's context conditions, and of class diagrams (`.cd`). " +
        `A model file of any language of the family with more than ${SIZE_LIMIT.toLocaleString('en')} characters is not parsed: ` +
        'it gets one `syntax/too-large` error (at its start) and an empty model, so that one pathological file cannot keep ' +
        'the editor or `maa-gen check` busy for minutes; see docs/cli.md for the time and memory measured at the limit.',
    entries: [
        {
            code: 'syntax/unexpected-token',
            severity: 'error',
            rule: 'The text does not follow the grammar. The parser recovers and goes on, so later errors in the same file may be follow-ups.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int ;\n}' }, at: ';' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n}' } },
        },
        {
            code: 'syntax/unexpected-end',
            severity: 'error',
            rule: 'The file ends in the middle of a construct (for example a missing closing brace).',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n' } },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n}' } },
        },
        {
            code: 'syntax/unexpected-character',
            severity: 'error',
            rule: 'A character that no token of the language starts with.',
            invalid: { files: { 'Foo.arc': 'component Foo { # }' }, at: '#' },
            valid: { files: { 'Foo.arc': 'component Foo { }' } },
        },
        {
            code: 'syntax/too-deep',
            severity: 'error',
            rule:
                'The text nests deeper than the parser can take (its recursion would overflow the stack): ' +
                `more than ${NESTING_LIMIT} nesting levels, where a parenthesis or bracket counts 16, a brace 4, ` +
                'a generic `<` 3, `if`/`else`/`while`/`for` 2 and any other keyword or operator 1 until its statement, ' +
                'argument or block ends. That allows, for example, 11 nested parentheses in an expression, 47 nested ' +
                'blocks in `compute`, 37 nested states, 86 nested `if` statements or 189 operators in one expression. The parser measured the limits with ' +
                "Node's default stack (and a syntax error at the innermost point): 27 parentheses, 125 blocks, 94 states, " +
                '452 prefix operators. The region past the limit (up to the end of its statement or enclosing bracket) is ' +
                'not parsed; the rest of the file is checked. The diagnostic marks the first token past the limit ' +
                'and counts further regions of the same file. Restructure the model, e.g. with local variables or ' +
                'helper components.',
            invalid: {
                files: {
                    'Foo.arc': `component Foo {\n  port in int i;\n  port out int o;\n  compute { o = ${'('.repeat(12)}i${')'.repeat(12)}; }\n}`,
                },
                at: '(',
            },
            valid: {
                files: {
                    'Foo.arc': `component Foo {\n  port in int i;\n  port out int o;\n  compute { o = ${'('.repeat(11)}i${')'.repeat(11)}; }\n}`,
                },
            },
        },
        {
            code: 'arc/file-name-mismatch',
            severity: 'error',
            rule: 'A file declares one top-level component, named like the file.',
            invalid: { files: { 'Foo.arc': 'component Bar { }' }, at: 'Bar' },
            valid: { files: { 'Foo.arc': 'component Foo { }' } },
        },
        {
            code: 'arc/package-mismatch',
            severity: 'error',
            rule: 'The package declaration equals the folder path below the model root.',
            invalid: { files: { 'a/Foo.arc': 'package b;\ncomponent Foo { }' }, at: 'b' },
            valid: { files: { 'a/Foo.arc': 'package a;\ncomponent Foo { }' } },
        },
        {
            code: 'arc/unresolved-type',
            severity: 'error',
            rule: 'The type of a port, field, parameter or type argument resolves to a primitive, a class-diagram type, a `java.lang`/`java.util` type or a type parameter.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in Speed s;\n}' }, at: 'Speed' },
            valid: {
                files: {
                    'Foo.arc': 'import t.Types.*;\ncomponent Foo {\n  port in Speed s;\n}',
                    't/Types.cd': 'package t;\nclassdiagram Types {\n  class Speed { double value; }\n}',
                },
            },
        },
        {
            code: 'arc/missing-component-type',
            severity: 'error',
            rule: 'The type of a subcomponent or a parent resolves to a component type.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  Sensor s;\n}' }, at: 'Sensor' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  a.b.A s;\n}', ...lib } },
        },
        {
            code: 'arc/circular-inheritance',
            severity: 'error',
            rule: 'A component type does not (transitively) extend itself.',
            invalid: { files: { 'Foo.arc': 'component Foo extends Bar { }', 'Bar.arc': 'component Bar extends Foo { }' }, at: 'Bar' },
            valid: { files: { 'Foo.arc': 'component Foo extends Bar { }', 'Bar.arc': 'component Bar { }' } },
        },
        {
            code: 'arc/subcomponent-cycle',
            severity: 'error',
            rule: 'A component type does not (transitively) contain an instance of itself.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  Bar bar;\n}', 'Bar.arc': 'component Bar {\n  Foo foo;\n}' }, at: 'bar' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  Bar bar;\n}', 'Bar.arc': 'component Bar { }' } },
        },
        {
            code: 'arc/root-instantiated',
            severity: 'error',
            rule: 'A top-level component type is not instantiated where it is declared.',
            invalid: { files: { 'Foo.arc': 'component Foo foo { }' }, at: 'foo' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  component Inner inner { }\n}' } },
        },
        {
            code: 'arc/duplicate-name',
            severity: 'error',
            rule: 'Ports, fields, parameters and subcomponents of a component share one namespace; type parameters and inner component types have their own.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int x;\n  int x = 0;\n}' }, at: 'x' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port in int x;\n  int y = 0;\n}' } },
        },
        {
            code: 'arc/reserved-name',
            severity: 'error',
            rule: 'A name is not `Tick` (the time-slice event), not a Java or Python keyword (the languages of the models and of the generated code), and not a word the model root reserves in `maa.json` (`{"reservedNames": {"port": ["speed"]}}`; kinds: component, port, field, parameter, subcomponent, typeParameter, state, or `*`).',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int Tick;\n}' }, at: 'Tick' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port in int tick;\n}' } },
        },
        {
            code: 'arc/missing-port',
            severity: 'error',
            rule: "A connector names existing ports (of the component, or of the subcomponent's type, including inherited ports).",
            invalid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.x -> o;\n}',
                    ...lib,
                },
                at: 'x',
            },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/missing-subcomponent',
            severity: 'error',
            rule: 'A connector names existing subcomponents.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  a.b.A a;\n  i -> x.i;\n}', ...lib }, at: 'x' },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/source-direction-mismatch',
            severity: 'error',
            rule: 'A connector starts at an incoming port of the component or at an outgoing port of a subcomponent.',
            invalid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.i -> o;\n}',
                    ...lib,
                },
                at: 'b.i',
            },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/target-direction-mismatch',
            severity: 'error',
            rule: 'A connector ends at outgoing ports of the component or at incoming ports of subcomponents.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int i, j;\n  a.b.A a;\n  i -> j;\n}', ...lib }, at: 'j' },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/connector-type-mismatch',
            severity: 'error',
            rule: "The source port's type is assignable to each target port's type (subtyping, boxing and unboxing, numeric widening; generic arguments must match).",
            invalid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in boolean i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
                at: 'b.i',
            },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out long o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/timing-mismatch',
            severity: 'error',
            rule: "A target port is at most as strongly timed as its source (`<<untimed>>` < `<<timed>>` < `<<sync>>`). Ports without timing take their behavior's timing, else `timed`; an incoming port of a composed component without timing adopts the timing of the subcomponents it feeds.",
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port <<untimed>> in int i;\n  component Inner {\n    port <<sync>> in int i;\n  }\n  Inner inner;\n  i -> inner.i;\n}',
                },
                at: 'inner.i',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port <<sync>> in int i;\n  component Inner {\n    port <<untimed>> in int i;\n  }\n  Inner inner;\n  i -> inner.i;\n}',
                },
            },
        },
        {
            code: 'arc/multiple-timings',
            severity: 'error',
            rule: 'A port or behavior declares at most one timing.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port <<sync, timed>> in int i;\n}' }, at: '<<sync, timed>>' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port <<sync>> in int i;\n}' } },
        },
        {
            code: 'arc/multiple-senders',
            severity: 'error',
            rule: 'Every port is the target of at most one connector.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i, j;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  j -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
                at: 'b.i',
            },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/unconnected-sub-in-port',
            severity: 'error',
            rule: 'Every incoming port of a subcomponent has a sender.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port out int o;\n  a.b.B b(1);\n  b.o -> o;\n}', ...lib }, at: 'b' },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/unconnected-sub-out-port',
            severity: 'warning',
            rule: 'Every outgoing port of a subcomponent is used (otherwise its messages are lost).',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  a.b.B b(1);\n  i -> b.i;\n}', ...lib }, at: 'b' },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/unused-in-port',
            severity: 'warning',
            rule: 'Every incoming port of a composed component is forwarded to a subcomponent (or an outgoing port).',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  a.b.A a;\n}', ...lib }, at: 'i' },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/unused-out-port',
            severity: 'warning',
            rule: 'Every outgoing port of a composed component has a sender.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port out int o;\n  a.b.A a;\n}', ...lib }, at: 'o' },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  a.b.B b(1);\n  i -> b.i;\n  b.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/connector-in-atomic',
            severity: 'warning',
            rule: 'Connectors belong to composed components; an atomic component computes its outputs in its behavior.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  i -> o;\n}' }, at: 'i -> o;' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = i;\n  }\n}' } },
        },
        {
            code: 'arc/multiple-behaviors',
            severity: 'error',
            rule: 'An atomic component has at most one behavior (a `compute` block or one embedded behavior block; `init` belongs to `compute`).',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  compute { }\n  compute { }\n}' }, at: 'compute { }' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port out int o;\n  init {\n    o = 0;\n  }\n  compute { }\n}' } },
        },
        {
            code: 'arc/behavior-in-decomposed',
            severity: 'error',
            rule: 'A decomposed component (one with subcomponents) declares no behavior besides `init`: its behavior is that of its subcomponents and connectors, and a `compute` block or automaton beside them would never run.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  component Inc {\n    port in int i;\n    port out int o;\n  }\n  Inc inc;\n  i -> inc.i;\n  inc.o -> o;\n  compute {\n    o = i;\n  }\n}',
                },
                at: 'compute {\n    o = i;\n  }',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  component Inc {\n    port in int i;\n    port out int o;\n  }\n  Inc inc;\n  i -> inc.i;\n  inc.o -> o;\n}',
                },
            },
        },
        {
            code: 'arc/multiple-autoconnects',
            severity: 'error',
            rule: 'A component declares at most one `autoconnect` (`port`, `type` or `off`).',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  component Inc {\n    port in int i;\n    port out int o;\n  }\n  Inc inc;\n  autoconnect port;\n  autoconnect type;\n}',
                },
                at: 'autoconnect type;',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  component Inc {\n    port in int i;\n    port out int o;\n  }\n  Inc inc;\n  autoconnect port;\n}',
                },
            },
        },
        {
            code: 'arc/autoconnect-in-atomic',
            severity: 'error',
            rule: '`autoconnect` belongs to decomposed components: an atomic component has no subcomponents whose ports it could connect.',
            invalid: {
                files: {
                    'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  autoconnect port;\n  compute {\n    o = i;\n  }\n}',
                },
                at: 'autoconnect port;',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  component Inc {\n    port in int i;\n    port out int o;\n  }\n  Inc inc;\n  autoconnect type;\n}',
                },
            },
        },
        {
            code: 'arc/delayed-in-port',
            severity: 'error',
            rule: '`<<delayed>>` applies to outgoing ports only.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port <<delayed>> in int i;\n}' }, at: 'delayed' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port <<delayed>> out int o;\n}' } },
        },
        {
            code: 'arc/feedback-not-causal',
            severity: 'error',
            rule: 'Every feedback cycle between subcomponents passes a `<<delayed>>` outgoing port (directly or inside a composed subcomponent): the stream semantics needs strong causality.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  component Inc {\n    port in int i;\n    port out int o;\n  }\n  Inc a, b;\n  a.o -> b.i;\n  b.o -> a.i;\n}',
                },
                at: 'b.o -> a.i;',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  component Inc {\n    port in int i;\n    port <<delayed>> out int o;\n  }\n  Inc a, b;\n  a.o -> b.i;\n  b.o -> a.i;\n}',
                },
            },
        },
        {
            code: 'arc/too-few-arguments',
            severity: 'error',
            rule: 'An instantiation gives a value to every parameter without a default.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  a.b.B b;\n}', ...lib }, at: 'b' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  a.b.A a;\n}', ...lib } },
        },
        {
            code: 'arc/too-many-arguments',
            severity: 'error',
            rule: 'An instantiation gives at most as many arguments as the type has parameters.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  a.b.A a(1);\n}', ...lib }, at: '1' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  a.b.A a;\n}', ...lib } },
        },
        {
            code: 'arc/argument-type-mismatch',
            severity: 'error',
            rule: "Each argument's type is assignable to its parameter's type (with the instantiation's type arguments substituted).",
            invalid: { files: { 'Foo.arc': 'component Foo(int x) extends a.b.B(true) { }', ...lib }, at: 'true' },
            valid: { files: { 'Foo.arc': 'component Foo(int x) extends a.b.B(x) { }', ...lib } },
        },
        {
            code: 'arc/unknown-argument-key',
            severity: 'error',
            rule: 'The key of a key argument (`b(p = 1)`) names a parameter of the instantiated type.',
            invalid: { files: { 'Foo.arc': 'component Foo extends a.b.B(q = 1) { }', ...lib }, at: 'q' },
            valid: { files: { 'Foo.arc': 'component Foo extends a.b.B(p = 1) { }', ...lib } },
        },
        {
            code: 'arc/argument-multiple-values',
            severity: 'error',
            rule: 'No parameter gets two values (positionally and by key, or twice by key).',
            invalid: { files: { 'Foo.arc': 'component Foo extends a.b.B(1, p = 2) { }', ...lib }, at: 'p = 2' },
            valid: { files: { 'Foo.arc': 'component Foo extends a.b.B(p = 2) { }', ...lib } },
        },
        {
            code: 'arc/positional-after-key',
            severity: 'error',
            rule: 'Positional arguments come before key arguments.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  component C(int x, int y) { }\n  C c(x = 1, 2);\n}' }, at: '2' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  component C(int x, int y) { }\n  C c(1, y = 2);\n}' } },
        },
        {
            code: 'arc/assignment-in-argument',
            severity: 'error',
            rule: 'Arguments have no side effects: no assignment (other than naming the key), `++` or `--`.',
            invalid: { files: { 'Foo.arc': 'component Foo(int x) extends a.b.B(x++) { }', ...lib }, at: 'x++' },
            valid: { files: { 'Foo.arc': 'component Foo(int x) extends a.b.B(x + 1) { }', ...lib } },
        },
        {
            code: 'arc/optional-params-last',
            severity: 'error',
            rule: 'Parameters with default values come after all parameters without.',
            invalid: { files: { 'Foo.arc': 'component Foo(int a = 1, int b) { }' }, at: 'b' },
            valid: { files: { 'Foo.arc': 'component Foo(int b, int a = 1) { }' } },
        },
        {
            code: 'arc/port-in-static-context',
            severity: 'error',
            rule: 'Ports carry values only while a component runs: they cannot appear in field initializers, parameter defaults or instantiation arguments.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  int f = i;\n}' }, at: 'i' },
            valid: { files: { 'Foo.arc': 'component Foo(int p) {\n  port in int i;\n  int f = p;\n}' } },
        },
        {
            code: 'arc/field-init-type-mismatch',
            severity: 'error',
            rule: "A field's initial value is assignable to the field's type.",
            invalid: { files: { 'Foo.arc': 'component Foo {\n  boolean f = 1;\n}' }, at: '1' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  double f = 1;\n}' } },
        },
        {
            code: 'arc/param-default-type-mismatch',
            severity: 'error',
            rule: "A parameter's default value is assignable to the parameter's type.",
            invalid: { files: { 'Foo.arc': 'component Foo(int p = false) { }' }, at: 'false' },
            valid: { files: { 'Foo.arc': 'component Foo(long p = 1) { }' } },
        },
        {
            code: 'arc/inherited-port-type-mismatch',
            severity: 'error',
            rule: 'A redeclared inherited port keeps a compatible type: an incoming port may narrow it, an outgoing port may widen it.',
            invalid: { files: { 'Foo.arc': 'component Foo extends a.b.B(1) {\n  port in double i;\n}', ...lib }, at: 'i' },
            valid: { files: { 'Foo.arc': 'component Foo extends a.b.B(1) {\n  port out long o;\n}', ...lib } },
        },
        {
            code: 'arc/inherited-port-direction-mismatch',
            severity: 'error',
            rule: 'A redeclared inherited port keeps its direction.',
            invalid: { files: { 'Foo.arc': 'component Foo extends a.b.B(1) {\n  port out int i;\n}', ...lib }, at: 'i' },
            valid: { files: { 'Foo.arc': 'component Foo extends a.b.B(1) {\n  port in int i;\n}', ...lib } },
        },
        {
            code: 'arc/type-arg-bound',
            severity: 'error',
            rule: 'Each type argument satisfies the bounds of its type parameter.',
            invalid: {
                files: { 'Foo.arc': 'component Foo {\n  port in String i;\n  a.b.Gen<String> g;\n  i -> g.i;\n}', ...lib },
                at: 'String',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in Integer i;\n  port out Integer o;\n  a.b.Gen<Integer> g;\n  i -> g.i;\n  g.o -> o;\n}',
                    ...lib,
                },
            },
        },
        {
            code: 'arc/too-few-type-args',
            severity: 'error',
            rule: 'A generic type gets as many type arguments as it has type parameters (or none, see arc/raw-generic).',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  component P<A, B> { }\n  P<int> p;\n}' }, at: 'P<int>' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  component P<A, B> { }\n  P<int, int> p;\n}' } },
        },
        {
            code: 'arc/too-many-type-args',
            severity: 'error',
            rule: 'A type gets no more type arguments than it has type parameters.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  a.b.A<int> a;\n}', ...lib }, at: 'a.b.A<int>' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  a.b.A a;\n}', ...lib } },
        },
        {
            code: 'arc/raw-generic',
            severity: 'warning',
            rule: 'A generic component type is instantiated or extended with type arguments.',
            invalid: { files: { 'Foo.arc': 'component Foo extends a.b.Gen { }', ...lib }, at: 'a.b.Gen' },
            valid: { files: { 'Foo.arc': 'component Foo extends a.b.Gen<Integer> { }', ...lib } },
        },
        {
            code: 'arc/naming-convention',
            severity: 'warning',
            rule: 'Component types and type parameters start upper case; ports, fields, parameters and subcomponents start lower case.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port in int Speed;\n}' }, at: 'Speed' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  port in int speed;\n}' } },
        },
        {
            code: 'arc/unknown-stereotype',
            severity: 'warning',
            rule: 'Stereotypes are one of `<<sync>>`, `<<timed>>`, `<<untimed>>`, `<<delayed>>`, `<<handwritten>>` (a misspelled timing would silently change the semantics).',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port <<synch>> in int i;\n}' }, at: 'synch' },
            valid: { files: { 'Foo.arc': '<<handwritten>> component Foo {\n  port <<sync>> in int i;\n}' } },
        },
        {
            code: 'expr/type-mismatch',
            severity: 'error',
            rule: 'Operators, conditions and assignments in expressions and statements get operands of fitting types (reported on the smallest offending sub-expression).',
            invalid: {
                files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  port out boolean o;\n  compute {\n    o = i + true;\n  }\n}' },
                at: 'i + true',
            },
            valid: {
                files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  port out boolean o;\n  compute {\n    o = i > 0;\n  }\n}' },
            },
        },
        {
            code: 'expr/unresolved-name',
            severity: 'error',
            rule: 'A name in an expression denotes a port, field, parameter, local variable, enum constant or type visible there.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  port out int o;\n  compute {\n    o = speed;\n  }\n}' }, at: 'speed' },
            valid: { files: { 'Foo.arc': 'component Foo(int speed) {\n  port out int o;\n  compute {\n    o = speed;\n  }\n}' } },
        },
        {
            code: 'expr/duplicate-case-label',
            severity: 'error',
            rule: 'The labels of a `switch` are distinct: every value labels one case, and there is at most one `default`.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    switch (i) {\n      case 1:\n        o = 1;\n        break;\n      case 2, 1:\n        o = 2;\n    }\n  }\n}',
                },
                at: '1',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    switch (i) {\n      case 1:\n        o = 1;\n        break;\n      case 2, 3:\n        o = 2;\n    }\n  }\n}',
                },
            },
        },
        {
            code: 'expr/mixed-switch-labels',
            severity: 'error',
            rule: 'A `switch` consists of either `case ...:` groups (which fall through) or `case ... ->` rules (which do not), not both; a rule has one label and one statement.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    switch (i) {\n      case 1:\n        o = 1;\n      case 2 -> o = 2;\n    }\n  }\n}',
                },
                at: 'i',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    switch (i) {\n      case 1 -> o = 1;\n      case 2, 3 -> o = 2;\n      default -> o = 0;\n    }\n  }\n}',
                },
            },
        },
        {
            code: 'expr/break-outside-loop',
            severity: 'error',
            rule: '`break` leaves the innermost loop (`while`, `do`, `for`) or `switch`; outside of them it has nothing to leave.',
            invalid: {
                files: { 'Foo.arc': 'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = i;\n    break;\n  }\n}' },
                at: 'break;',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = 0;\n    while (o < i) {\n      o++;\n      if (o > 9) break;\n    }\n  }\n}',
                },
            },
        },
        {
            code: 'expr/continue-outside-loop',
            severity: 'error',
            rule: '`continue` starts the next round of the innermost loop (`while`, `do`, `for`); a `switch` is no loop.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    switch (i) {\n      case 1:\n        continue;\n    }\n    o = i;\n  }\n}',
                },
                at: 'continue;',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = 0;\n    for (int k = 0; k < i; k++) {\n      if (k == 2) continue;\n      o = o + k;\n    }\n  }\n}',
                },
            },
        },
        {
            code: 'statement/switch-not-exhaustive',
            severity: 'error',
            rule: "A switch expression has a value for every selector value: a `default` arm, or (over an enum) an arm for every constant of the enum. (Switch expressions are Java 14's; MontiArc has none, this IDE offers them as an extension.)",
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = switch (i) {\n      case 1 -> 10;\n      case 2 -> 20;\n    };\n  }\n}',
                },
                at: 'i',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = switch (i) {\n      case 1 -> 10;\n      case 2 -> 20;\n      default -> 0;\n    };\n  }\n}',
                },
            },
        },
        {
            code: 'statement/missing-yield',
            severity: 'error',
            rule: 'A block arm of a switch expression (`case 1 -> { int y = 2; yield y; }`) ends with `yield value;` on every path: the yield gives the switch expression its value.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = switch (i) {\n      case 1 -> {\n        int y = i * 2;\n      }\n      default -> 0;\n    };\n  }\n}',
                },
                at: '{\n        int y = i * 2;\n      }',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = switch (i) {\n      case 1 -> {\n        int y = i * 2;\n        yield y;\n      }\n      default -> 0;\n    };\n  }\n}',
                },
            },
        },
        {
            code: 'statement/yield-outside-switch-expression',
            severity: 'error',
            rule: '`yield value;` gives a block arm of a switch expression its value; elsewhere (a compute block, a switch statement) it is not allowed. `yield` stays usable as a name.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    switch (i) {\n      case 1 -> {\n        yield 2;\n      }\n      default -> o = 1;\n    }\n  }\n}',
                },
                at: 'yield 2;',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    int yield = 2;\n    o = switch (i) {\n      case 1 -> {\n        yield yield;\n      }\n      default -> 1;\n    };\n  }\n}',
                },
            },
        },
        {
            code: 'statement/jump-out-of-switch-expression',
            severity: 'error',
            rule: '`break` and `continue` cannot leave a switch expression (its value would be missing); loops and switch statements inside an arm keep their own `break` and `continue`.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    while (o < i) {\n      o = switch (i) {\n        case 1 -> {\n          break;\n        }\n        default -> o + 1;\n      };\n    }\n  }\n}',
                },
                at: 'break;',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port in int i;\n  port out int o;\n  compute {\n    o = switch (i) {\n      case 1 -> {\n        int n = 0;\n        while (true) {\n          n++;\n          if (n > 3) break;\n        }\n        yield n;\n      }\n      default -> 0;\n    };\n  }\n}',
                },
            },
        },
        {
            code: 'variability/constraint-unsatisfied',
            severity: 'error',
            rule: 'The `constraint`s of a variable component (its own, inherited ones and those of its subcomponents, with the arguments they are instantiated with) admit at least one configuration of its features.',
            invalid: { files: { 'Foo.arc': 'component Foo {\n  feature fast;\n  constraint(fast);\n  constraint(!fast);\n}' }, at: 'Foo' },
            valid: { files: { 'Foo.arc': 'component Foo {\n  feature fast, cheap;\n  constraint(!(fast && cheap));\n}' } },
        },
        {
            code: 'variability/subcomponent-features-unconstrained',
            severity: 'error',
            rule: 'Each feature of a subcomponent is fixed by the constraints of the enclosing component (a function of its own features and parameters): a configuration of the component is a configuration of all its parts.',
            invalid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  port out int o;\n  component Sensor {\n    feature precise;\n    port out int v;\n  }\n  Sensor s;\n  s.v -> o;\n}',
                },
                at: 's',
            },
            valid: {
                files: {
                    'Foo.arc':
                        'component Foo {\n  feature fast;\n  port out int o;\n  component Sensor {\n    feature precise;\n    port out int v;\n  }\n  Sensor s;\n  s.v -> o;\n  constraint(s.precise == !fast);\n}',
                },
            },
        },
        {
            code: 'variability/expression-not-checkable',
            severity: 'error',
            rule: 'The condition of a `constraint` or `varif` uses features, parameters, literals and boolean, comparison and arithmetic operators only: method calls and array accesses cannot be decided when the configurations are enumerated.',
            invalid: { files: { 'Foo.arc': 'component Foo(int p) {\n  constraint(Math.abs(p) > 1);\n}' }, at: 'Math.abs(p)' },
            valid: { files: { 'Foo.arc': 'component Foo(int p) {\n  constraint(p > 1 || p < -1);\n}' } },
        },
        {
            code: 'variability/too-many-features',
            severity: 'warning',
            rule: 'A variable component is checked in each of its configurations when at most 16 features, boolean parameters and conditions decide them (2^16 assignments are enumerated) and at most 256 different selections of variation points result; beyond that it is checked once with every variation point included.',
            invalid: {
                files: {
                    'Foo.arc': 'component Foo {\n  feature f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16, f17;\n}',
                },
                at: 'Foo',
            },
            valid: {
                files: {
                    'Foo.arc': 'component Foo {\n  feature f1, f2, f3, f4, f5, f6, f7, f8, f9, f10, f11, f12, f13, f14, f15, f16;\n}',
                },
            },
        },
        {
            code: 'cd/duplicate-name',
            severity: 'error',
            rule: 'A class diagram declares each type once, and an enum each constant once.',
            invalid: { files: { 't/Types.cd': 'package t;\nclassdiagram Types {\n  enum Color { RED, RED; }\n}' }, at: 'RED' },
            valid: { files: { 't/Types.cd': 'package t;\nclassdiagram Types {\n  enum Color { RED, GREEN; }\n}' } },
        },
        {
            code: 'cd/file-name-mismatch',
            severity: 'error',
            rule: 'A class diagram is declared in a file named like it.',
            invalid: { files: { 't/Types.cd': 'package t;\nclassdiagram Other { }' }, at: 'Other' },
            valid: { files: { 't/Types.cd': 'package t;\nclassdiagram Types { }' } },
        },
        {
            code: 'cd/package-mismatch',
            severity: 'error',
            rule: "A class diagram's package equals its folder path below the model root.",
            invalid: { files: { 't/Types.cd': 'package x;\nclassdiagram Types { }' }, at: 'x' },
            valid: { files: { 't/Types.cd': 'package t;\nclassdiagram Types { }' } },
        },
    ],
};
