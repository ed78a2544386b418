/**
 * The time window the panels draw (plots and the state timeline share one): which span of
 * simulated time maps onto a panel's width, zoomed by the wheel and panned by dragging. While it
 * follows (the default), it shows the newest `span` seconds of the store; zooming or panning
 * stops following, `follow()` (the "Live" button) resumes it. Pure.
 */

export interface TimeSpan {
    t0: number;
    t1: number;
}

/** The shortest span a zoom reaches (1 ms) and the longest (a day). */
export const MIN_SPAN = 0.001;
export const MAX_SPAN = 86_400;
const DEFAULT_SPAN = 10;

export class TimeWindow {
    private fixed: TimeSpan | undefined;
    private followSpan = DEFAULT_SPAN;

    /** Shows the newest data (the window ends at the store's end). */
    get following(): boolean {
        return this.fixed === undefined;
    }

    /** The span to draw for data from `start` to `end` (`undefined`: no data yet). */
    span(start: number | undefined, end: number | undefined): TimeSpan {
        if (this.fixed) return { ...this.fixed };
        const last = end ?? 0;
        const first = start ?? last;
        // the whole run while it is shorter than the span, then the newest span seconds
        const t0 = Math.max(first, last - this.followSpan);
        return { t0, t1: Math.max(t0 + MIN_SPAN, last) };
    }

    follow(): void {
        if (this.fixed) this.followSpan = clampSpan(this.fixed.t1 - this.fixed.t0);
        this.fixed = undefined;
    }

    /** Sets the window (stops following). */
    set(span: TimeSpan): void {
        const width = clampSpan(span.t1 - span.t0);
        const mid = (span.t0 + span.t1) / 2;
        this.fixed = Number.isFinite(mid) ? { t0: mid - width / 2, t1: mid + width / 2 } : this.fixed;
    }

    /** Zooms by `factor` (< 1 in, > 1 out) around the time `anchor`, from the span now shown. */
    zoom(current: TimeSpan, factor: number, anchor: number): void {
        if (!(factor > 0) || !Number.isFinite(anchor)) return;
        const width = clampSpan((current.t1 - current.t0) * factor);
        const ratio = current.t1 > current.t0 ? (anchor - current.t0) / (current.t1 - current.t0) : 0.5;
        const t0 = anchor - ratio * width;
        this.fixed = { t0, t1: t0 + width };
    }

    /** Moves the span now shown by `dt` seconds (positive: later). */
    pan(current: TimeSpan, dt: number): void {
        if (!Number.isFinite(dt)) return;
        this.fixed = { t0: current.t0 + dt, t1: current.t1 + dt };
    }
}

function clampSpan(w: number): number {
    return Math.min(MAX_SPAN, Math.max(MIN_SPAN, Number.isFinite(w) ? w : DEFAULT_SPAN));
}

/** The x coordinate of time `t` in a `width` wide drawing of `span`. */
export function xOf(t: number, span: TimeSpan, width: number): number {
    const w = span.t1 - span.t0;
    return w > 0 ? ((t - span.t0) / w) * width : 0;
}

/** The time at x coordinate `x` of a `width` wide drawing of `span`. */
export function tOf(x: number, span: TimeSpan, width: number): number {
    return width > 0 ? span.t0 + (x / width) * (span.t1 - span.t0) : span.t0;
}

/** Ticks for a time axis: round times (1, 2, 5 × 10^k seconds apart) inside the span, at most about `count`. */
export function timeTicks(span: TimeSpan, count = 6): number[] {
    const w = span.t1 - span.t0;
    if (!(w > 0) || count < 1) return [];
    const raw = w / count;
    const mag = 10 ** Math.floor(Math.log10(raw));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => s >= raw) ?? 10 * mag;
    const ticks: number[] = [];
    for (let t = Math.ceil(span.t0 / step) * step; t <= span.t1 + step * 1e-9; t += step) ticks.push(Number(t.toFixed(9)));
    return ticks;
}

/** A time as the panels label it: seconds with as many decimals as the span needs. */
export function formatTime(t: number, span?: number): string {
    const decimals = span === undefined ? 3 : span < 0.1 ? 4 : span < 1 ? 3 : span < 10 ? 2 : span < 100 ? 1 : 0;
    return `${t.toFixed(decimals)} s`;
}
