import { describe, expect, test } from 'vitest';
import { traceFileContract, TRACE_FORMAT_VERSION } from '../dist/index.js';

const element = {
    file: 'toast/Controller.arc',
    range: { start: { line: 4, character: 0 }, end: { line: 24, character: 1 } },
    path: '/component',
    type: 'ComponentType',
    name: 'Controller',
};
const trace = {
    version: TRACE_FORMAT_VERSION,
    application: 'ToastServiceRobot',
    platform: 'timesync',
    rootComponent: 'toast.ToastServiceRobot',
    modelRoot: '../../models',
    generators: [{ name: 'timesync.Components', kind: 'component', package: '@maa/generators-python', version: '0.1.0' }],
    files: [
        {
            path: 'toast/controller.py',
            generator: 'timesync.Components',
            userFile: false,
            sha256: 'a'.repeat(64),
            lines: 53,
            traces: [{ lines: { first: 0, last: 52 }, generator: 'timesync.Components', element }],
        },
    ],
};

describe('trace file contract', () => {
    test('a trace with 0-based ranges is valid, and so is an element without text (range null)', () => {
        expect(traceFileContract.issues(trace)).toEqual([]);
        const builtIn = structuredClone(trace);
        builtIn.files[0]!.traces[0]!.element = { ...element, range: null as never };
        expect(traceFileContract.check(builtIn)).toBe(true);
    });

    test('the 1-based arrays of format version 1 are refused, naming the field', () => {
        const old = structuredClone(trace) as unknown as {
            version: number;
            files: Array<{ traces: Array<{ lines: unknown; element: { range: unknown } }> }>;
        };
        old.version = 1;
        old.files[0]!.traces[0]!.lines = [1, 53];
        old.files[0]!.traces[0]!.element.range = [5, 1, 25, 2];
        const pointers = traceFileContract.issues(old).map((i) => i.pointer);
        expect(pointers).toContain('/version');
        expect(pointers).toContain('/files/0/traces/0/lines');
        expect(pointers).toContain('/files/0/traces/0/element/range');
    });

    test('negative positions are refused', () => {
        const bad = structuredClone(trace);
        bad.files[0]!.traces[0]!.element.range.start.line = -1;
        expect(traceFileContract.issues(bad).map((i) => i.pointer)).toContain('/files/0/traces/0/element/range');
    });
});
