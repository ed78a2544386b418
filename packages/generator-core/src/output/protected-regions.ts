/**
 * Protected regions: in a generated file, the lines between a line containing
 * `PROTECTED REGION BEGIN <id>` and a line containing `PROTECTED REGION END <id>` (in any
 * comment syntax, e.g. `# PROTECTED REGION BEGIN imports`) belong to the user. On
 * regeneration the region's lines from the existing file replace the generated default.
 */
const BEGIN = /PROTECTED REGION BEGIN\s+([^\s*#/-][^\s]*)/;
const END = /PROTECTED REGION END\s+([^\s*#/-][^\s]*)/;

/** The regions of a text: id -> the lines strictly between its markers. */
export function protectedRegions(text: string): Map<string, string[]> {
    const regions = new Map<string, string[]>();
    let current: { id: string; lines: string[] } | undefined;
    for (const line of text.split('\n')) {
        if (current) {
            const end = END.exec(line);
            if (end && end[1] === current.id) {
                regions.set(current.id, current.lines);
                current = undefined;
            } else {
                current.lines.push(line);
            }
            continue;
        }
        const begin = BEGIN.exec(line);
        if (begin && !regions.has(begin[1]!)) current = { id: begin[1]!, lines: [] };
    }
    return regions;
}

/**
 * The generated text with the user's regions of `existing` put back. Returns the merged text,
 * how many regions hold user content (differing from the generated default), and the regions
 * the new text no longer has (dropped, which the caller may want to report).
 */
export function mergeProtectedRegions(generated: string, existing: string): { text: string; kept: number; dropped: string[] } {
    const old = protectedRegions(existing);
    if (old.size === 0) return { text: generated, kept: 0, dropped: [] };
    const out: string[] = [];
    const used = new Set<string>();
    let kept = 0;
    let skipping: { id: string; defaults: string[] } | undefined;
    for (const line of generated.split('\n')) {
        if (skipping !== undefined) {
            const end = END.exec(line);
            if (end && end[1] === skipping.id) {
                out.push(line);
                if (skipping.defaults.join('\n') !== old.get(skipping.id)!.join('\n')) kept++;
                skipping = undefined;
            } else {
                skipping.defaults.push(line);
            }
            continue;
        }
        out.push(line);
        const begin = BEGIN.exec(line);
        const id = begin?.[1];
        if (id !== undefined && old.has(id) && !used.has(id)) {
            out.push(...old.get(id)!);
            used.add(id);
            skipping = { id, defaults: [] };
        }
    }
    if (skipping !== undefined) {
        // The generated text never closes the region: keep it as generated.
        return { text: generated, kept: 0, dropped: [] };
    }
    return { text: out.join('\n'), kept, dropped: [...old.keys()].filter((k) => !used.has(k)) };
}
