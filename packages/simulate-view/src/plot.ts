/** The live plot's data: a bounded window of samples and its SVG path. Pure. */

export interface Sample {
    /** Time (simulation seconds, or wall-clock seconds when no clock is known). */
    t: number;
    v: number;
}

/** The last `capacity` samples (a ring buffer; oldest dropped first). */
export class SampleWindow {
    private readonly buf: Sample[] = [];
    private start = 0;

    constructor(readonly capacity = 200) {
        if (!(capacity >= 1)) throw new Error('capacity must be at least 1');
    }

    get length(): number {
        return this.buf.length;
    }

    push(t: number, v: number): void {
        if (!Number.isFinite(v) || !Number.isFinite(t)) return;
        if (this.buf.length < this.capacity) {
            this.buf.push({ t, v });
        } else {
            this.buf[this.start] = { t, v };
            this.start = (this.start + 1) % this.capacity;
        }
    }

    clear(): void {
        this.buf.length = 0;
        this.start = 0;
    }

    /** Oldest first. */
    samples(): Sample[] {
        return [...this.buf.slice(this.start), ...this.buf.slice(0, this.start)];
    }

    /** Minimum and maximum of the values, `undefined` when empty. */
    range(): { min: number; max: number } | undefined {
        if (this.buf.length === 0) return undefined;
        let min = Infinity;
        let max = -Infinity;
        for (const s of this.buf) {
            if (s.v < min) min = s.v;
            if (s.v > max) max = s.v;
        }
        return { min, max };
    }

    last(): Sample | undefined {
        if (this.buf.length === 0) return undefined;
        return this.buf[(this.start + this.buf.length - 1) % this.buf.length];
    }
}

/**
 * The SVG path (`M x y L …`) of the samples scaled into a `width` × `height` box (y up, a flat
 * series in the middle); samples are spread by index so a paused clock still draws.
 */
export function sparklinePath(samples: readonly Sample[], width: number, height: number, pad = 2): string {
    if (samples.length === 0) return '';
    let min = Infinity;
    let max = -Infinity;
    for (const s of samples) {
        min = Math.min(min, s.v);
        max = Math.max(max, s.v);
    }
    const h = height - 2 * pad;
    const w = width - 2 * pad;
    const span = max - min;
    const n = samples.length;
    const pts = samples.map((s, i) => {
        const x = pad + (n === 1 ? w : (i / (n - 1)) * w);
        const y = span === 0 ? height / 2 : pad + h - ((s.v - min) / span) * h;
        return `${round(x)} ${round(y)}`;
    });
    return `M ${pts.join(' L ')}`;
}

function round(n: number): number {
    return Math.round(n * 10) / 10;
}
