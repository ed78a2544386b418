import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { EmptyFileSystem, type LangiumDocument } from 'langium';
import { afterEach, describe, expect, test, vi } from 'vitest';
import { checkRoots, createAdlServices, type CheckDiagnostic, type HostLanguageServices } from '../src/index.js';

let dirs: string[] = [];
afterEach(() => {
    for (const d of dirs) rmSync(d, { recursive: true, force: true });
    dirs = [];
    vi.restoreAllMocks();
});

function root(files: Record<string, string>): string {
    const dir = mkdtempSync(join(tmpdir(), 'maa-root-checker-'));
    dirs.push(dir);
    for (const [name, text] of Object.entries(files)) writeFileSync(join(dir, name), text);
    return dir;
}

const byFile = (found: CheckDiagnostic[], dir: string): Record<string, string[]> => {
    const out: Record<string, string[]> = {};
    for (const d of found) (out[d.file.substring(dir.length + 1)] ??= []).push(d.code);
    return out;
};

/** Services whose parser or indexing breaks on files containing `EXPLODE` (a stand-in for a bug). */
function explodingServices(where: 'parser' | 'indexing'): HostLanguageServices {
    const s = createAdlServices(EmptyFileSystem);
    if (where === 'parser') {
        const parser = s.Arc.parser.LangiumParser;
        const parse = parser.parse.bind(parser);
        parser.parse = ((text: string, options?: Parameters<typeof parse>[1]) => {
            if (text.includes('EXPLODE')) throw new RangeError('Maximum call stack size exceeded');
            return parse(text, options);
        }) as typeof parser.parse;
    } else {
        const computation = s.Arc.references.ScopeComputation;
        const collect = computation.collectExportedSymbols.bind(computation);
        computation.collectExportedSymbols = (doc: LangiumDocument, token) => {
            if (doc.textDocument.getText().includes('EXPLODE')) throw new Error('indexing bug');
            return collect(doc, token);
        };
    }
    return s;
}

describe('a file that cannot be checked is reported, and the others are checked', () => {
    test.each(['parser', 'indexing'] as const)('the %s throws on one file', async (where) => {
        vi.spyOn(console, 'error').mockImplementation(() => undefined);
        const a = root({ 'A.arc': 'component A { EXPLODE }', 'B.arc': 'component B {\n  port in Missing m;\n}' });
        const other = root({ 'C.arc': 'component C {\n  port in Missing m;\n}' });
        const found = await checkRoots(explodingServices(where), [{ root: a }, { root: other }]);
        expect(byFile(found, a)['A.arc']).toEqual(['internal/check-failed']);
        const failure = found.find((d) => d.file.endsWith('A.arc'))!;
        expect(failure.message).toMatch(where === 'parser' ? /nested too deeply for the parser/ : /indexing bug/);
        expect(failure.message).toContain('could not be checked');
        expect(byFile(found, a)['B.arc']).toEqual(['arc/unresolved-type']);
        expect(byFile(found, other)['C.arc']).toEqual(['arc/unresolved-type']);
    });

    test('without a failure no file is reported as unchecked', async () => {
        const a = root({ 'A.arc': 'component A { }', 'B.arc': 'component B {\n  port in Missing m;\n}' });
        const found = await checkRoots(explodingServices('parser'), [{ root: a }]);
        expect(found.map((d) => d.code)).toEqual(['arc/unresolved-type']);
    });
});
