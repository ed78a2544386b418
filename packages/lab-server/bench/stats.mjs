// Figures of the lab load benchmark (lab-bench.mjs): percentiles and per-kind summaries.
// Pure functions, tested by test/bench-stats.test.ts.

/**
 * The p-th percentile (0..100) of the numbers by the nearest-rank method: the smallest value
 * with at least p% of the values at or below it. NaN for no values.
 */
export function percentile(values, p) {
    if (values.length === 0) return Number.NaN;
    const sorted = [...values].sort((a, b) => a - b);
    const rank = Math.max(1, Math.ceil((p / 100) * sorted.length));
    return sorted[Math.min(rank, sorted.length) - 1];
}

/** The median (the mean of the two middle values for an even count); NaN for no values. */
export function median(values) {
    if (values.length === 0) return Number.NaN;
    const s = [...values].sort((a, b) => a - b);
    const mid = Math.floor(s.length / 2);
    return s.length % 2 ? s[mid] : (s[mid - 1] + s[mid]) / 2;
}

/**
 * One row per request kind and an `overall` row: count, requests per second over `seconds`,
 * p50/p90/p99 latency in ms, errors.
 * @param samples [{kind, ms, ok}]
 */
export function summarize(samples, seconds) {
    const kinds = [...new Set(samples.map((s) => s.kind))];
    const row = (kind, of) => ({
        kind,
        count: of.length,
        perSecond: seconds > 0 ? of.length / seconds : 0,
        p50: percentile(
            of.map((s) => s.ms),
            50,
        ),
        p90: percentile(
            of.map((s) => s.ms),
            90,
        ),
        p99: percentile(
            of.map((s) => s.ms),
            99,
        ),
        errors: of.filter((s) => !s.ok).length,
    });
    return [
        ...kinds.map((k) =>
            row(
                k,
                samples.filter((s) => s.kind === k),
            ),
        ),
        row('overall', samples),
    ];
}
