// The benchmarks' one table: each figure with its goal beside it (check-bench.mjs, generate-bench.mjs).

/** Prints `rows` ([measure, value, goal, met]) as a Markdown table with aligned columns. */
export function printTable(rows) {
    const header = ['measure', 'value', 'goal', ''];
    const widths = header.map((h, i) => Math.max(h.length, ...rows.map((r) => String(r[i]).length)));
    const line = (cells) => `| ${cells.map((c, i) => String(c).padEnd(widths[i])).join(' | ')} |`;
    console.log(line(header));
    console.log(`|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`);
    for (const r of rows) console.log(line(r));
}
