import os from 'node:os';
import path from 'node:path';

/**
 * Replaces the absolute folders maa-ide knows (the workspace, the generated output, its own
 * installation, the home folder) in texts sent to clients: error bodies never reveal where
 * things live on the machine, and paths inside the workspace read as the relative paths the
 * API uses anyway.
 */
export class PathRedactor {
    private readonly rules: Array<[prefix: string, label: string]>;

    /** @param roots absolute folder → what it reads as ('' for "relative to it") */
    constructor(roots: ReadonlyArray<readonly [string, string]>) {
        const all: Array<[string, string]> = [];
        for (const [dir, label] of [...roots, [os.homedir(), '~'] as const]) {
            const abs = path.resolve(dir);
            if (abs === path.parse(abs).root) continue; // "/" would eat every path
            all.push([abs, label]);
        }
        // The longest prefix first: the workspace inside the home folder reads as relative, not as ~/...
        this.rules = all.sort((a, b) => b[0].length - a[0].length);
    }

    text(value: string): string {
        let out = value;
        for (const [prefix, label] of this.rules) {
            // `prefix/rest` → `label/rest` (or `rest`), the bare prefix → the label.
            out = out.split(`${prefix}${path.sep}`).join(label === '' ? '' : `${label}/`);
            out = out.split(prefix).join(label === '' ? '.' : label);
        }
        return scrubAbsolutePaths(out);
    }

    /** Redacts every string in a JSON-like value. */
    value<T>(value: T): T {
        if (typeof value === 'string') return this.text(value) as T;
        if (Array.isArray(value)) return value.map((v: unknown) => this.value(v)) as T;
        if (typeof value === 'object' && value !== null) {
            return Object.fromEntries(Object.entries(value).map(([k, v]) => [k, this.value(v)])) as T;
        }
        return value;
    }
}

/**
 * Absolute paths outside the known folders (a Python traceback's `/usr/lib/python3/...`):
 * the folders go, the file name stays. Only paths of four or more segments after a quote,
 * blank or parenthesis count, so request paths such as `/api/generated/file` in messages are kept.
 */
export function scrubAbsolutePaths(text: string): string {
    return text.replace(
        /(^|[\s"'(=])\/(?:[^\s"'()/:,]+\/){3,}([^\s"'()/:,]*)/gm,
        (_m, before: string, name: string) => `${before}…/${name}`,
    );
}
