import { existsSync, readFileSync, readdirSync } from 'node:fs';
import { join, relative } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { validate, type Finding } from './helpers.js';

// Real MontiArc automata: the models of MontiArc's stream I/O test suite (read from the shared
// conformance folder at test time, never copied into the repository).
const MODELS = fileURLToPath(new URL('../../../../shared/conformance/montiarc-io/models', import.meta.url));
const available = existsSync(MODELS);

function walk(dir: string): string[] {
    return readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
        e.isDirectory() ? walk(join(dir, e.name)) : /\.(arc|cd)$/.test(e.name) ? [join(dir, e.name)] : [],
    );
}

describe.skipIf(!available)('MontiArc io models with automata', () => {
    if (!available) {
        test.skip(`skipped: ${MODELS} is absent (a user's clone has no ../shared)`, () => {});
        return;
    }
    const files = Object.fromEntries(walk(MODELS).map((f) => [relative(MODELS, f), readFileSync(f, 'utf8')]));
    const withAutomata = Object.keys(files).filter(
        (f) => f.endsWith('.arc') && /\bautomaton\b/.test(files[f]!.replace(/\/\*[\s\S]*?\*\/|\/\/.*/g, '')),
    );
    let found: Finding[] | undefined;
    const all = async (): Promise<Finding[]> => (found ??= await validate(files));

    test('there are automata to parse', () => {
        expect(withAutomata.length).toBeGreaterThan(30);
    });
    test.each(withAutomata)('%s parses without syntax errors', async (file) => {
        const mine = (await all()).filter((f) => f.file === file);
        expect(
            mine.filter((f) => f.code.startsWith('syntax/')),
            JSON.stringify(mine, null, 1),
        ).toEqual([]);
    });
    test.each(withAutomata)('%s has no automaton errors', async (file) => {
        const mine = (await all()).filter((f) => f.file === file);
        expect(
            mine.filter((f) => f.code.startsWith('automaton/') && f.severity === 'error'),
            JSON.stringify(mine, null, 1),
        ).toEqual([]);
    });
});
