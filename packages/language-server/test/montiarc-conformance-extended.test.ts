import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, test } from 'vitest';
import { checkModelRoots, type CheckDiagnostic } from '../src/index.js';

/**
 * The test classes of cocos-extended.json that this project passes completely: the test asserts
 * 100 % for each. Add a class here when its construct is done (variability: 12-A; modes: 12-B;
 * autoconnect: 12-C; ...). Every other class is scored and printed, not asserted.
 */
const ASSERTED_CLASSES: readonly string[] = [
    // variable architectures (feature, varif, constraint)
    'VariantCoCosTest',
    'ConstraintNoAssignmentExprTest',
    'ConstraintSatisfied4CompTest',
    'VarIfNoAssignmentExprTest',
    'ConstraintSmtConvertibleTest',
    'VarIfSmtConvertibleTest',
    'SubcomponentsConstraintTest',
    'NamesCapitalizationTest',
    'UniqueIdentifierTest',
    // autoconnect
    'AtomicNoAutoConnectTest',
    'MaxOneAutoConnectTest',
    // mode automata and unsupported automaton elements (12-B)
    'ModeCoCosTest',
    'ModeAutomataInDecomposedComponentTest',
    'ModeAutomatonContainsNoStatesTest',
    'MaxOneModeAutomatonTest',
    'ModeOmitPortDefinitionTest',
    'AtLeastOneInitialStateTest',
    'MaxOneInitialStateTest',
    'StatechartContainsNoModeTest',
    'UnsupportedAutomatonElementsTest'
];

/**
 * MontiArc's context-condition test models for the constructs beyond the core language
 * (shared/conformance/montiarc/cocos-extended.json, read at test time, never copied into this
 * repository), run through the checking path of `maa-gen check`: one model root per case, all
 * checks enabled. Scoring as in that folder's README: an invalid case passes when every
 * expected code is reported for its root; a valid case when its root gets no `syntax/` or
 * `link/` diagnostic and none of the codes the invalid cases of its class expect.
 */
const here = dirname(fileURLToPath(import.meta.url));
const suiteFile = resolve(here, '../../../../shared/conformance/montiarc/cocos-extended.json');

interface Case {
    cls: string;
    kind: 'valid' | 'invalid';
    comment: string;
    model: string;
    helpers: string[];
    expected: string[];
}

function writeModel(root: string, text: string): void {
    const pkg = /^\s*package\s+([\w.]+)\s*;/.exec(text)?.[1];
    const name = /component\s+(\w+)/.exec(text)?.[1] ?? 'Model';
    const dir = pkg ? join(root, ...pkg.split('.')) : root;
    mkdirSync(dir, { recursive: true });
    writeFileSync(join(dir, `${name}.arc`), text);
}

describe.skipIf(!existsSync(suiteFile))('MontiArc context-condition suite, extended constructs', () => {
    const work = mkdtempSync(join(tmpdir(), 'maa-montiarc-ext-'));
    afterAll(() => rmSync(work, { recursive: true, force: true }));

    test(`pass rate per class; 100% for ${ASSERTED_CLASSES.length} asserted classes`, async () => {
        const cases = (JSON.parse(readFileSync(suiteFile, 'utf8')) as { cases: Case[] }).cases;
        const roots = cases.map((c, i) => {
            const root = join(work, `case${String(i).padStart(3, '0')}`);
            mkdirSync(root, { recursive: true });
            writeModel(root, c.model);
            for (const h of c.helpers) writeModel(root, h);
            return root;
        });
        const diagnostics = await checkModelRoots(roots.map((root) => ({ root })));
        const byRoot = new Map<string, CheckDiagnostic[]>();
        for (const d of diagnostics) byRoot.set(d.root, [...(byRoot.get(d.root) ?? []), d]);

        const invalidCodes = new Map<string, Set<string>>();
        for (const c of cases) {
            if (c.kind === 'invalid') invalidCodes.set(c.cls, new Set([...(invalidCodes.get(c.cls) ?? []), ...c.expected]));
        }
        const perClass = new Map<string, { passed: number; total: number }>();
        const failures: string[] = [];
        cases.forEach((c, i) => {
            const codes = new Set((byRoot.get(roots[i]!) ?? []).map((d) => d.code));
            const pass = c.kind === 'invalid'
                ? c.expected.every((e) => codes.has(e))
                : ![...codes].some((x) => x.startsWith('syntax/') || x.startsWith('link/') || invalidCodes.get(c.cls)?.has(x));
            const s = perClass.get(c.cls) ?? { passed: 0, total: 0 };
            s.total++;
            if (pass) s.passed++;
            else failures.push(`${c.cls} ${c.kind} expected [${c.expected.join(', ')}] got [${[...codes].join(', ')}]: ${c.model.replace(/\s+/g, ' ')}`);
            perClass.set(c.cls, s);
        });

        const passed = [...perClass.values()].reduce((a, s) => a + s.passed, 0);
        const lines = [...perClass.entries()].sort().map(([cls, s]) => `${((100 * s.passed) / s.total).toFixed(0).padStart(4)}%  ${String(s.passed).padStart(3)}/${String(s.total).padEnd(3)} ${cls}${ASSERTED_CLASSES.includes(cls) ? ' (asserted)' : ''}`);
        console.log(`MontiArc conformance (extended): ${passed}/${cases.length} (${((100 * passed) / cases.length).toFixed(1)}%)\n${lines.join('\n')}${failures.length ? `\nfailing cases:\n  ${failures.join('\n  ')}` : ''}`);

        for (const cls of ASSERTED_CLASSES) {
            const s = perClass.get(cls);
            expect(s, `class ${cls} in the suite`).toBeDefined();
            const failing = failures.filter((f) => f.startsWith(`${cls} `));
            expect(failing, cls).toEqual([]);
        }
    });
});

describe.skipIf(existsSync(suiteFile))('MontiArc context-condition suite, extended constructs (absent)', () => {
    test.skip(`skipped: ${suiteFile} not found (the suite lives in the workplace's shared/ folder, next to the clone)`, () => {});
});
