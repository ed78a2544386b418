import { fileURLToPath } from 'node:url';
import { cocosCaseFiles, cocosFailure, cocosSuiteFile, forbiddenCodesByClass, loadCocosCases } from '@maa/language-adl/testing';
import { describe, expect, test } from 'vitest';
import { dump, validate } from './helpers.js';

// MontiArc's context-condition cases that this package answers for, one test each, checked with
// this package's services alone (the family-wide run is language-server's montiarc-conformance):
// the core cases that contain automata (cocos.json), and the mode automata and unsupported
// automaton elements of cocos-extended.json. Read from the workplace's shared/ folder at test
// time, never copied into the repository; scored as its README says (@maa/language-adl/testing).
const here = fileURLToPath(new URL('.', import.meta.url));

/** The test classes of cocos-extended.json this package is responsible for. */
const MODE_CLASSES: readonly string[] = [
    'ModeCoCosTest',
    'ModeAutomataInDecomposedComponentTest',
    'ModeAutomatonContainsNoStatesTest',
    'MaxOneModeAutomatonTest',
    'ModeOmitPortDefinitionTest',
    'AtLeastOneInitialStateTest',
    'MaxOneInitialStateTest',
    'StatechartContainsNoModeTest',
    'UnsupportedAutomatonElementsTest',
];

const suites = [
    { name: 'cocos.json', title: 'core cases with automata', pick: (c: { model: string }) => /\bautomaton\b/.test(c.model) },
    {
        name: 'cocos-extended.json',
        title: 'mode automata and unsupported automaton elements',
        pick: (c: { cls: string }) => MODE_CLASSES.includes(c.cls),
    },
] as const;

for (const suite of suites) {
    const file = cocosSuiteFile(here, suite.name);
    const all = loadCocosCases(file);
    if (!all) {
        describe(`MontiArc ${suite.name} (absent)`, () => {
            test.skip(`skipped: ${file} is absent (a user's clone has no ../shared)`, () => {});
        });
        continue;
    }
    describe(`MontiArc ${suite.name}: ${suite.title}`, () => {
        const cases = all.filter(suite.pick);
        // Valid cases must not report what the invalid cases of their class expect (the whole class counts).
        const forbidden = forbiddenCodesByClass(all.filter((c) => cases.some((x) => x.cls === c.cls)));
        if (suite.name === 'cocos-extended.json') {
            test('every mode class is present', () => {
                expect(new Set(cases.map((c) => c.cls))).toEqual(new Set(MODE_CLASSES));
            });
        }
        test.each(cases.map((c) => [`${c.cls} ${c.kind}: ${c.comment}`, c] as const))('%s', async (_name, c) => {
            const found = await validate(cocosCaseFiles(c));
            expect(
                cocosFailure(
                    c,
                    found.map((f) => f.code),
                    forbidden,
                ),
                dump(found),
            ).toBeUndefined();
        });
    });
}
