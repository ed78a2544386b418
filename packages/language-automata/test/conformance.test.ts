import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { dump, validate } from './helpers.js';

// MontiArc's own context-condition test models that contain automata (read from the shared
// conformance folder at test time, never copied into the repository), scored as its README says.
const COCOS = fileURLToPath(new URL('../../../../shared/conformance/montiarc/cocos.json', import.meta.url));
const available = existsSync(COCOS);

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

describe.skipIf(!available)('MontiArc context-condition cases with automata', () => {
    if (!available) {
        test.skip(`skipped: ${COCOS} is absent (a user's clone has no ../shared)`, () => {});
        return;
    }
    const cases = (JSON.parse(readFileSync(COCOS, 'utf8')) as { cases: Case[] }).cases.filter((c) => /\bautomaton\b/.test(c.model));
    const expectedOfClass = new Map<string, Set<string>>();
    for (const c of cases) {
        if (c.kind !== 'invalid') continue;
        const set = expectedOfClass.get(c.cls) ?? new Set<string>();
        c.expected.forEach((e) => set.add(e));
        expectedOfClass.set(c.cls, set);
    }
    test.each(cases.map((c) => [`${c.cls} ${c.kind}: ${c.model}`, c] as const))('%s', async (_name, c) => {
        const found = await validate(files(c));
        const codes = found.map((f) => f.code);
        if (c.kind === 'invalid') {
            for (const e of c.expected) expect(codes, dump(found)).toContain(e);
        } else {
            const forbidden = expectedOfClass.get(c.cls) ?? new Set<string>();
            expect(codes.filter((x) => x.startsWith('syntax/') || x.startsWith('link/') || forbidden.has(x)), dump(found)).toEqual([]);
        }
    });
});
