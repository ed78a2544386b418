import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { dump, validate } from './helpers.js';

// MontiArc's context-condition cases of mode automata and unsupported automaton elements
// (shared/conformance/montiarc/cocos-extended.json, read at test time, never copied into the
// repository), scored as its README says: an invalid case reports every expected code; a valid
// one no syntax/ or link/ code and none of the codes the invalid cases of its class expect.
const COCOS = fileURLToPath(new URL('../../../../shared/conformance/montiarc/cocos-extended.json', import.meta.url));
const available = existsSync(COCOS);

/** The test classes of cocos-extended.json this package is responsible for. */
export const MODE_CLASSES: readonly string[] = [
    'ModeCoCosTest', 'ModeAutomataInDecomposedComponentTest', 'ModeAutomatonContainsNoStatesTest', 'MaxOneModeAutomatonTest',
    'ModeOmitPortDefinitionTest', 'AtLeastOneInitialStateTest', 'MaxOneInitialStateTest', 'StatechartContainsNoModeTest',
    'UnsupportedAutomatonElementsTest'
];

interface Case {
    cls: string;
    kind: 'valid' | 'invalid';
    comment: string;
    model: string;
    helpers: string[];
    expected: string[];
}

function files(c: Case): Record<string, string> {
    const out: Record<string, string> = {};
    for (const text of [c.model, ...c.helpers]) {
        const pkg = /^\s*package\s+([\w.]+)\s*;/m.exec(text)?.[1];
        const name = /component\s+(\w+)/.exec(text)![1]!;
        out[`${pkg ? `${pkg.replace(/\./g, '/')}/` : ''}${name}.arc`] = text;
    }
    return out;
}

describe.skipIf(!available)('MontiArc context-condition cases of modes (cocos-extended.json)', () => {
    if (!available) {
        test.skip(`skipped: ${COCOS} is absent (a user's clone has no ../shared)`, () => {});
        return;
    }
    const cases = (JSON.parse(readFileSync(COCOS, 'utf8')) as { cases: Case[] }).cases.filter((c) => MODE_CLASSES.includes(c.cls));
    test('every class is present', () => {
        expect(new Set(cases.map((c) => c.cls))).toEqual(new Set(MODE_CLASSES));
    });
    const expectedOfClass = new Map<string, Set<string>>();
    for (const c of cases) {
        if (c.kind !== 'invalid') continue;
        const set = expectedOfClass.get(c.cls) ?? new Set<string>();
        c.expected.forEach((e) => set.add(e));
        expectedOfClass.set(c.cls, set);
    }
    test.each(cases.map((c) => [`${c.cls} ${c.kind}: ${c.comment}`, c] as const))('%s', async (_name, c) => {
        const found = await validate(files(c));
        const codes = found.map((f) => f.code);
        if (c.kind === 'invalid') {
            for (const e of c.expected) expect(codes, dump(found)).toContain(e);
            // Codes expected twice (one per offending element) are reported as often.
            for (const e of new Set(c.expected)) {
                expect(codes.filter((x) => x === e).length, dump(found)).toBeGreaterThanOrEqual(c.expected.filter((x) => x === e).length);
            }
        } else {
            const forbidden = expectedOfClass.get(c.cls) ?? new Set<string>();
            expect(codes.filter((x) => x.startsWith('syntax/') || x.startsWith('link/') || forbidden.has(x)), dump(found)).toEqual([]);
        }
    });
});
