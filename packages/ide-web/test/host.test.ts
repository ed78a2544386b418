// The workbench host's own logic (src/host): the workspace tree behind its file system provider,
// quick open's pattern, and the extension files it registers.
import { describe, expect, it } from 'vitest';
import { extensionFiles } from '../src/host/extension.js';
import { matchesPattern, normalizePath, WorkspaceTree } from '../src/host/workspace-tree.js';

const LISTING = [
    { path: 'toast-service', type: 'directory' as const },
    { path: 'toast-service/TR.arcapp', type: 'file' as const, size: 120 },
    { path: 'toast-service/toast', type: 'directory' as const },
    { path: 'toast-service/toast/Controller.arc', type: 'file' as const, size: 900 },
    { path: 'README.md', type: 'file' as const, size: 10 },
];

describe('WorkspaceTree', () => {
    it('answers stat and readdir from the listing (the root is the empty path)', () => {
        const tree = new WorkspaceTree(LISTING);
        expect(tree.stat('')?.type).toBe('directory');
        expect(tree.stat('/toast-service/TR.arcapp/')).toEqual({ type: 'file', size: 120, mtime: 0 });
        expect(tree.readdir('')).toEqual([
            ['README.md', 'file'],
            ['toast-service', 'directory'],
        ]);
        expect(tree.readdir('toast-service')).toEqual([
            ['TR.arcapp', 'file'],
            ['toast', 'directory'],
        ]);
        expect(tree.stat('nope')).toBeUndefined();
        expect(tree.readdir('README.md')).toBeUndefined();
    });

    it('adds a written file with its folders and bumps the mtime of a rewritten one', () => {
        const tree = new WorkspaceTree(LISTING);
        const created = tree.written('new/deep/A.arc', 5);
        expect(created.type).toBe('file');
        expect(tree.stat('new/deep')?.type).toBe('directory');
        expect(tree.readdir('new')).toEqual([['deep', 'directory']]);
        const before = tree.stat('toast-service/TR.arcapp')?.mtime ?? 0;
        const after = tree.written('toast-service/TR.arcapp', 130);
        expect(after.mtime).toBeGreaterThan(before);
        expect(after.size).toBe(130);
    });

    it('removes an entry with everything below it', () => {
        const tree = new WorkspaceTree(LISTING);
        tree.removed('toast-service');
        expect(tree.stat('toast-service/toast/Controller.arc')).toBeUndefined();
        expect(tree.readdir('')).toEqual([['README.md', 'file']]);
    });

    it('normalizes paths', () => {
        expect(normalizePath('/a//b/./c/')).toBe('a/b/c');
        expect(normalizePath('/')).toBe('');
    });
});

describe('matchesPattern', () => {
    it("matches quick open's relaxed way: letters in order, any case, spaces ignored", () => {
        expect(matchesPattern('toast-service/toast/Controller.arc', 'ctrl')).toBe(true);
        expect(matchesPattern('toast-service/toast/Controller.arc', 'toast Controller')).toBe(true);
        expect(matchesPattern('toast-service/toast/Controller.arc', 'CONTROLLER.arc')).toBe(true);
        expect(matchesPattern('toast-service/toast/Controller.arc', 'lrtc')).toBe(false);
        expect(matchesPattern('README.md', '')).toBe(true);
    });
});

describe('extensionFiles', () => {
    it('keeps the relative files of the listing without the manifest and the listing itself', () => {
        expect(extensionFiles(['package.json', 'files.json', 'out/web/extension.js', 'syntaxes/arc.tmLanguage.json'])).toEqual([
            'out/web/extension.js',
            'syntaxes/arc.tmLanguage.json',
        ]);
    });
    it('drops paths that would leave the extension folder, and refuses a listing that is not a list', () => {
        expect(extensionFiles(['/etc/passwd', '../x.js', 'a/../../b', 'ok.js', 3])).toEqual(['ok.js']);
        expect(() => extensionFiles({ files: [] })).toThrow(/not a list/);
    });
});
