import { URI } from 'langium';
import { resolveModelRoot } from './workspace/model-root.js';

/**
 * The model roots of a workspace. Every model file belongs to exactly one root (the longest
 * root folder containing it); packages are the folders below the root, and names resolve only
 * among the files of the same root plus the built-in library. This is what lets one process
 * check several independent projects (or hundreds of test cases) at once.
 */
export class ModelRoots {
    static readonly BUILTIN_SCHEME = 'builtin';
    private roots: string[] = [];

    setRoots(roots: URI[]): void {
        this.roots = roots.map((r) => withSlash(r.toString())).sort((a, b) => b.length - a.length);
    }

    addRoot(root: URI): void {
        this.setRoots([...this.roots.map((r) => URI.parse(r)), root]);
    }

    all(): readonly string[] {
        return this.roots;
    }

    isBuiltin(uri: URI | string): boolean {
        return (typeof uri === 'string' ? URI.parse(uri) : uri).scheme === ModelRoots.BUILTIN_SCHEME;
    }

    /**
     * The root a document belongs to. A document outside every root gets its root by the one rule
     * of `resolveModelRoot` (docs/user-guide.md, "Model roots"): the configured roots are the
     * folders with a `maa.json` the workspace manager found, and a document outside all of them
     * has none above it that is known, so its root is its own folder.
     */
    rootOf(uri: URI | string): string {
        const s = typeof uri === 'string' ? uri : uri.toString();
        if (this.isBuiltin(s)) return `${ModelRoots.BUILTIN_SCHEME}:/`;
        for (const root of this.roots) {
            if (s.startsWith(root)) return root;
        }
        return withSlash(resolveModelRoot(s, { hasMarker: () => false }));
    }

    /** The package a document's folder denotes (`a.b` for `<root>/a/b/X.arc`). */
    expectedPackage(uri: URI | string): string {
        const s = typeof uri === 'string' ? uri : uri.toString();
        const root = this.rootOf(s);
        const rel = decodeURIComponent(s.substring(root.length));
        const folder = rel.includes('/') ? rel.substring(0, rel.lastIndexOf('/')) : '';
        return folder
            .split('/')
            .filter((p) => p.length > 0)
            .join('.');
    }

    /** Whether a document may see the symbols of another: same root, or the other is built in. */
    visible(from: URI | string, to: URI | string): boolean {
        return this.isBuiltin(to) || this.rootOf(from) === this.rootOf(to);
    }
}

function withSlash(s: string): string {
    return s.endsWith('/') ? s : `${s}/`;
}
