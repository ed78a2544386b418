import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { cocosCaseFiles, cocosSuiteFile, formatCocosScore, loadCocosCases, scoreCocos, type CocosCase } from '@maa/language-adl/testing';
import { afterAll, describe, expect, test } from 'vitest';
import { checkModelRoots } from '../src/index.js';

/**
 * MontiArc's own context-condition test models (shared/conformance/montiarc, read at test time,
 * never copied into this repository), run through the checking path of `maa-gen check`: one
 * model root per case, all checks enabled, scored as that folder's README says. `cocos.json`
 * holds the core language, `cocos-extended.json` variability, modes, autoconnect and the rest;
 * every test class of both must pass completely.
 */
const here = dirname(fileURLToPath(import.meta.url));

/**
 * MontiArc's reserved-keyword tests configure the check under test with the keywords `key` and
 * `word` for one kind of element; the same configuration here goes through the model root's
 * `maa.json` (see docs/diagnostics.md, arc/reserved-name).
 */
const RESERVED_KIND: Record<string, string> = {
    ComponentNoReservedKeywordTest: 'component',
    PortNoReservedKeywordTest: 'port',
    FieldNameIsNoReservedKeywordTest: 'field',
    ParameterNoReservedKeywordTest: 'parameter',
    SubcomponentNoReservedKeywordTest: 'subcomponent',
    TypeParamNameIsNoReservedKeywordTest: 'typeParameter',
    StateNameIsNoReservedKeywordTest: 'state',
};

/** Writes each case into a model root of its own and checks them all in one run; the codes per case. */
async function checkCases(work: string, cases: readonly CocosCase[]): Promise<string[][]> {
    const roots = cases.map((c, i) => {
        const root = join(work, `case${String(i).padStart(3, '0')}`);
        for (const [rel, text] of Object.entries(cocosCaseFiles(c))) {
            mkdirSync(dirname(join(root, rel)), { recursive: true });
            writeFileSync(join(root, rel), text);
        }
        const kind = RESERVED_KIND[c.cls];
        if (kind) writeFileSync(join(root, 'maa.json'), JSON.stringify({ reservedNames: { [kind]: ['key', 'word'] } }));
        return root;
    });
    const codes = new Map<string, string[]>(roots.map((r) => [r, []]));
    for (const d of await checkModelRoots(roots.map((root) => ({ root })))) codes.get(d.root)?.push(d.code);
    return roots.map((r) => codes.get(r) ?? []);
}

for (const name of ['cocos.json', 'cocos-extended.json'] as const) {
    const suiteFile = cocosSuiteFile(here, name);
    const cases = loadCocosCases(suiteFile);
    if (!cases) {
        describe(`MontiArc context-condition suite ${name} (absent)`, () => {
            test.skip(`skipped: ${suiteFile} not found (the suite lives in the workplace's shared/ folder, next to the clone)`, () => {});
        });
        continue;
    }
    describe(`MontiArc context-condition suite ${name}`, () => {
        const work = mkdtempSync(join(tmpdir(), 'maa-montiarc-'));
        afterAll(() => rmSync(work, { recursive: true, force: true }));

        test('every case of every test class passes', async () => {
            const score = scoreCocos(cases, await checkCases(work, cases));
            console.log(formatCocosScore(`MontiArc conformance (${name})`, score));
            expect(score.failures).toEqual([]);
            expect(score.passed).toBe(cases.length);
        });
    });
}
