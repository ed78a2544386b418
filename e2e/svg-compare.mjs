// Compares two diagram SVGs by their model elements: the IDE's Export SVG (ids `<baseDiv>_<id>`,
// styles inlined by Sprotty's exporter) and `maa-gen diagram`'s (ids `maa-diagram_<id>`, a
// stylesheet inside). Both are XML written by a serializer: attributes in double quotes.
import { execFile } from 'node:child_process';
import path from 'node:path';
import { repo } from './lib.mjs';

const decode = (text) =>
    text
        .replace(/&lt;/g, '<')
        .replace(/&gt;/g, '>')
        .replace(/&quot;/g, '"')
        .replace(/&#39;|&apos;/g, "'")
        .replace(/&amp;/g, '&');

/** The model ids of a diagram SVG (the part after the first `_` of every element id), sorted. */
export function diagramIds(svg) {
    const ids = [...svg.matchAll(/<[\w:-]+\b[^>]*?\sid="([^"]*)"/g)].map((m) => decode(m[1])).filter((id) => id.includes('_'));
    return ids.map((id) => id.slice(id.indexOf('_') + 1)).sort();
}

/** The texts of the diagram's text elements that carry a model id (names, types, ports, transitions), by id. */
export function diagramTexts(svg) {
    const texts = new Map();
    for (const m of svg.matchAll(/<text\b[^>]*?\sid="([^"]*)"[^>]*>([^<]*)/g)) {
        const id = decode(m[1]);
        texts.set(id.slice(id.indexOf('_') + 1), decode(m[2]).trim());
    }
    return texts;
}

/** Classes the IDE adds for what a user does (selection, hover): not part of the model's drawing. */
const INTERACTION_CLASSES = new Set(['selected', 'mouseover']);

/** The classes of every element with a model id, sorted and without the interaction classes, by id. */
export function diagramClasses(svg) {
    const classes = new Map();
    for (const m of svg.matchAll(/<[\w:-]+\b([^>]*)>/g)) {
        const id = /\sid="([^"]*)"/.exec(m[1])?.[1];
        if (id === undefined || !id.includes('_')) continue;
        const cls = (/\sclass="([^"]*)"/.exec(m[1])?.[1] ?? '').split(/\s+/).filter((c) => c && !INTERACTION_CLASSES.has(c));
        classes.set(decode(id).slice(id.indexOf('_') + 1), cls.sort().join(' '));
    }
    return classes;
}

/** The route of every edge (the numbers of its path's `d`), by model id. */
export function diagramRoutes(svg) {
    const routes = new Map();
    for (const m of svg.matchAll(/<g\b([^>]*)>\s*<path\b[^>]*?\sd="([^"]*)"/g)) {
        const id = /\sid="([^"]*)"/.exec(m[1])?.[1];
        if (id === undefined || !/_(conn|tr):/.test(id)) continue;
        routes.set(
            decode(id).slice(id.indexOf('_') + 1),
            [...m[2].matchAll(/-?\d+(?:\.\d+)?(?:e-?\d+)?/g)].map((n) => Number(n[0])),
        );
    }
    return routes;
}

/** Whether two routes are the same up to rounding (the IDE prints full precision, maa-gen three decimals). */
export function sameRoute(a, b) {
    return a !== undefined && b !== undefined && a.length === b.length && a.every((x, i) => Math.abs(x - b[i]) < 0.01);
}

/** What differs between two lists of ids (empty when equal as sets). */
export function idDifference(a, b) {
    const sa = new Set(a);
    const sb = new Set(b);
    return { onlyFirst: [...sa].filter((x) => !sb.has(x)), onlySecond: [...sb].filter((x) => !sa.has(x)) };
}

/** Runs the built `maa-gen diagram ARGS... --out -` and resolves with its SVG. */
export function cliDiagram(args) {
    const bin = path.join(repo, 'packages', 'cli', 'bin', 'maa-gen.js');
    return new Promise((resolve, reject) => {
        execFile(
            process.execPath,
            [bin, 'diagram', ...args, '--out', '-'],
            { cwd: repo, maxBuffer: 64 * 1024 * 1024 },
            (error, stdout, stderr) => {
                if (error) reject(new Error(`maa-gen diagram ${args.join(' ')} failed (${error.code}):\n${stderr}`));
                else resolve(stdout);
            },
        );
    });
}
