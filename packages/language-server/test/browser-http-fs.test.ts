// The worker's file system: the workspace over the backend's HTTP API, checked against a small
// HTTP server over a fixture folder; and the family's workspace start-up on it (model roots by
// maa.json, cross-file references).
import { cpSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { URI } from 'langium';
import { HttpFileSystemProvider, toUri, workspacePath } from '../src/browser/http-file-system.js';
import { serveWorkspace, type WorkspaceServer } from './browser-helpers.js';
import { EXAMPLE } from './diagram-helpers.js';

let dir = '';
let server: WorkspaceServer;

beforeAll(async () => {
    dir = mkdtempSync(join(tmpdir(), 'maa-http-fs-'));
    cpSync(EXAMPLE, join(dir, 'toast-service'), { recursive: true });
    mkdirSync(join(dir, 'notes'));
    writeFileSync(join(dir, 'notes', 'a b.txt'), 'spaced');
    writeFileSync(join(dir, '.hidden'), 'x');
    server = await serveWorkspace(dir);
});

afterAll(async () => {
    await server?.close();
    rmSync(dir, { recursive: true, force: true });
});

const uri = (path: string): URI => URI.parse(`file:///workspace/${path}`);

describe('HttpFileSystemProvider', () => {
    test('lists folders and reads files of the workspace', async () => {
        const fs = new HttpFileSystemProvider({ apiBase: `${server.url}/` });
        const top = await fs.readDirectory(URI.parse('file:///workspace/'));
        expect(top.map((n) => `${n.uri.toString()} ${n.isDirectory ? 'dir' : 'file'}`)).toEqual([
            'file:///workspace/notes dir',
            'file:///workspace/toast-service dir',
        ]);
        const toast = await fs.readDirectory(uri('toast-service/toast'));
        expect(toast.filter((n) => n.isFile).map((n) => n.uri.path)).toContain('/workspace/toast-service/toast/Controller.arc');
        expect(toast.filter((n) => n.isDirectory).map((n) => n.uri.path)).toEqual(['/workspace/toast-service/toast/types']);
        expect(await fs.readFile(uri('toast-service/maa.json'))).toBe('{}\n');
        expect(await fs.readFile(toUri('notes/a b.txt'))).toBe('spaced');
        expect(new TextDecoder().decode(await fs.readBinary(uri('notes/a%20b.txt')))).toBe('spaced');
        expect(await fs.exists(uri('toast-service/TR.arcapp'))).toBe(true);
        expect(await fs.exists(uri('toast-service/nope.arc'))).toBe(false);
        expect(await fs.exists(URI.parse('builtin:/lib.arc'))).toBe(false);
        expect(await fs.stat(uri('toast-service'))).toMatchObject({ isDirectory: true, isFile: false });
        expect(await fs.stat(uri('toast-service/TR.arcapp'))).toMatchObject({ isDirectory: false, isFile: true });
    });

    test('answers synchronously from what it fetched before, and reports what it cannot know', async () => {
        const fs = new HttpFileSystemProvider({ apiBase: server.url });
        expect(() => fs.readDirectorySync(uri('toast-service'))).toThrow(/not been listed/);
        expect(() => fs.readFileSync(uri('toast-service/maa.json'))).toThrow(/not read yet/);
        await fs.readDirectory(uri(''));
        await fs.readFile(uri('toast-service/maa.json'));
        expect(fs.existsSync(uri('toast-service/toast/Controller.arc'))).toBe(true);
        expect(fs.statSync(uri('toast-service/toast'))).toMatchObject({ isDirectory: true });
        expect(fs.readDirectorySync(uri('toast-service')).map((n) => n.uri.path)).toContain('/workspace/toast-service/TR.arcapp');
        expect(fs.readFileSync(uri('toast-service/maa.json'))).toBe('{}\n');
    });

    test("fails with the backend's message for a missing file and for anything outside the workspace", async () => {
        const fs = new HttpFileSystemProvider({ apiBase: server.url });
        await expect(fs.readFile(uri('toast-service/Missing.arc'))).rejects.toThrow(/404 no file 'toast-service\/Missing.arc'/);
        await expect(fs.readFile(URI.parse('file:///etc/passwd'))).rejects.toThrow(/outside the workspace/);
        await expect(fs.readDirectory(uri('toast-service/TR.arcapp'))).rejects.toThrow(/no such directory/);
        expect(workspacePath(URI.parse('file:///workspace'))).toBe('');
        expect(workspacePath(URI.parse('file:///workspaces/x'))).toBeUndefined();
    });

    test('lists once for a burst of lookups and again after invalidate()', async () => {
        const fs = new HttpFileSystemProvider({ apiBase: server.url, listingTtlMs: 60_000 });
        const before = server.requests.filter((r) => r === '/api/files').length;
        await Promise.all([fs.readDirectory(uri('')), fs.exists(uri('toast-service')), fs.stat(uri('notes'))]);
        await fs.readDirectory(uri('toast-service'));
        expect(server.requests.filter((r) => r === '/api/files').length - before).toBe(1);
        writeFileSync(join(dir, 'notes', 'new.txt'), 'new');
        expect(await fs.exists(uri('notes/new.txt'))).toBe(false);
        fs.invalidate();
        expect(await fs.exists(uri('notes/new.txt'))).toBe(true);
    });
});
