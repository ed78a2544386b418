import { URI, UriUtils } from 'langium';
import { ManifestError, validateManifest, type ManifestSource } from '../manifest/manifest.js';
import { compare } from '../model/architecture.js';
import { GeneratorRegistry, type RegisteredGenerator } from './registry.js';

/**
 * The part of a file system discovery needs; Langium's FileSystemProvider (NodeFileSystem in
 * Node, EmptyFileSystem in a browser) provides it, so the same code serves the CLI and the
 * language server.
 */
export interface ManifestFileSystem {
    existsSync(uri: URI): boolean;
    readFileSync(uri: URI): string;
    readDirectorySync(uri: URI): ReadonlyArray<{ readonly uri: URI }>;
}

export interface DiscoveryOptions {
    /**
     * Further folders whose `node_modules` (and package.json) are searched, with their
     * ancestors, after those above `from` (default: the installation of generator-core itself,
     * so generators installed next to the tools are found).
     */
    readonly extraRoots?: readonly URI[];
}

/** The folder generator-core is installed in, when it runs from files (not in a browser bundle). */
export function installationRoot(): URI | undefined {
    try {
        const self = URI.parse(import.meta.url);
        return self.scheme === 'file' ? UriUtils.dirname(self) : undefined;
    } catch {
        return undefined;
    }
}

/**
 * Discovers the generators of installed packages, as Node would resolve packages from the folder
 * `from`: every `node_modules` folder on the way up to the file-system root (a nearer package
 * shadows a farther one of the same name), plus the `package.json` files on that way (a
 * project may declare its own generators). A package declares its generators in its
 * package.json as `"maa": { "generators": [ MANIFEST | "path/to/manifest.json", ... ] }`.
 */
export function discoverGenerators(fs: ManifestFileSystem, from: URI, options: DiscoveryOptions = {}): GeneratorRegistry {
    const generators: RegisteredGenerator[] = [];
    const problems: ManifestError[] = [];
    const seenPackages = new Set<string>();
    const seenDirs = new Set<string>();

    const readPackage = (dir: URI): void => {
        const key = dir.toString();
        if (seenDirs.has(key)) return;
        seenDirs.add(key);
        const file = UriUtils.joinPath(dir, 'package.json');
        let pkg: Record<string, unknown>;
        try {
            if (!fs.existsSync(file)) return;
            pkg = JSON.parse(fs.readFileSync(file)) as Record<string, unknown>;
        } catch {
            return; // not a package we can read: not ours to judge
        }
        if (typeof pkg !== 'object' || pkg === null) return;
        const maa = pkg['maa'] as Record<string, unknown> | undefined;
        if (!maa || typeof maa !== 'object' || !('generators' in maa)) return;
        const name = typeof pkg['name'] === 'string' ? pkg['name'] : dir.path.substring(dir.path.lastIndexOf('/') + 1);
        if (seenPackages.has(name)) return;
        seenPackages.add(name);
        const version = typeof pkg['version'] === 'string' ? pkg['version'] : '0.0.0';
        const declared = maa['generators'];
        if (!Array.isArray(declared)) {
            problems.push(new ManifestError(name, file.fsPath, 'maa.generators', 'must be an array of manifests or manifest file paths'));
            return;
        }
        declared.forEach((item: unknown, i) => {
            const field = `maa.generators[${i}]`;
            try {
                let json = item;
                let source: ManifestSource = {
                    packageName: name,
                    packageVersion: version,
                    packageDir: dir.fsPath,
                    file: file.fsPath,
                    field,
                };
                if (typeof item === 'string') {
                    const manifestFile = UriUtils.resolvePath(dir, item);
                    if (!manifestFile.path.startsWith(`${dir.path}/`)) {
                        throw new ManifestError(name, file.fsPath, field, `manifest file '${item}' lies outside the package`);
                    }
                    let text: string;
                    try {
                        text = fs.readFileSync(manifestFile);
                    } catch {
                        throw new ManifestError(name, file.fsPath, field, `cannot read manifest file '${item}'`);
                    }
                    try {
                        json = JSON.parse(text);
                    } catch (e) {
                        throw new ManifestError(name, manifestFile.fsPath, '', `invalid JSON (${(e as Error).message})`);
                    }
                    source = { ...source, file: manifestFile.fsPath, field: '' };
                } else if (typeof item !== 'object' || item === null || Array.isArray(item)) {
                    throw new ManifestError(name, file.fsPath, field, 'must be a manifest object or the path of a manifest file');
                }
                const manifest = validateManifest(json, { packageName: name, file: source.file, field: source.field });
                generators.push({ manifest, source });
            } catch (e) {
                if (e instanceof ManifestError) problems.push(e);
                else throw e;
            }
        });
    };

    const searchNodeModules = (dir: URI): void => {
        const nm = UriUtils.joinPath(dir, 'node_modules');
        for (const entry of list(fs, nm)) {
            const base = UriUtils.basename(entry);
            if (base.startsWith('.')) continue;
            if (base.startsWith('@')) {
                for (const scoped of list(fs, entry)) readPackage(scoped);
            } else {
                readPackage(entry);
            }
        }
    };

    const extra = options.extraRoots ?? [installationRoot()].filter((r): r is URI => r !== undefined);
    const roots = [...ancestors(from), ...extra.flatMap((r) => ancestors(r))];
    for (const dir of roots) {
        readPackage(dir);
        searchNodeModules(dir);
    }
    return new GeneratorRegistry(generators, problems);
}

function list(fs: ManifestFileSystem, dir: URI): URI[] {
    try {
        if (!fs.existsSync(dir)) return [];
        return fs
            .readDirectorySync(dir)
            .map((e) => e.uri)
            .sort((a, b) => compare(a.path, b.path));
    } catch {
        return [];
    }
}

/** The folder and every folder above it. */
function ancestors(dir: URI): URI[] {
    const out: URI[] = [];
    let d = dir;
    for (;;) {
        out.push(d);
        const parent = UriUtils.dirname(d);
        if (parent.path === d.path) break;
        d = parent;
    }
    return out;
}
