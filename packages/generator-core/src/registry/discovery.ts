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
    const found: Discovered = { generators: [], problems: [], seenPackages: new Set(), seenDirs: new Set() };
    const extra = options.extraRoots ?? [installationRoot()].filter((r): r is URI => r !== undefined);
    const roots = [...ancestors(from), ...extra.flatMap((r) => ancestors(r))];
    for (const dir of roots) {
        readPackage(fs, dir, found);
        for (const installed of installedPackages(fs, dir)) readPackage(fs, installed, found);
    }
    return new GeneratorRegistry(found.generators, found.problems);
}

/** What discovery has found so far, and what it has already looked at. */
interface Discovered {
    readonly generators: RegisteredGenerator[];
    readonly problems: ManifestError[];
    /** Package names already read: a nearer package shadows a farther one of the same name. */
    readonly seenPackages: Set<string>;
    readonly seenDirs: Set<string>;
}

/** A package that declares generators (`"maa": { "generators": ... }` in its package.json). */
interface DeclaringPackage {
    readonly name: string;
    readonly version: string;
    readonly dir: URI;
    /** Its package.json. */
    readonly file: URI;
    /** The value of `maa.generators`, not yet checked. */
    readonly declared: unknown;
}

/** The package folders of `dir/node_modules` (scoped ones inside their `@scope` folder), in path order. */
function* installedPackages(fs: ManifestFileSystem, dir: URI): Generator<URI> {
    const nm = UriUtils.joinPath(dir, 'node_modules');
    for (const entry of list(fs, nm)) {
        const base = UriUtils.basename(entry);
        if (base.startsWith('.')) continue;
        if (base.startsWith('@')) yield* list(fs, entry);
        else yield entry;
    }
}

/** Registers the generators the package in `dir` declares, once per folder and package name. */
function readPackage(fs: ManifestFileSystem, dir: URI, found: Discovered): void {
    const key = dir.toString();
    if (found.seenDirs.has(key)) return;
    found.seenDirs.add(key);
    const pkg = declaringPackage(fs, dir);
    if (!pkg || found.seenPackages.has(pkg.name)) return;
    found.seenPackages.add(pkg.name);
    if (!Array.isArray(pkg.declared)) {
        found.problems.push(
            new ManifestError(pkg.name, pkg.file.fsPath, 'maa.generators', 'must be an array of manifests or manifest file paths'),
        );
        return;
    }
    pkg.declared.forEach((item: unknown, i) => {
        try {
            found.generators.push(declaredGenerator(fs, pkg, item, `maa.generators[${i}]`));
        } catch (e) {
            if (e instanceof ManifestError) found.problems.push(e);
            else throw e;
        }
    });
}

/** The package in `dir` if its package.json declares generators; a package.json we cannot read is not ours to judge. */
function declaringPackage(fs: ManifestFileSystem, dir: URI): DeclaringPackage | undefined {
    const file = UriUtils.joinPath(dir, 'package.json');
    let pkg: Record<string, unknown>;
    try {
        // A missing file throws too. Discovery reads every installed package's package.json after
        // each workspace change (hundreds in a development checkout): only a text that names the
        // key "maa" can declare generators, so the others are not parsed.
        const text = fs.readFileSync(file);
        if (!text.includes('"maa"')) return undefined;
        pkg = JSON.parse(text) as Record<string, unknown>;
    } catch {
        return undefined;
    }
    if (typeof pkg !== 'object' || pkg === null) return undefined;
    const maa = pkg['maa'] as Record<string, unknown> | undefined;
    if (!maa || typeof maa !== 'object' || !('generators' in maa)) return undefined;
    const name = typeof pkg['name'] === 'string' ? pkg['name'] : dir.path.substring(dir.path.lastIndexOf('/') + 1);
    const version = typeof pkg['version'] === 'string' ? pkg['version'] : '0.0.0';
    return { name, version, dir, file, declared: maa['generators'] };
}

/** One entry of `maa.generators`: a manifest inline or the path of a manifest file in the package, validated. */
function declaredGenerator(fs: ManifestFileSystem, pkg: DeclaringPackage, item: unknown, field: string): RegisteredGenerator {
    const { name, dir, file } = pkg;
    let json = item;
    let source: ManifestSource = {
        packageName: name,
        packageVersion: pkg.version,
        packageDir: dir.fsPath,
        file: file.fsPath,
        field,
    };
    if (typeof item === 'string') {
        const manifestFile = UriUtils.resolvePath(dir, item);
        json = readManifestFile(fs, pkg, manifestFile, item, field);
        source = { ...source, file: manifestFile.fsPath, field: '' };
    } else if (typeof item !== 'object' || item === null || Array.isArray(item)) {
        throw new ManifestError(name, file.fsPath, field, 'must be a manifest object or the path of a manifest file');
    }
    const manifest = validateManifest(json, { packageName: name, file: source.file, field: source.field });
    return { manifest, source };
}

/** The JSON of a manifest file the package names (`item`, as written); it must lie inside the package. */
function readManifestFile(fs: ManifestFileSystem, pkg: DeclaringPackage, manifestFile: URI, item: string, field: string): unknown {
    const { name, dir, file } = pkg;
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
        return JSON.parse(text);
    } catch (e) {
        throw new ManifestError(name, manifestFile.fsPath, '', `invalid JSON (${(e as Error).message})`);
    }
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
