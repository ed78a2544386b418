// A grading run's progress from the engine's events (src/grading/engine.ts progressOf) and the
// recordings' names and files (src/grading/files.ts): a scenario id never leaves its folder.
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { progressOf, recordingFile, recordingName } from '../src/grading/index.js';

describe('a grading run’s progress', () => {
    it('counts the driver’s task lines as @maa/grading forwards them, and takes an explicit done/total', () => {
        let p = { done: 0, total: 2 };
        p = progressOf({ kind: 'submission', submission: '1', step: 'generate', message: 'generating' }, p);
        expect(p).toEqual({ done: 0, total: 2 });
        p = progressOf({ kind: 'driver', line: { event: 'started', tasks: 5, mode: 'local', nodes: 1, cpus: 2 } }, p);
        expect(p).toEqual({ done: 0, total: 5 });
        p = progressOf({ kind: 'driver', line: { event: 'task', id: '1.tests', status: 'ok' } }, p);
        p = progressOf({ event: 'task', id: '1.scenario.standard', status: 'timeout' }, p);
        expect(p).toEqual({ done: 2, total: 5 });
        expect(progressOf({ done: 7, total: 9 }, p)).toEqual({ done: 7, total: 9 });
        expect(progressOf(null, p)).toBe(p);
        expect(progressOf('text', p)).toBe(p);
        // More task lines than announced never show more done than total.
        expect(progressOf({ event: 'task' }, { done: 5, total: 5 })).toEqual({ done: 6, total: 6 });
    });
});

describe('the recordings’ files', () => {
    it('names a recording by its scenario, with anything but letters, digits, _ and - replaced', () => {
        expect(recordingName('standard')).toBe('standard.mcap');
        expect(recordingName('../../etc/passwd')).toBe('______etc_passwd.mcap');
        expect(recordingName('')).toBe('scenario.mcap');
    });

    it('finds a stored recording only inside <data-dir>/recordings and only as an .mcap file', () => {
        const data = path.resolve('/srv/lab-data');
        expect(recordingFile(data, { scenario: 's', path: 'recordings/1/2/s.mcap' })).toBe(
            path.join(data, 'recordings', '1', '2', 's.mcap'),
        );
        expect(recordingFile(data, { scenario: 's', path: 'recordings/../postgres/x.mcap' })).toBeUndefined();
        expect(recordingFile(data, { scenario: 's', path: '../../etc/passwd' })).toBeUndefined();
        expect(recordingFile(data, { scenario: 's', path: 'recordings/1/2/s.json' })).toBeUndefined();
    });
});
