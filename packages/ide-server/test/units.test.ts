import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { readCookie, sameSecret } from '../src/access.js';
import { platformKind } from '../src/apps.js';
import { checkRelativePath } from '../src/confinement.js';
import { PathRedactor, scrubAbsolutePaths } from '../src/redact.js';
import { findPackageDir, parseReadyLine } from '../src/sim-session.js';
import { walkTree } from '../src/walk.js';

describe('small parts', () => {
    it('derives a platform kind from its generator names', () => {
        expect(platformKind(['ros2.Components', 'ros2.DataTypes', 'ros2.AutomataBehavior'])).toBe('ros2');
        expect(platformKind(['timesync.Components', 'timesync.DataTypes', 'my.Extra'])).toBe('timesync');
        expect(platformKind([])).toBe('');
    });

    it('checks the syntax of client paths', () => {
        expect(checkRelativePath('a/./b//c.arc')).toEqual(['a', 'b', 'c.arc']);
        for (const bad of ['', '.', '..', 'a/..', '/a', 'C:\\a', 'a\\b', 'a\0b', 'c:/x'])
            expect(() => checkRelativePath(bad), bad).toThrow();
    });

    it("reads maa-sim's ready line", () => {
        const ready = parseReadyLine('{"event": "ready", "rosbridge": "ws://127.0.0.1:4001", "viser": "http://127.0.0.1:4002"}');
        expect(ready?.rosbridge.port).toBe('4001');
        expect(ready?.viser?.origin).toBe('http://127.0.0.1:4002');
        expect(parseReadyLine('{"event": "ready", "rosbridge": "ws://127.0.0.1:4001", "viser": null}')?.viser).toBeUndefined();
        for (const other of ['maa-sim: lockstep mode', '{"event": "finished"}', '{not json', '{"event": "ready", "rosbridge": null}']) {
            expect(parseReadyLine(other), other).toBeUndefined();
        }
    });

    it('finds the folder of a generated package', () => {
        const dir = mkdtempSync(path.join(tmpdir(), 'maa-ide-unit-'));
        try {
            mkdirSync(path.join(dir, 'a_interfaces'));
            mkdirSync(path.join(dir, 'b', 'b'), { recursive: true });
            writeFileSync(path.join(dir, 'b', 'deployment.json'), '{}');
            writeFileSync(path.join(dir, 'lockstep.json'), '{}');
            expect(findPackageDir(dir, 'deployment.json')).toBe(path.join(dir, 'b'));
            expect(findPackageDir(dir, 'lockstep.json')).toBe(dir);
            expect(findPackageDir(dir, 'nothing.json')).toBeUndefined();
        } finally {
            rmSync(dir, { recursive: true, force: true });
        }
    });

    it('reads one cookie of a Cookie header and compares secrets', () => {
        expect(readCookie('a=1; maa-ide-token-3000=abc; b=2', 'maa-ide-token-3000')).toBe('abc');
        expect(readCookie('maa-ide-token-30000=abc', 'maa-ide-token-3000')).toBeUndefined();
        expect(readCookie(undefined, 'x')).toBeUndefined();
        expect(sameSecret('same-secret', 'same-secret')).toBe(true);
        expect(sameSecret('same-secret', 'same-secreT')).toBe(false);
        expect(sameSecret('', 'same-secret')).toBe(false);
    });

    it('redacts known folders and absolute paths of tracebacks, keeps request paths', () => {
        const redact = new PathRedactor([
            ['/srv/x/ws', ''],
            ['/srv/x/out', '<generated>'],
        ]);
        expect(redact.text('cannot write /srv/x/ws/a/b.arc')).toBe('cannot write a/b.arc');
        expect(redact.text('the folder /srv/x/ws is gone')).toBe('the folder . is gone');
        expect(redact.text('in /srv/x/out/TR/timesync')).toBe('in <generated>/TR/timesync');
        expect(redact.value({ error: 'x /srv/x/ws/a', log: ['File "/usr/lib/python3/dist-packages/x.py", line 3'] })).toEqual({
            error: 'x a',
            log: ['File "…/x.py", line 3'],
        });
        expect(scrubAbsolutePaths('unknown route: GET /api/generated/file')).toBe('unknown route: GET /api/generated/file');
        expect(scrubAbsolutePaths('rosbridge at ws://127.0.0.1:9090/a/b/c/d')).toBe('rosbridge at ws://127.0.0.1:9090/a/b/c/d');
    });
});

describe('walkTree', () => {
    it('yields every entry depth first, enters only the folders it is allowed to, and passes over unreadable ones', async () => {
        const root = mkdtempSync(path.join(tmpdir(), 'maa-walk-'));
        try {
            mkdirSync(path.join(root, 'a', 'b'), { recursive: true });
            mkdirSync(path.join(root, 'node_modules', 'x'), { recursive: true });
            writeFileSync(path.join(root, 'a', 'b', 'f.txt'), '');
            writeFileSync(path.join(root, 'node_modules', 'x', 'g.txt'), '');
            writeFileSync(path.join(root, 'top.txt'), '');
            const seen: string[] = [];
            for await (const { rel } of walkTree(root, ({ dirent }) => dirent.name !== 'node_modules')) seen.push(rel);
            expect(seen.sort()).toEqual(['a', 'a/b', 'a/b/f.txt', 'node_modules', 'top.txt']);
            const none: string[] = [];
            for await (const { rel } of walkTree(path.join(root, 'missing'))) none.push(rel);
            expect(none).toEqual([]);
        } finally {
            rmSync(root, { recursive: true, force: true });
        }
    });
});
