// The fuzz corpus through the family's validation, in process: every example model (and the
// MontiArc conformance models when ../shared is checked out) truncated, with tokens deleted,
// duplicated and swapped, with random bytes, plus deep nesting and noise in every language.
// No exception may escape and no check may fail (internal/check-failed). The corpus is seeded:
// MAA_FUZZ_SEED=<n> reproduces a run; a failure names the seed and the case.
import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { EmptyFileSystem, URI, type LangiumDocument } from 'langium';
import { describe, expect, test } from 'vitest';
import { builtinDocuments } from '@maa/language-adl';
import { mutations, pathological, random, type FuzzCase } from '@maa/language-adl/testing';
import { createMaaServices } from '../src/family.js';

const repo = resolve(dirname(fileURLToPath(import.meta.url)), '../../..');
const SOURCES = [join(repo, 'examples'), resolve(repo, '../shared/conformance')].filter((d) => existsSync(d));
const SEED = Number(process.env['MAA_FUZZ_SEED'] ?? 20261123);

function modelFiles(dir: string): string[] {
    const out: string[] = [];
    for (const name of readdirSync(dir).sort()) {
        const p = join(dir, name);
        if (statSync(p).isDirectory()) out.push(...modelFiles(p));
        else if (/\.(arc|cd|ra|arcapp)$/.test(name)) out.push(p);
    }
    return out;
}

function corpus(): FuzzCase[] {
    const files = SOURCES.flatMap((d) => modelFiles(d).map((f) => ({ path: relative(d, f), text: readFileSync(f, 'utf8') })));
    const cases = files.flatMap((f, i) => mutations(f.path, f.text, { seed: SEED + i, perKind: 1 }));
    // More cut points for the larger files, where truncation meets the most constructs.
    for (const f of [...files].sort((a, b) => b.text.length - a.text.length).slice(0, 6)) {
        cases.push(...mutations(f.path, f.text, { seed: SEED, perKind: 10 }).filter((c) => c.name.startsWith('truncate')));
    }
    const rnd = random(SEED);
    for (const path of ['A.arc', 'T.cd', 'R.ra', 'X.arcapp'])
        for (const depth of [100, 10_000]) cases.push(...pathological(path, depth, rnd));
    return cases;
}

describe(`fuzz corpus (seed ${SEED}; MAA_FUZZ_SEED reproduces it)`, () => {
    test('no exception escapes and no check fails', async () => {
        const cases = corpus();
        // A guard against an empty corpus: the examples alone give about 180 cases, with the
        // conformance models (when ../shared is checked out beside the repository) over 300.
        expect(cases.length).toBeGreaterThan(SOURCES.length > 1 ? 300 : 150);
        const services = createMaaServices(EmptyFileSystem);
        const shared = services.shared;
        const failures: string[] = [];
        const BATCH = 40;
        for (let b = 0; b < cases.length; b += BATCH) {
            const part = cases.slice(b, b + BATCH);
            // Each case in a model root of its own, so cases never resolve names in each other.
            shared.maa.ModelRoots.setRoots(part.map((_, k) => URI.file(`/fuzz/${b + k}`)));
            let docs: LangiumDocument[];
            try {
                docs = part.map((c, k) => shared.workspace.LangiumDocuments.createDocument(URI.file(`/fuzz/${b + k}/${c.path}`), c.text));
                await shared.workspace.DocumentBuilder.build([...builtinDocuments(shared), ...docs], { validation: true });
            } catch (e) {
                failures.push(`batch ${b}..${b + part.length - 1} (${part.map((c) => c.name).join('; ')}): ${String(e)}`);
                continue;
            }
            part.forEach((c, k) => {
                for (const d of docs[k]!.diagnostics ?? []) {
                    if (d.code === 'internal/check-failed' || d.code === undefined) failures.push(`${c.name}: ${d.message}`);
                }
            });
            for (const d of docs) shared.workspace.LangiumDocuments.deleteDocument(d.uri);
            // An in-memory build never waits for I/O: without this the whole loop is one stretch of
            // microtasks, during which the worker cannot answer Vitest's RPC (docs/testing.md).
            await new Promise((resolve) => setImmediate(resolve));
        }
        expect(failures, `seed ${SEED}`).toEqual([]);
    });
});
