import { mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import type { MaaGraph } from '@maa/language-server';
import { CliError } from '../errors.js';
import type { CliIo } from '../io.js';

export type DiagramFormat = 'svg' | 'png';

/**
 * The SVG as a PNG, `scale` pixels per SVG unit, by resvg (a Rust SVG renderer with prebuilt
 * binaries on npm; no browser). Text is drawn with the system's fonts: DejaVu Sans, whose
 * metrics the layout's label sizes come from, where the stylesheet's families are missing.
 */
export async function rasterize(svg: string, scale: number): Promise<Buffer> {
    const { Resvg } = await import('@resvg/resvg-js');
    const resvg = new Resvg(svg, {
        fitTo: { mode: 'zoom', value: scale },
        font: { loadSystemFonts: true, defaultFontFamily: 'DejaVu Sans', sansSerifFamily: 'DejaVu Sans' },
    });
    return resvg.render().asPng();
}

/** Writes the diagram to `out` (`-`: standard output), creating its folder; a failure is an I/O problem. */
export function writeOutput(out: string, data: string | Buffer, io: CliIo): void {
    if (out === '-') {
        io.out(typeof data === 'string' ? data : data.toString('latin1'));
        return;
    }
    const file = path.resolve(io.cwd, out);
    try {
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, data);
    } catch (e) {
        const code = (e as NodeJS.ErrnoException).code;
        throw new CliError(`cannot write ${out}: ${code === 'EACCES' || code === 'EPERM' ? 'permission denied' : (code ?? String(e))}`);
    }
}

/** What the diagram shows, for the report line: `C&C view of toast.X: 8 components, 31 ports, 24 connectors`. */
export function diagramSummary(graph: MaaGraph, component: string): string {
    const counts = new Map<string, number>();
    const visit = (e: { type: string; children?: ReadonlyArray<{ type: string }> }): void => {
        counts.set(e.type, (counts.get(e.type) ?? 0) + 1);
        for (const c of e.children ?? []) visit(c);
    };
    for (const c of graph.children) visit(c);
    const n = (type: string, word: string): string => `${counts.get(type) ?? 0} ${word}${counts.get(type) === 1 ? '' : 's'}`;
    return graph.id.startsWith('automaton:')
        ? `state machine of ${component}: ${n('node:state', 'state')}, ${n('edge:transition', 'transition')}`
        : `C&C view of ${component}: ${n('node:component', 'component')}, ${n('port', 'port')}, ${n('edge:connector', 'connector')}`;
}
