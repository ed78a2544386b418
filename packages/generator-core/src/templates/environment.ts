import nunjucks from 'nunjucks';
import type { AstNode } from 'langium';
import type { TemplateRenderer } from '../generators/types.js';
import { TRACER_CONTEXT_KEY, type Tracer } from '../output/file-builder.js';
import {
    camelCase,
    constantCase,
    indentLines,
    kebabCase,
    pascalCase,
    pythonIdentifier,
    pythonString,
    snakeCase,
    xmlEscape,
} from './naming.js';

/** The filters every generator's templates get. */
export const TEMPLATE_FILTERS: Readonly<Record<string, (...args: never[]) => unknown>> = {
    snake_case: (s: unknown) => snakeCase(String(s)),
    pascal_case: (s: unknown) => pascalCase(String(s)),
    camel_case: (s: unknown) => camelCase(String(s)),
    constant_case: (s: unknown) => constantCase(String(s)),
    kebab_case: (s: unknown) => kebabCase(String(s)),
    indent_lines: (s: unknown, width?: number | string) => indentLines(String(s), width ?? 4),
    py_ident: (s: unknown) => pythonIdentifier(String(s)),
    py_str: (s: unknown) => pythonString(s),
    xml_escape: (s: unknown) => xmlEscape(s),
    json: (v: unknown, indent?: number) => JSON.stringify(v, null, indent),
};

interface NunjucksParser {
    nextToken(): { value: string };
    parseSignature(a: null, b: boolean): unknown;
    advanceAfterBlockEnd(name?: string): void;
    parseUntilBlocks(...names: string[]): unknown;
}

interface NunjucksNodes {
    CallExtension: new (ext: object, method: string, args: unknown, contentArgs: unknown[]) => unknown;
}

/**
 * `{% trace element %}...{% endtrace %}`: the enclosed output is traced to the model element
 * (the trace file maps its line range to the element). Outside a FileBuilder it renders the
 * body unchanged.
 */
class TraceExtension {
    readonly tags = ['trace'];

    parse(parser: NunjucksParser, nodes: NunjucksNodes): unknown {
        const tok = parser.nextToken();
        const args = parser.parseSignature(null, true);
        parser.advanceAfterBlockEnd(tok.value);
        const body = parser.parseUntilBlocks('endtrace');
        parser.advanceAfterBlockEnd();
        return new nodes.CallExtension(this, 'run', args, [body]);
    }

    run(context: { ctx: Record<string, unknown> }, element: unknown, body: () => string): nunjucks.runtime.SafeString {
        const text = body();
        const tracer = context.ctx[TRACER_CONTEXT_KEY] as Tracer | undefined;
        const isNode = typeof element === 'object' && element !== null && typeof (element as AstNode).$type === 'string';
        const node = isNode ? (element as AstNode) : (element as { node?: AstNode } | undefined)?.node;
        return new nunjucks.runtime.SafeString(tracer && node ? tracer.wrap(node, text) : text);
    }
}

/**
 * The shared Nunjucks environment of all generators: no HTML escaping (the output is code),
 * undefined variables are errors (a typo must not silently produce broken code), block tags
 * do not leave blank lines, plus the naming, indentation and escaping filters and the
 * `{% trace %}` tag.
 */
export function createTemplateEnvironment(searchPaths: readonly string[] = []): nunjucks.Environment {
    const loader = searchPaths.length > 0 ? new nunjucks.FileSystemLoader([...searchPaths], { noCache: false }) : null;
    const env = new nunjucks.Environment(loader, { autoescape: false, throwOnUndefined: true, trimBlocks: true, lstripBlocks: true });
    for (const [name, fn] of Object.entries(TEMPLATE_FILTERS)) env.addFilter(name, fn as (...args: unknown[]) => unknown);
    env.addExtension('TraceExtension', new TraceExtension() as unknown as nunjucks.Extension);
    return env;
}

/** A renderer over a generator's template folder (manifest `templates`), or none. */
export function createTemplateRenderer(templatesDir?: string): TemplateRenderer {
    const env = createTemplateEnvironment(templatesDir ? [templatesDir] : []);
    return {
        render: (template, context) => {
            if (!templatesDir) throw new Error(`cannot render '${template}': the generator's manifest names no templates folder`);
            return env.render(template, context);
        },
        renderString: (source, context) => env.renderString(source, context),
    };
}
