/**
 * **Show generated code** and **Show model element**: lookups in a trace file
 * (`<out>/<platform>/.maa-trace.json`, @maa/protocol's TraceFile) in both directions. Pure: paths
 * in, paths and 0-based ranges out; the extension opens the editors. No Node built-ins (the web
 * entry bundles this for the browser): paths are handled with `/`, a Windows path's `\` read as
 * `/` (`C:/a/b`), which `vscode.Uri.file` accepts too.
 */
import type { Position, Range, Trace, TraceFile } from '@maa/protocol';

/** Where generated lines are: an absolute file and 0-based inclusive lines. */
export interface GeneratedLocation {
    readonly file: string;
    readonly first: number;
    readonly last: number;
    readonly generator: string;
}

/** A model element: its absolute file and 0-based range. */
export interface ModelLocation {
    readonly file: string;
    readonly range: Range;
    readonly type: string;
    readonly name?: string;
}

/** `p` with `/` separators, `.` and `..` segments resolved (an absolute path: `/a`, `C:/a`). */
function normalize(p: string): string {
    const slashed = p.replace(/\\/g, '/');
    const root = /^[A-Za-z]:\//.exec(slashed)?.[0] ?? (slashed.startsWith('/') ? '/' : '');
    const parts: string[] = [];
    for (const segment of slashed.slice(root.length).split('/')) {
        if (segment === '..') parts.pop();
        else if (segment !== '' && segment !== '.') parts.push(segment);
    }
    return root + parts.join('/');
}

function isAbsolute(p: string): boolean {
    return /^([A-Za-z]:)?[\\/]/.test(p);
}

/** Like `path.resolve` for absolute bases: the last absolute segment onwards, joined and normalized. */
function resolve(...segments: string[]): string {
    let start = 0;
    segments.forEach((s, i) => {
        if (isAbsolute(s)) start = i;
    });
    return normalize(segments.slice(start).join('/'));
}

/** The absolute model file of a trace element (relative to the model root, which is relative to the platform folder). */
export function modelFileOf(trace: TraceFile, platformDir: string, elementFile: string): string {
    if (/^[a-z][a-z0-9+.-]*:\/\//i.test(elementFile)) return elementFile;
    return resolve(platformDir, trace.modelRoot, elementFile);
}

function before(a: Position, b: Position): boolean {
    return a.line < b.line || (a.line === b.line && a.character <= b.character);
}

function contains(range: Range, pos: Position): boolean {
    return before(range.start, pos) && before(pos, range.end);
}

/** A size to order ranges by (smaller is more specific). */
function extent(range: Range): number {
    return (range.end.line - range.start.line) * 1_000_000 + (range.end.character - range.start.character);
}

/**
 * The generated code of the innermost model element at `pos` in `modelFile`: every traced line
 * span of that element (in generated-file order); empty when nothing traced contains the position.
 */
export function generatedCodeAt(trace: TraceFile, platformDir: string, modelFile: string, pos: Position): GeneratedLocation[] {
    const target = resolve(modelFile);
    const hits: Array<{ file: string; t: Trace; range: Range }> = [];
    for (const f of trace.files) {
        for (const t of f.traces) {
            const range = t.element.range;
            if (!range || modelFileOf(trace, platformDir, t.element.file) !== target || !contains(range, pos)) continue;
            hits.push({ file: resolve(platformDir, f.path), t, range });
        }
    }
    if (hits.length === 0) return [];
    const smallest = Math.min(...hits.map((h) => extent(h.range)));
    const inner = hits.filter((h) => extent(h.range) === smallest);
    // Of equally small elements (siblings cannot overlap, so these are the same element) keep all spans.
    return inner
        .map((h) => ({ file: h.file, first: h.t.lines.first, last: h.t.lines.last, generator: h.t.generator }))
        .sort((a, b) => a.file.localeCompare(b.file) || a.first - b.first);
}

/** The model element the generated `line` (0-based) of `generatedFile` comes from: the narrowest traced span around it. */
export function modelElementAt(trace: TraceFile, platformDir: string, generatedFile: string, line: number): ModelLocation | undefined {
    const dir = `${resolve(platformDir)}/`;
    const generated = resolve(generatedFile);
    const rel = generated.startsWith(dir) ? generated.slice(dir.length) : undefined;
    const file = rel === undefined ? undefined : trace.files.find((f) => f.path === rel);
    if (!file) return undefined;
    let best: Trace | undefined;
    for (const t of file.traces) {
        if (line < t.lines.first || line > t.lines.last || !t.element.range) continue;
        if (!best || t.lines.last - t.lines.first < best.lines.last - best.lines.first) best = t;
    }
    if (!best?.element.range) return undefined;
    return {
        file: modelFileOf(trace, platformDir, best.element.file),
        range: best.element.range,
        type: best.element.type,
        ...(best.element.name === undefined ? {} : { name: best.element.name }),
    };
}

/** The platform folder a generated file belongs to: the nearest ancestor among the folders holding a trace file (as given). */
export function platformDirOf(generatedFile: string, traceDirs: readonly string[]): string | undefined {
    const file = resolve(generatedFile);
    return traceDirs
        .map((given) => ({ given, dir: resolve(given) }))
        .filter(({ dir }) => file.startsWith(`${dir}/`))
        .sort((a, b) => b.dir.length - a.dir.length)[0]?.given;
}
