/**
 * Plot series over the timeline store: the numeric fields of a topic's messages (`data`,
 * `position.x`, `position[0]`), their values over a time span, and the SVG path of a series in a
 * plot's box. Pure.
 */
import type { TimelineStore } from './store.js';
import { xOf, type TimeSpan } from './window.js';

/** One series of a plot: a numeric field of a topic's messages. */
export interface SeriesKey {
    topic: string;
    /** Path into the message (`data`, `pose.position.x`, `position[1]`); `""`: the message itself. */
    field: string;
}

export interface Point {
    t: number;
    v: number;
}

/** The most fields listed for one message (a large array stays usable). */
const MAX_FIELDS = 64;

/** A value as a number: numbers, booleans (0/1); anything else is none. */
export function numeric(x: unknown): number | undefined {
    if (typeof x === 'number') return Number.isFinite(x) ? x : undefined;
    if (typeof x === 'boolean') return x ? 1 : 0;
    return undefined;
}

/** The paths of the numeric leaves of a message, in field order. */
export function numericFields(message: unknown): string[] {
    const out: string[] = [];
    const walk = (x: unknown, path: string): void => {
        if (out.length >= MAX_FIELDS) return;
        if (numeric(x) !== undefined) {
            out.push(path);
            return;
        }
        if (Array.isArray(x)) for (const [i, e] of x.entries()) walk(e, `${path}[${i}]`);
        else if (x && typeof x === 'object')
            for (const [k, v] of Object.entries(x as Record<string, unknown>)) walk(v, path ? `${path}.${k}` : k);
    };
    walk(message, '');
    return out;
}

/** The segments of a field path: `a.b[2]` → `['a', 'b', 2]`; `undefined` when malformed. */
export function parseField(field: string): Array<string | number> | undefined {
    if (field === '') return [];
    const out: Array<string | number> = [];
    const re = /([^.[\]]+)|\[(\d+)\]/gy;
    let pos = 0;
    while (pos < field.length) {
        if (field[pos] === '.' && pos > 0) pos++;
        re.lastIndex = pos;
        const m = re.exec(field);
        if (!m) return undefined;
        out.push(m[1] !== undefined ? m[1] : Number(m[2]));
        pos = re.lastIndex;
    }
    return out;
}

/** The number at `field` of a message, `undefined` when there is none. */
export function fieldValue(message: unknown, field: string): number | undefined {
    const path = parseField(field);
    if (!path) return undefined;
    let x: unknown = message;
    for (const seg of path) {
        if (x === null || typeof x !== 'object') return undefined;
        x = (x as Record<string | number, unknown>)[seg];
    }
    return numeric(x);
}

/**
 * The points of a series in a span, plus the last one before it (so a line enters the plot
 * from its left edge).
 */
export function seriesPoints(store: TimelineStore, key: SeriesKey, span: TimeSpan): Point[] {
    const out: Point[] = [];
    const before = store.latestAt(key.topic, span.t0);
    if (before && before.t < span.t0) {
        const v = fieldValue(before.message, key.field);
        if (v !== undefined) out.push({ t: before.t, v });
    }
    for (const m of store.range(key.topic, span.t0, span.t1)) {
        const v = fieldValue(m.message, key.field);
        if (v !== undefined) out.push({ t: m.t, v });
    }
    return out;
}

/** Minimum and maximum of the values of several series (a flat range widened by ±1), `undefined` when empty. */
export function valueRange(series: readonly (readonly Point[])[]): { min: number; max: number } | undefined {
    let min = Infinity;
    let max = -Infinity;
    for (const s of series)
        for (const p of s) {
            if (p.v < min) min = p.v;
            if (p.v > max) max = p.v;
        }
    if (min === Infinity) return undefined;
    if (min === max) return { min: min - 1, max: max + 1 };
    const pad = (max - min) * 0.05;
    return { min: min - pad, max: max + pad };
}

/**
 * The SVG path of a series as a step line (a port holds its value until the next message) in a
 * `width` × `height` box; a point that keeps the value adds nothing, and points on one pixel
 * column become one vertical stroke, so a long run still draws a short path.
 */
export function seriesPath(
    points: readonly Point[],
    span: TimeSpan,
    range: { min: number; max: number },
    width: number,
    height: number,
): string {
    if (points.length === 0) return '';
    const yOf = (v: number): number => height - ((v - range.min) / (range.max - range.min)) * height;
    const parts: string[] = [];
    let lastX = Number.NaN;
    let lastY = Number.NaN;
    for (const p of points) {
        const x = round(Math.max(-1, xOf(p.t, span, width)));
        const y = round(yOf(p.v));
        if (parts.length === 0) parts.push(`M ${x} ${y}`);
        else if (y === lastY)
            continue; // the step line holds it anyway
        else if (x === lastX) parts.push(`V ${y}`);
        else parts.push(`H ${x} V ${y}`);
        lastX = x;
        lastY = y;
    }
    // the last value holds until the end of the span (or of the data)
    parts.push(`H ${round(Math.min(width, xOf(span.t1, span, width)))}`);
    return parts.join(' ');
}

function round(n: number): number {
    return Math.round(n * 10) / 10;
}
