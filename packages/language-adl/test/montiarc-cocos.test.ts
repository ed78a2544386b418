import { describe, expect, it } from 'vitest';
import { cocosCaseFiles, scoreCocos, type CocosCase } from '../src/testing/montiarc-cocos.js';

// The scoring of MontiArc's context-condition cases (shared/conformance/montiarc/README.md) that
// every conformance runner uses: checked on made-up cases, so a lenient scorer cannot hide failures.
const invalid = (expected: string[]): CocosCase => ({
    cls: 'PortTest',
    kind: 'invalid',
    comment: 'bad',
    model: 'component A { }',
    helpers: [],
    expected,
});
const valid = (): CocosCase => ({ cls: 'PortTest', kind: 'valid', comment: 'good', model: 'component B { }', helpers: [], expected: [] });

describe('scoring MontiArc context-condition cases', () => {
    it('an invalid case passes only with every expected code, as often as expected', () => {
        const cases = [invalid(['arc/duplicate-name', 'arc/duplicate-name']), invalid(['arc/missing-port'])];
        const score = scoreCocos(cases, [['arc/duplicate-name'], ['arc/missing-port', 'arc/unused-in-port']]);
        expect(score.passed).toBe(1);
        expect(score.failures).toEqual([expect.stringContaining('missing [arc/duplicate-name]')]);
    });

    it("a valid case fails on syntax/, link/ and its class's expected codes, not on others", () => {
        const cases = [invalid(['arc/missing-port']), valid(), valid(), valid()];
        const score = scoreCocos(cases, [['arc/missing-port'], ['arc/unused-in-port'], ['syntax/unexpected-token'], ['arc/missing-port']]);
        expect(score.passed).toBe(2);
        expect(score.perClass.get('PortTest')).toEqual({ passed: 2, total: 4 });
        expect(score.failures.map((f) => f.split(': ')[1])).toEqual([
            'valid, but reported [syntax/unexpected-token]',
            'valid, but reported [arc/missing-port]',
        ]);
    });

    it('places helpers at their package path and the model at the root', () => {
        const c: CocosCase = { ...valid(), model: 'component Top { }', helpers: ['package a.b;\ncomponent Sub { }'] };
        expect(Object.keys(cocosCaseFiles(c)).sort()).toEqual(['Top.arc', 'a/b/Sub.arc']);
    });
});
