/**
 * What `maa-gen test` (packages/cli) and the IDE backend's `POST /api/test` (packages/ide-server)
 * share about the stream tests the time-synchronous runtime runs (`python -m
 * maa_timesync.streamtest BUILD --json FILE…`): the result of one test as the runner prints it,
 * which files a run finds by default, and the `--case` selection.
 */
import { readdir } from 'node:fs/promises';
import path from 'node:path';

/** One test's result, as the runner's `--json` prints it (`test` null: a file whose tests did not run). */
export interface StreamTestResult {
    file: string;
    test: string | null;
    line: number;
    passed: boolean;
    problems: string[];
}

/** Whether the search enters a folder or looks at a file: it skips hidden ones, node_modules and generated. */
function visited(name: string): boolean {
    return !name.startsWith('.') && name !== 'node_modules' && name !== 'generated';
}

/** Every `*.stream` file below a folder (absolute; skipping node_modules, generated output and hidden folders), sorted by name folder by folder. */
export async function findStreamFiles(dir: string): Promise<string[]> {
    const out: string[] = [];
    const visit = async (d: string): Promise<void> => {
        const entries = await readdir(d, { withFileTypes: true });
        for (const entry of entries.sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0))) {
            if (!visited(entry.name)) continue;
            const full = path.join(d, entry.name);
            if (entry.isDirectory()) await visit(full);
            else if (entry.isFile() && entry.name.endsWith('.stream')) out.push(full);
        }
    };
    await visit(dir);
    return out;
}

/**
 * The results of the tests `cases` names (all when it names none). A file-level result (`test`
 * null: a file that does not parse or names no component of the application) stays, since its
 * cases did not run; a name no file has a test of is refused with `refuse(message)`'s error.
 */
export function selectCases(
    results: readonly StreamTestResult[],
    cases: readonly string[] | undefined,
    refuse: (message: string) => Error,
): StreamTestResult[] {
    if (!cases || cases.length === 0) return [...results];
    const missing = cases.filter((c) => !results.some((r) => r.test === c));
    if (missing.length > 0 && !results.some((r) => r.test === null)) {
        throw refuse(`no stream test named ${missing.map((c) => JSON.stringify(c)).join(', ')} in the files run`);
    }
    return results.filter((r) => r.test === null || cases.includes(r.test));
}
