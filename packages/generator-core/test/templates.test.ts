import { describe, expect, test } from 'vitest';
import {
    camelCase,
    constantCase,
    indentLines,
    kebabCase,
    mergeProtectedRegions,
    pascalCase,
    pythonIdentifier,
    pythonString,
    snakeCase,
    xmlEscape,
} from '../src/index.js';
import { createTemplateEnvironment, createTemplateRenderer } from '../src/node.js';
import { resolveTraceMarks, Tracer } from '../src/output/file-builder.js';

describe('naming conventions', () => {
    test.each([
        [
            'ToastServiceRobot',
            'toast_service_robot',
            'ToastServiceRobot',
            'toastServiceRobot',
            'TOAST_SERVICE_ROBOT',
            'toast-service-robot',
        ],
        ['armController', 'arm_controller', 'ArmController', 'armController', 'ARM_CONTROLLER', 'arm-controller'],
        ['HTTPServer2go', 'http_server2go', 'HTTPServer2go', 'hTTPServer2go', 'HTTP_SERVER2GO', 'http-server2go'],
        [
            'toast_service robot',
            'toast_service_robot',
            'ToastServiceRobot',
            'toastServiceRobot',
            'TOAST_SERVICE_ROBOT',
            'toast-service-robot',
        ],
    ])('%s', (input, snake, pascal, camel, constant, kebab) => {
        expect([snakeCase(input), pascalCase(input), camelCase(input), constantCase(input), kebabCase(input)]).toEqual([
            snake,
            pascal,
            camel,
            constant,
            kebab,
        ]);
    });

    test('identifiers, strings and escaping', () => {
        expect(pythonIdentifier('class')).toBe('class_');
        expect(pythonIdentifier('2fast')).toBe('_2fast');
        expect(pythonString('say "hi"\n')).toBe('"say \\"hi\\"\\n"');
        expect(xmlEscape('<a & "b">')).toBe('&lt;a &amp; &quot;b&quot;&gt;');
        expect(indentLines('a\n\nb', 2)).toBe('  a\n\n  b');
    });
});

describe('the shared Nunjucks environment', () => {
    test('offers the naming filters, does not escape, and trims block lines', () => {
        const env = createTemplateEnvironment();
        const out = env.renderString(
            '{% for p in ports %}\n{{ p | snake_case }} = {{ p | py_str }}  # <{{ p | constant_case }}>\n{% endfor %}\n',
            { ports: ['distanceSensor', 'armCmd'] },
        );
        expect(out).toBe('distance_sensor = "distanceSensor"  # <DISTANCE_SENSOR>\narm_cmd = "armCmd"  # <ARM_CMD>\n');
    });

    test('an undefined variable is an error, not an empty string', () => {
        expect(() => createTemplateEnvironment().renderString('{{ missing.name }}', {})).toThrow();
    });

    test('{% trace %} marks the lines of an element for the trace file', () => {
        const tracer = new Tracer();
        const a = { $type: 'Port', name: 'a' } as never;
        const b = { $type: 'Port', name: 'b' } as never;
        const out = createTemplateRenderer().renderString(
            'header\n{% for p in ps %}\n{% trace p %}\nline {{ p.name }}\nmore {{ p.name }}\n{% endtrace %}\n{% endfor %}\nend\n',
            { ps: [a, b], __maaTracer: tracer },
        );
        const { content, ranges } = resolveTraceMarks(out, tracer);
        expect(content).toBe('header\nline a\nmore a\nline b\nmore b\nend\n');
        expect(ranges.map((r) => `${r.startLine}-${r.endLine} ${(r.element as unknown as { name: string }).name}`)).toEqual([
            '2-3 a',
            '4-5 b',
        ]);
    });

    test('trace marks resolve to the same lines as a plain scan of the text (nesting, leading and only line breaks, empty regions)', () => {
        // The definition resolveTraceMarks keeps (it counts as the text comes, in one pass): a
        // region spans from its first line with text (leading line breaks skipped) to the line
        // its text ends on; empty regions and regions of unknown elements give no range.
        // biome-ignore lint/suspicious/noControlCharactersInRegex: the trace marks are control characters
        const MARK = /\u0001(\/?)(\d+)\u0002/g;
        const reference = (marked: string, tracer: Tracer): Array<[number, number, unknown]> => {
            let content = '';
            const open = new Map<number, number>();
            const ranges: Array<[number, number, unknown]> = [];
            const lineAt = (offset: number): number => content.slice(0, offset).split('\n').length;
            let last = 0;
            for (const m of marked.matchAll(MARK)) {
                content += marked.substring(last, m.index);
                last = m.index + m[0].length;
                const id = Number(m[2]);
                if (m[1] !== '/') {
                    open.set(id, content.length);
                    continue;
                }
                const start = open.get(id);
                open.delete(id);
                const element = tracer.element(id);
                if (start === undefined || !element || start === content.length) continue;
                const leading = /^\n*/.exec(content.slice(start))![0].length;
                const first = lineAt(start) + leading;
                const lastLine = lineAt(content.length) - (content.endsWith('\n') ? 1 : 0);
                if (lastLine >= first) ranges.push([first, lastLine, element]);
            }
            return ranges.sort((a, b) => a[0] - b[0] || b[1] - a[1]);
        };
        // Texts from pieces and marks, chosen by a small deterministic generator.
        let seed = 7;
        const next = (n: number): number => {
            seed = (seed * 48271) % 2147483647;
            return seed % n;
        };
        const pieces = ['', '\n', '\n\n', 'x', 'ab\n', '\ncd', 'e\nf\n'];
        for (let round = 0; round < 300; round++) {
            const tracer = new Tracer();
            const open: Array<{ end: string }> = [];
            let marked = '';
            for (let step = 0; step < 12; step++) {
                const choice = next(4);
                if (choice === 0) {
                    const region = tracer.open({ $type: 'E', name: `e${round}.${step}` } as never);
                    open.push(region);
                    marked += region.begin;
                } else if (choice === 1 && open.length > 0) marked += open.pop()!.end;
                else marked += pieces[next(pieces.length)];
            }
            // A close mark never opened, of an element the tracer does not know: no range.
            marked += '\u0001/999\u0002';
            const { content, ranges } = resolveTraceMarks(marked, tracer);
            expect(content).toBe(marked.replace(MARK, ''));
            expect(ranges.map((r) => [r.startLine, r.endLine, r.element])).toEqual(reference(marked, tracer));
        }
    });

    test('a renderer without a template folder renders strings only', () => {
        expect(() => createTemplateRenderer().render('x.njk', {})).toThrow(/names no templates folder/);
    });
});

describe('protected regions', () => {
    test('carry the user content of the existing file into the regenerated one', () => {
        const generated =
            'a\n# PROTECTED REGION BEGIN imports\n# default\n# PROTECTED REGION END imports\nb\n// PROTECTED REGION BEGIN body\n// PROTECTED REGION END body\n';
        const existing =
            'old a\n# PROTECTED REGION BEGIN imports\nimport os\n# PROTECTED REGION END imports\n// PROTECTED REGION BEGIN gone\nx = 1\n// PROTECTED REGION END gone\n';
        const merged = mergeProtectedRegions(generated, existing);
        expect(merged.text).toBe(
            'a\n# PROTECTED REGION BEGIN imports\nimport os\n# PROTECTED REGION END imports\nb\n// PROTECTED REGION BEGIN body\n// PROTECTED REGION END body\n',
        );
        expect(merged.kept).toBe(1);
        expect(merged.dropped).toEqual(['gone']);
    });
});
