#!/usr/bin/env node
// Builds the workspace packages whose inputs changed since their last build, in dependency order,
// and skips the others (`npm start` uses it; a second start with nothing changed builds nothing).
//
// A package is rebuilt when its build key differs from the one recorded after its last successful
// build, or when its outputs are gone or differ from what that build left. The key hashes the
// contents of
//   - the package's own sources: every file of its folder except the outputs (dist/, build/,
//     src/generated/) and tool folders (node_modules/, venvs, caches), so package.json (with the
//     build script), tsconfig.json, grammars and tests count;
//   - tsconfig.base.json and package-lock.json at the root (compiler options, third-party versions);
//   - for every workspace package it depends on, directly or not: that package's sources (without
//     its test/ and bench/ folders, which no dependent reads) and its outputs, so a rebuild of a
//     dependency that changed nothing it exports rebuilds nothing after it;
//   - the generator declarations of every workspace package (the `maa.generators` field of its
//     package.json and the manifest files it names), which language-server's build reads
//     (bin/write-generator-manifests.mjs) without depending on those packages.
//   - the folders outside the package that its build copies (outsideInputs below: the project
//     templates of @maa/cli, one of which is examples/toast-service).
// Contents, not modification times: a checkout or a copy that keeps the contents rebuilds nothing,
// and an edit that restores a file's old contents too. The records live in
// node_modules/.cache/maa-build/ (so `npm ci` starts over with a full build).
//
// Usage: node scripts/build-if-stale.mjs [--force] [--verbose] [--dry-run]
//   --force     build every package, whatever the records say
//   --verbose   show the output of every build (otherwise only of a build that fails)
//   --dry-run   build nothing; say which packages would be built and why
import { spawn } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

/** The folders (relative to a package) a build writes; everything else in the package is a source. */
export const OUTPUT_DIRS = ['dist', 'build', 'src/generated'];

/** Folders that are neither sources nor outputs: installed tools, Python environments, caches. */
const TOOL_DIRS = new Set([
    'node_modules',
    '__pycache__',
    '.pytest_cache',
    '.ruff_cache',
    '.mypy_cache',
    '.cache',
    'coverage',
    '.vitest-cache',
]);

/** Top-level folders of a dependency that its dependents never read. */
const PRIVATE_DIRS = ['test', 'bench'];

/** Files at the root of the repository that every build reads. */
export const ROOT_INPUTS = ['tsconfig.base.json', 'package-lock.json'];

const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';

function isToolEntry(name) {
    return TOOL_DIRS.has(name) || name.startsWith('.venv') || name.endsWith('.tsbuildinfo') || name === '.DS_Store';
}

/**
 * The files under `dir` (relative, with `/`, sorted), leaving out tool folders and every folder
 * whose path relative to `dir` is in `skip`.
 */
export function listFiles(dir, skip = []) {
    const files = [];
    const walk = (rel) => {
        let entries;
        try {
            entries = readdirSync(path.join(dir, rel), { withFileTypes: true });
        } catch {
            return; // a folder that is missing (or vanished meanwhile) holds nothing
        }
        for (const entry of entries) {
            if (isToolEntry(entry.name)) continue;
            const child = rel ? `${rel}/${entry.name}` : entry.name;
            if (entry.isDirectory()) {
                if (!skip.includes(child)) walk(child);
            } else if (entry.isFile() || entry.isSymbolicLink()) {
                files.push(child);
            }
        }
    };
    walk('');
    return files.sort();
}

/** A package's sources: its files outside the output folders (`forDependents`: without test/ and bench/ too). */
export function sourceFiles(pkgDir, forDependents = false) {
    return listFiles(pkgDir, forDependents ? [...OUTPUT_DIRS, ...PRIVATE_DIRS] : OUTPUT_DIRS);
}

/** A package's outputs: the files in its output folders. */
export function outputFiles(pkgDir) {
    return OUTPUT_DIRS.flatMap((out) => listFiles(path.join(pkgDir, out)).map((f) => `${out}/${f}`));
}

/** One hash of the names and contents of `files` (relative to `root`); a missing file hashes as missing. */
export function hashFiles(root, files) {
    const hash = createHash('sha256');
    for (const file of files) {
        let content;
        try {
            content = readFileSync(path.join(root, file));
        } catch {
            content = null;
        }
        hash.update(`${file}\0${content === null ? '-' : createHash('sha256').update(content).digest('hex')}\n`);
    }
    return hash.digest('hex');
}

/** The hash of no files at all: the outputs of a package that has none. */
export const NO_FILES = hashFiles('.', []);

/**
 * The build key of a package from the hashes of everything its build reads (see the header):
 * `own` its sources, `root` the root inputs, `deps` one `{ name, sources, outputs }` per
 * workspace package it depends on, `declarations` the generator declarations, `outside` the
 * folders outside the package that its build reads.
 */
export function buildKey({ own, root, deps, declarations, outside = NO_FILES }) {
    const hash = createHash('sha256').update(`own ${own}\nroot ${root}\ndeclarations ${declarations}\noutside ${outside}\n`);
    for (const dep of [...deps].sort((a, b) => a.name.localeCompare(b.name))) {
        hash.update(`dep ${dep.name} ${dep.sources} ${dep.outputs}\n`);
    }
    return hash.digest('hex');
}

/**
 * Whether a package must be built: `record` is what its last successful build left (`{ key,
 * outputs }`, undefined when there was none), `key` its build key now, `outputs` the hash of its
 * outputs now. Returns `{ stale, reason }`.
 */
export function staleness(record, key, outputs) {
    if (!record) return { stale: true, reason: 'no build recorded' };
    if (record.key !== key) return { stale: true, reason: 'inputs changed' };
    if (outputs === NO_FILES) return { stale: true, reason: 'outputs missing' };
    if (record.outputs !== outputs) return { stale: true, reason: 'outputs changed since its build' };
    return { stale: false, reason: 'up to date' };
}

/**
 * The workspace packages of the repository at `repo`, in an order where each comes after the
 * workspace packages it depends on (ties keep the order of the root package.json). Each is
 * `{ name, dir, rel, build, deps, closure }`: `build` its build script (undefined: nothing to
 * build), `deps` the names of the workspace packages it depends on, `closure` those it depends on
 * directly or not.
 */
export function readWorkspaces(repo) {
    const root = JSON.parse(readFileSync(path.join(repo, 'package.json'), 'utf8'));
    const listed = (root.workspaces ?? []).map((rel) => {
        const dir = path.join(repo, rel);
        const pkg = JSON.parse(readFileSync(path.join(dir, 'package.json'), 'utf8'));
        const declared = { ...pkg.dependencies, ...pkg.devDependencies, ...pkg.peerDependencies, ...pkg.optionalDependencies };
        return { name: pkg.name, dir, rel, build: pkg.scripts?.build, declared: Object.keys(declared), pkg };
    });
    const names = new Set(listed.map((w) => w.name));
    const byName = new Map(listed.map((w) => [w.name, w]));
    for (const w of listed) w.deps = w.declared.filter((d) => names.has(d) && d !== w.name);
    for (const w of listed) w.closure = dependencyClosure(w, byName);
    return dependencyOrder(listed).map(({ name, dir, rel, build, deps, closure, pkg }) => ({ name, dir, rel, build, deps, closure, pkg }));
}

function dependencyClosure(start, byName) {
    const seen = new Set();
    const visit = (w) => {
        for (const d of w.deps) {
            if (seen.has(d) || d === start.name) continue;
            seen.add(d);
            visit(byName.get(d));
        }
    };
    visit(start);
    return [...seen].sort();
}

/** Dependencies first; within a dependency cycle (dev dependencies may close one) the listed order decides. */
function dependencyOrder(listed) {
    const done = new Set();
    const order = [];
    while (order.length < listed.length) {
        const ready = listed.find((w) => !done.has(w.name) && w.deps.every((d) => done.has(d)));
        const next = ready ?? listed.find((w) => !done.has(w.name));
        done.add(next.name);
        order.push(next);
    }
    return order;
}

/**
 * The folders outside a package (relative to the repository) that its build reads: the `from`
 * folders of its templates/templates.json that lie outside it (@maa/cli's scripts/copy-templates.mjs
 * copies each into dist/templates; the toast-service template is examples/toast-service).
 */
export function outsideInputs(repo, w) {
    let manifest;
    try {
        manifest = JSON.parse(readFileSync(path.join(w.dir, 'templates', 'templates.json'), 'utf8'));
    } catch {
        return []; // no templates (or none readable: its build reports that)
    }
    const folders = (Array.isArray(manifest?.templates) ? manifest.templates : [])
        .filter((t) => typeof t?.from === 'string')
        .map((t) => path.resolve(w.dir, t.from))
        .filter((dir) => path.relative(w.dir, dir).startsWith('..'))
        .map((dir) => path.relative(repo, dir).split(path.sep).join('/'));
    return [...new Set(folders)].sort();
}

/** One hash of the files of the given folders of the repository. */
function foldersHash(repo, folders) {
    return hashFiles(
        repo,
        folders.flatMap((folder) => listFiles(path.join(repo, folder)).map((f) => `${folder}/${f}`)),
    );
}

/** The hash of every workspace package's generator declarations (package.json `maa.generators` and the manifest files named there). */
export function declarationsHash(workspaces) {
    const hash = createHash('sha256');
    for (const w of [...workspaces].sort((a, b) => a.name.localeCompare(b.name))) {
        const declared = w.pkg?.maa?.generators;
        if (!Array.isArray(declared)) continue;
        hash.update(`${w.name} ${JSON.stringify(declared)}\n`);
        const files = declared.filter((item) => typeof item === 'string');
        hash.update(`${hashFiles(w.dir, files)}\n`);
    }
    return hash.digest('hex');
}

function recordFile(stampDir, w) {
    return path.join(stampDir, `${w.rel.replaceAll(/[\\/]/g, '+')}.json`);
}

function readRecord(stampDir, w) {
    try {
        return JSON.parse(readFileSync(recordFile(stampDir, w), 'utf8'));
    } catch {
        return undefined;
    }
}

/** Runs `npm run build` in one workspace package; resolves `{ code, output }` (output: what it printed, unless `verbose` streamed it). */
export function npmBuild(repo, w, verbose) {
    return new Promise((resolve) => {
        const child = spawn(npm, ['run', 'build', '-w', w.rel], { cwd: repo, stdio: verbose ? 'inherit' : ['ignore', 'pipe', 'pipe'] });
        const chunks = [];
        child.stdout?.on('data', (c) => chunks.push(c));
        child.stderr?.on('data', (c) => chunks.push(c));
        child.on('error', (e) => resolve({ code: 2, output: `could not start ${npm}: ${e.message}\n` }));
        child.on('close', (code, signal) => resolve({ code: code ?? (signal ? 128 : 2), output: Buffer.concat(chunks).toString() }));
    });
}

/** Hashes of a package's sources and outputs, computed once each (outputs again after a build). */
class PackageHashes {
    constructor() {
        this.cache = new Map();
    }
    get(w, kind) {
        const key = `${w.name} ${kind}`;
        if (!this.cache.has(key)) {
            const files = kind === 'outputs' ? outputFiles(w.dir) : sourceFiles(w.dir, kind === 'interface');
            this.cache.set(key, hashFiles(w.dir, files));
        }
        return this.cache.get(key);
    }
    forget(w) {
        this.cache.delete(`${w.name} outputs`);
    }
}

function keyOf(repo, w, byName, hashes, root, declarations) {
    const deps = w.closure.map((name) => {
        const dep = byName.get(name);
        return { name, sources: hashes.get(dep, 'interface'), outputs: hashes.get(dep, 'outputs') };
    });
    const outside = foldersHash(repo, outsideInputs(repo, w));
    return buildKey({ own: hashes.get(w, 'sources'), root, deps, declarations, outside });
}

/**
 * Builds the stale packages of the workspace at `repo`, one after the other in dependency order.
 * Options: `force` (build all), `verbose` (stream build output), `dryRun` (build nothing, say
 * what would be built: `built` lists those), `write` (where the progress
 * lines go, default stdout), `first`/`total` (the phase numbers of the progress lines, default
 * 1 and the number of packages with a build script), `stampDir` (default
 * node_modules/.cache/maa-build), `runBuild(w)` (default `npm run build`; resolves
 * `{ code, output }`). Resolves `{ ok, built, skipped, failed }` (names; `failed` the package
 * whose build failed, after which nothing else is built).
 */
export async function buildStale(repo, options = {}) {
    const { force = false, verbose = false, dryRun = false, write = (text) => process.stdout.write(text) } = options;
    const stampDir = options.stampDir ?? path.join(repo, 'node_modules', '.cache', 'maa-build');
    const runBuild = options.runBuild ?? ((w) => npmBuild(repo, w, verbose));
    const workspaces = readWorkspaces(repo);
    const byName = new Map(workspaces.map((w) => [w.name, w]));
    const buildable = workspaces.filter((w) => w.build);
    const first = options.first ?? 1;
    const total = options.total ?? buildable.length;
    const root = hashFiles(repo, ROOT_INPUTS);
    const declarations = declarationsHash(workspaces);
    const hashes = new PackageHashes();
    const result = { ok: true, built: [], skipped: [], failed: undefined };
    for (const [i, w] of buildable.entries()) {
        const phase = `[${first + i}/${total}]`;
        const started = Date.now();
        const key = keyOf(repo, w, byName, hashes, root, declarations);
        const { stale, reason } = force
            ? { stale: true, reason: 'forced' }
            : staleness(readRecord(stampDir, w), key, hashes.get(w, 'outputs'));
        if (dryRun) {
            // a dependent of a package that would be built is rebuilt only when that build changes its outputs
            const after = w.closure.filter((d) => result.built.includes(d));
            const maybe = !stale && after.length > 0 ? `, unless the build of ${after.join(', ')} changes what it depends on` : '';
            write(`${phase} ${w.name}: ${stale ? `would be built (${reason})` : `up to date${maybe}`}\n`);
            (stale ? result.built : result.skipped).push(w.name);
            continue;
        }
        if (!stale) {
            write(`${phase} ${w.name} is up to date (${seconds(started)})\n`);
            result.skipped.push(w.name);
            continue;
        }
        // one line per package ("[2/11] building X (why) ... 12.3 s"), unless its output comes in between
        write(`${phase} building ${w.name} (${reason}) ...${verbose ? '\n' : ''}`);
        const { code, output } = await runBuild(w);
        hashes.forget(w);
        const end = verbose ? `${phase} ${w.name}:` : '';
        if (code !== 0) {
            write(`${end} failed (exit ${code}) after ${seconds(started)}\n`);
            if (output) process.stderr.write(output);
            return { ...result, ok: false, failed: w.name };
        }
        mkdirSync(stampDir, { recursive: true });
        writeFileSync(recordFile(stampDir, w), `${JSON.stringify({ key, outputs: hashes.get(w, 'outputs') })}\n`);
        write(`${end} ${seconds(started)}\n`);
        result.built.push(w.name);
    }
    return result;
}

function seconds(since) {
    return `${((Date.now() - since) / 1000).toFixed(1)} s`;
}

const isMain = process.argv[1] && pathToFileURL(path.resolve(process.argv[1])).href === import.meta.url;
if (isMain) {
    const args = process.argv.slice(2);
    if (args.includes('--help') || args.includes('-h')) {
        console.log(
            'usage: node scripts/build-if-stale.mjs [--force] [--verbose] [--dry-run]\n' +
                '  builds the workspace packages whose inputs changed since their last build (--force: all of them;\n' +
                "  --verbose: show the builds' output; --dry-run: only say what would be built and why)",
        );
        process.exit(0);
    }
    const unknown = args.find((a) => !['--force', '--verbose', '--dry-run'].includes(a));
    if (unknown) {
        console.error(`build-if-stale: unknown argument ${unknown} (see --help)`);
        process.exit(2);
    }
    const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
    if (!existsSync(path.join(repo, 'node_modules'))) {
        console.error('build-if-stale: node_modules is missing; run "npm ci" first');
        process.exit(2);
    }
    const result = await buildStale(repo, {
        force: args.includes('--force'),
        verbose: args.includes('--verbose'),
        dryRun: args.includes('--dry-run'),
    });
    process.exit(result.ok ? 0 : 1);
}
