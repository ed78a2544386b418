import { readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, test } from 'vitest';
import { lockstepContract, LOCKSTEP_FILE_NAME, stepOutputsContract } from '../dist/index.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');

function find(dir: string, name: string, out: string[] = []): string[] {
    for (const e of readdirSync(dir)) {
        const abs = path.join(dir, e);
        if (statSync(abs).isDirectory()) find(abs, name, out);
        else if (e === name) out.push(abs);
    }
    return out;
}

describe('lock-step contracts', () => {
    test('every generated lockstep.json (the timesync golden files) keeps the contract', () => {
        const files = find(path.join(repo, 'packages/generators-python/test'), LOCKSTEP_FILE_NAME);
        expect(files.length).toBeGreaterThan(0);
        for (const f of files) expect(lockstepContract.issues(JSON.parse(readFileSync(f, 'utf8'))), f).toEqual([]);
    });

    test.each([
        [{ format: 'maa-lockstep/1' }, '/factory', "factory must be 'module:callable'"],
        [{ format: 'maa-lockstep/1', factory: 'a:b', period: 0 }, '/period', 'period must be a positive number of seconds'],
        [{ format: 'maa-lockstep/2', factory: 'a:b' }, '/format', "format must be 'maa-lockstep/1'"],
    ])('%j is refused at %s', (value, pointer, message) => {
        expect(lockstepContract.issues(value)).toContainEqual({ pointer, message });
    });

    test('step outputs: absolute topics, one message or a list of them', () => {
        expect(stepOutputsContract.check({ '/a': { data: 1 }, '/b': [{ data: 1 }], '/c': null })).toBe(true);
        expect(stepOutputsContract.check({ a: { data: 1 } })).toBe(false);
        expect(stepOutputsContract.check({ '/a': 3 })).toBe(false);
    });
});
