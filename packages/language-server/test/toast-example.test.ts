import { cpSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { checkModelRoots } from '../src/index.js';

const example = resolve(dirname(fileURLToPath(import.meta.url)), '../../../examples/toast-service');

/** Checks a copy of the example with one file changed by `edit` and returns the codes per file. */
async function checkBroken(file: string, edit: (text: string) => string): Promise<Array<{ file: string; code: string }>> {
    const root = mkdtempSync(join(tmpdir(), 'maa-toast-'));
    try {
        cpSync(example, root, { recursive: true });
        const path = join(root, file);
        const before = readFileSync(path, 'utf8');
        const after = edit(before);
        expect(after, 'the mutation must change the file').not.toBe(before);
        writeFileSync(path, after);
        const found = await checkModelRoots([{ root }]);
        return found.map((d) => ({ file: d.file.substring(root.length + 1), code: d.code }));
    } finally {
        rmSync(root, { recursive: true, force: true });
    }
}

describe('the ToastServiceRobot example', () => {
    test('checks without errors or warnings', async () => {
        const found = await checkModelRoots([{ root: example }]);
        expect(found.map((d) => `${d.file}:${d.line} ${d.code} ${d.message}`)).toEqual([]);
    });

    test('checks without diagnostics as part of examples/ (its maa.json makes it a model root of its own)', async () => {
        // examples/lab/ holds exercise starters with errors on purpose and partial solutions: only
        // the example's own files matter here (the lab's are checked by the lab's exercise tests)
        const found = await checkModelRoots([{ root: resolve(example, '..') }]);
        const inExample = found.filter((d) => resolve(d.file).startsWith(`${example}/`));
        expect(inExample.map((d) => `${d.file}:${d.line} ${d.code} ${d.message}`)).toEqual([]);
        expect(found.some((d) => d.file.includes('toast-service'))).toBe(false);
    });

    test.each([
        [
            'a connector to a port that does not exist',
            'toast/ToastServiceRobot.arc',
            (t: string) => t.replace('-> ctrl.distance', '-> ctrl.dist'),
            'arc/missing-port',
        ],
        [
            'a connector between ports of different types',
            'toast/ToastServiceRobot.arc',
            (t: string) => t.replace('color.value -> ctrl.color', 'dist.value -> ctrl.color'),
            'arc/connector-type-mismatch',
        ],
        [
            'a feedback loop without delay',
            'toast/Controller.arc',
            (t: string) => t.replace('<<delayed>> out ArmProgram arm', 'out ArmProgram arm'),
            'arc/feedback-not-causal',
        ],
        [
            'an unconnected input of a subcomponent',
            'toast/ToastServiceRobot.arc',
            (t: string) => t.replace('  color.value -> ctrl.color;\n', ''),
            'arc/unconnected-sub-in-port',
        ],
        [
            'a guard that is not boolean',
            'toast/Controller.arc',
            (t: string) => t.replace('[distance < threshold]', '[distance]'),
            'automaton/guard-not-boolean',
        ],
        [
            'a transition to a missing state',
            'toast/Controller.arc',
            (t: string) => t.replace('Serving -> Idle', 'Serving -> Idel'),
            'automaton/missing-state',
        ],
        [
            'a move to an unknown location',
            'toast/ArmController.arc',
            (t: string) => t.replace('move breadbox;', 'move bredbox;'),
            'robotarm/unresolved-name',
        ],
        [
            'an arm command without program',
            'toast/types/Types.cd',
            (t: string) => t.replace('PICKUP_AND_DEPLOY;', 'PICKUP_AND_DEPLOY, DANCE;'),
            'robotarm/command-without-program',
        ],
        [
            'a misspelled enum constant',
            'toast/Controller.arc',
            (t: string) => t.replace('ToastColor.GOLDEN', 'ToastColor.GOLD'),
            'expr/unresolved-name',
        ],
        [
            'a missing type',
            'toast/ColorSensor.arc',
            (t: string) => t.replace('out ToastColor value', 'out ToastColour value'),
            'arc/unresolved-type',
        ],
        [
            'a wrong package',
            'toast/PlateLocator.arc',
            (t: string) => t.replace('package toast;', 'package toasty;'),
            'arc/package-mismatch',
        ],
        ['a truncated file', 'toast/ToasterController.arc', (t: string) => t.substring(0, t.length / 2), 'syntax/unexpected-end'],
    ])('reports %s', async (_what, file, edit, code) => {
        const found = await checkBroken(file, edit);
        expect(found.map((f) => f.code)).toContain(code);
    });
});
