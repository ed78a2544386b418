import type { AstNode } from 'langium';
import type { FileBuilder, FileOptions, OutputSink, TemplateRenderer } from '../generators/types.js';

/** Key of the render context under which a FileBuilder passes its tracer to `{% trace %}`. */
export const TRACER_CONTEXT_KEY = '__maaTracer';

const OPEN = '\u0001';
const CLOSE = '\u0002';
// biome-ignore lint/suspicious/noControlCharactersInRegex: the marks are control characters no model text contains
const MARKER = /\u0001(\/?)(\d+)\u0002/g;

/** Allocates trace marks for model elements; text between an element's marks is traced to it. */
export class Tracer {
    private readonly elements: AstNode[] = [];

    wrap(element: AstNode, text: string): string {
        if (text.length === 0) return text;
        const id = this.elements.push(element) - 1;
        return `${OPEN}${id}${CLOSE}${text}${OPEN}/${id}${CLOSE}`;
    }

    open(element: AstNode): { begin: string; end: string } {
        const id = this.elements.push(element) - 1;
        return { begin: `${OPEN}${id}${CLOSE}`, end: `${OPEN}/${id}${CLOSE}` };
    }

    element(id: number): AstNode | undefined {
        return this.elements[id];
    }
}

/** A traced line range of a generated file (1-based, inclusive). */
export interface TracedRange {
    readonly startLine: number;
    readonly endLine: number;
    readonly element: AstNode;
    readonly generator: string;
}

export interface FinishedFile {
    readonly path: string;
    readonly content: string;
    readonly userFile: boolean;
    readonly generator: string;
    readonly traces: readonly TracedRange[];
}

/** A trace region whose close mark has not been met yet. */
interface OpenRegion {
    readonly startLine: number;
    readonly startOffset: number;
    /** Line breaks at the start of the region's text (a region starting at the end of a line starts on the next one). */
    leading: number;
}

/**
 * Strips trace marks from text and returns the line ranges they enclosed. One pass: the text is
 * collected in pieces, and lines, length and the regions' leading line breaks are counted as the
 * pieces come (no scan of the text collected so far: files with many marks stay linear).
 */
export function resolveTraceMarks(
    marked: string,
    tracer: Tracer,
): { content: string; ranges: Array<{ startLine: number; endLine: number; element: AstNode }> } {
    const pieces: string[] = [];
    let length = 0;
    let endsWithNewline = false;
    let line = 1;
    let last = 0;
    const open = new Map<number, OpenRegion>();
    // Regions that have seen only line breaks so far.
    const fresh = new Set<OpenRegion>();
    const ranges: Array<{ startLine: number; endLine: number; element: AstNode }> = [];
    const advance = (text: string): void => {
        if (text.length === 0) return;
        pieces.push(text);
        length += text.length;
        endsWithNewline = text.charCodeAt(text.length - 1) === 10;
        for (let i = text.indexOf('\n'); i !== -1; i = text.indexOf('\n', i + 1)) line++;
        if (fresh.size === 0) return;
        let breaks = 0;
        while (breaks < text.length && text.charCodeAt(breaks) === 10) breaks++;
        for (const region of fresh) {
            region.leading += breaks;
            if (breaks < text.length) fresh.delete(region);
        }
    };
    for (const m of marked.matchAll(MARKER)) {
        advance(marked.substring(last, m.index));
        last = m.index + m[0].length;
        const id = Number(m[2]);
        if (m[1] !== '/') {
            const region: OpenRegion = { startLine: line, startOffset: length, leading: 0 };
            open.set(id, region);
            fresh.add(region);
            continue;
        }
        const start = open.get(id);
        open.delete(id);
        if (start) fresh.delete(start);
        const element = tracer.element(id);
        if (!start || !element || length === start.startOffset) continue;
        const startLine = start.startLine + start.leading;
        const endLine = endsWithNewline ? line - 1 : line;
        if (endLine >= startLine) ranges.push({ startLine, endLine, element });
    }
    advance(marked.substring(last));
    ranges.sort((a, b) => a.startLine - b.startLine || b.endLine - a.endLine);
    return { content: pieces.join(''), ranges };
}

class DefaultFileBuilder implements FileBuilder {
    private text = '';
    readonly tracer = new Tracer();

    constructor(
        readonly path: string,
        readonly options: FileOptions,
        readonly generator: string,
        private readonly renderer: TemplateRenderer,
    ) {}

    write(text: string, element?: AstNode): this {
        this.text += element ? this.tracer.wrap(element, text) : text;
        return this;
    }

    line(text = '', element?: AstNode): this {
        return this.write(`${text}\n`, element);
    }

    traced<T>(element: AstNode, body: () => T): T {
        const { begin, end } = this.tracer.open(element);
        this.text += begin;
        try {
            return body();
        } finally {
            this.text += end;
        }
    }

    render(template: string, context: Record<string, unknown>, element?: AstNode): this {
        const out = this.renderer.render(template, { ...context, [TRACER_CONTEXT_KEY]: this.tracer });
        return this.write(out, element);
    }

    finish(): FinishedFile {
        const { content, ranges } = resolveTraceMarks(this.text, this.tracer);
        return {
            path: this.path,
            content,
            userFile: this.options.userFile === true,
            generator: this.generator,
            traces: ranges.map((r) => ({ ...r, generator: this.generator })),
        };
    }
}

/** A problem with a generator's output (bad or duplicate path). */
export class OutputError extends Error {}

/**
 * Collects the files of all generators of one run in memory; nothing touches the disk until
 * the run has succeeded (see writeOutput).
 */
export class OutputCollector {
    private readonly files = new Map<string, DefaultFileBuilder>();

    count(): number {
        return this.files.size;
    }

    /** The sink a generator writes to. */
    sink(generator: string, renderer: TemplateRenderer): OutputSink {
        return {
            file: (path: string, options: FileOptions = {}) => {
                const p = normalizePath(path, generator);
                const existing = this.files.get(p);
                if (existing) {
                    throw new OutputError(
                        `generator '${generator}' writes '${p}', which ${existing.generator === generator ? 'it has' : `generator '${existing.generator}' has`} already written`,
                    );
                }
                const b = new DefaultFileBuilder(p, options, generator, renderer);
                this.files.set(p, b);
                return b;
            },
        };
    }

    /** Every file, sorted by path. */
    finish(): FinishedFile[] {
        return [...this.files.values()].map((b) => b.finish()).sort((a, b) => (a.path < b.path ? -1 : a.path > b.path ? 1 : 0));
    }
}

/** Output paths are relative, use `/`, and stay inside the output folder. */
export function normalizePath(path: string, generator: string): string {
    const parts: string[] = [];
    if (path.startsWith('/') || /^[A-Za-z]:/.test(path) || path.includes('\\') || path.includes('\0')) {
        throw new OutputError(`generator '${generator}' writes '${path}': output paths are relative and use '/'`);
    }
    for (const seg of path.split('/')) {
        if (seg === '' || seg === '.') continue;
        if (seg === '..') throw new OutputError(`generator '${generator}' writes '${path}', which leaves the output folder`);
        parts.push(seg);
    }
    if (parts.length === 0) throw new OutputError(`generator '${generator}' writes a file without a name`);
    return parts.join('/');
}
