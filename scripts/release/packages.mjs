// The workspace's packages as a release sees them: which are public (published to the registry,
// installed by users), their versions, and the version bump of `npm run release` as pure
// functions over package.json texts (scripts/release/release.mjs does the I/O; docs/releasing.md).
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';

/** The dependency fields whose ranges on workspace packages a bump rewrites. */
export const DEPENDENCY_FIELDS = ['dependencies', 'devDependencies', 'peerDependencies', 'optionalDependencies'];

const SEMVER = /^(\d+)\.(\d+)\.(\d+)(?:-([0-9A-Za-z.-]+))?$/;

/**
 * Every workspace package of the repository at `repo`, in the root package.json's order:
 * `{ dir, file, text, json }` (dir relative to the repository, text the package.json as written).
 */
export function readWorkspace(repo) {
    const root = JSON.parse(readFileSync(path.join(repo, 'package.json'), 'utf8'));
    return root.workspaces.map((dir) => {
        const file = path.join(repo, dir, 'package.json');
        const text = readFileSync(file, 'utf8');
        return { dir, file, text, json: JSON.parse(text) };
    });
}

/** The packages a user installs: every workspace package not marked private. */
export function publicPackages(packages) {
    return packages.filter((p) => p.json.private !== true);
}

/**
 * The public packages ordered so that each comes after the workspace packages it depends on
 * (runtime dependencies), the order `npm publish` must follow; ties keep the workspace order.
 */
export function dependencyOrder(packages) {
    const byName = new Map(packages.map((p) => [p.json.name, p]));
    const done = new Set();
    const order = [];
    const visit = (p, trail) => {
        if (done.has(p.json.name)) return;
        if (trail.includes(p.json.name)) throw new Error(`dependency cycle: ${[...trail, p.json.name].join(' -> ')}`);
        for (const dep of Object.keys(p.json.dependencies ?? {})) {
            const target = byName.get(dep);
            if (target) visit(target, [...trail, p.json.name]);
        }
        done.add(p.json.name);
        order.push(p);
    };
    for (const p of packages) visit(p, []);
    return order;
}

/**
 * The version a release gets: `spec` is a version (`1.2.3`, `1.2.3-rc.1`) or `major`, `minor`,
 * `patch` (from `current`). Throws on anything else and on a version that does not exceed `current`.
 */
export function nextVersion(current, spec) {
    const now = SEMVER.exec(current);
    if (!now) throw new Error(`the current version '${current}' is not a semantic version`);
    const [major, minor, patch] = now.slice(1, 4).map(Number);
    const bumped = {
        major: `${major + 1}.0.0`,
        minor: `${major}.${minor + 1}.0`,
        // a prerelease 1.2.3-rc.1 is released as 1.2.3
        patch: now[4] ? `${major}.${minor}.${patch}` : `${major}.${minor}.${patch + 1}`,
    }[spec];
    const version = bumped ?? spec;
    if (!SEMVER.test(version)) throw new Error(`'${spec}' is neither a version (1.2.3, 1.2.3-rc.1) nor major, minor or patch`);
    if (compareVersions(version, current) <= 0) throw new Error(`${version} does not come after the current version ${current}`);
    return version;
}

/** Semantic-version precedence (-1, 0, 1); a prerelease comes before its release. */
export function compareVersions(a, b) {
    const [pa, pb] = [SEMVER.exec(a), SEMVER.exec(b)];
    if (!pa || !pb) throw new Error(`not a semantic version: ${pa ? b : a}`);
    for (let i = 1; i <= 3; i++) {
        const d = Number(pa[i]) - Number(pb[i]);
        if (d !== 0) return Math.sign(d);
    }
    if (pa[4] === pb[4]) return 0;
    if (pa[4] === undefined) return 1;
    if (pb[4] === undefined) return -1;
    return comparePrerelease(pa[4].split('.'), pb[4].split('.'));
}

function comparePrerelease(a, b) {
    for (let i = 0; i < Math.max(a.length, b.length); i++) {
        if (a[i] === undefined) return -1;
        if (b[i] === undefined) return 1;
        const [na, nb] = [/^\d+$/.test(a[i]), /^\d+$/.test(b[i])];
        if (na && nb && Number(a[i]) !== Number(b[i])) return Math.sign(Number(a[i]) - Number(b[i]));
        if (na !== nb) return na ? -1 : 1; // numeric identifiers sort before alphanumeric ones
        if (!na && a[i] !== b[i]) return a[i] < b[i] ? -1 : 1;
    }
    return 0;
}

/** The one version every public package carries (they are released together); throws when they differ. */
export function sharedVersion(packages) {
    const versions = new Set(publicPackages(packages).map((p) => p.json.version));
    if (versions.size !== 1) {
        const list = publicPackages(packages).map((p) => `${p.json.name}@${p.json.version}`);
        throw new Error(`the public packages must share one version before a release: ${list.join(', ')}`);
    }
    return [...versions][0];
}

/**
 * The bump to `version`, as `{ dir, text }` for every package.json that changes: each public
 * package's `version`, and in every workspace package (private ones too, so the workspace still
 * resolves) each dependency range on a public package, pinned to exactly `version` (the packages
 * are released and tested together). Texts keep their formatting: only those values change.
 */
export function planBump(packages, version) {
    const bumped = new Set(publicPackages(packages).map((p) => p.json.name));
    const changes = [];
    for (const p of packages) {
        let text = p.json.private === true ? p.text : setTopLevelVersion(p.text, version);
        for (const field of DEPENDENCY_FIELDS) {
            for (const dep of Object.keys(p.json[field] ?? {})) {
                if (bumped.has(dep)) text = setDependencyRange(text, field, dep, version);
            }
        }
        if (text !== p.text) changes.push({ dir: p.dir, text });
    }
    return changes;
}

/** `text` (a package.json) with its top-level `"version"` set to `version`. */
export function setTopLevelVersion(text, version) {
    const changed = replaceInObject(text, topLevelSpan(text), 'version', version);
    if (changed === undefined) throw new Error('package.json has no top-level "version"');
    return changed;
}

/** `text` (a package.json) with the range of `dep` in its `field` object set to `range`. */
export function setDependencyRange(text, field, dep, range) {
    const span = objectSpan(text, field);
    const changed = span && replaceInObject(text, span, dep, range);
    if (changed === undefined) throw new Error(`package.json has no "${dep}" in "${field}"`);
    return changed;
}

/** The span of the root object's own members (nested objects skipped by depth). */
function topLevelSpan(text) {
    return { start: text.indexOf('{') + 1, end: text.lastIndexOf('}'), depth: 1 };
}

/** The span inside the top-level object member `field` (`"field": { ... }`), or undefined. */
function objectSpan(text, field) {
    const opening = new RegExp(`^\\s*"${escapeRegExp(field)}"\\s*:\\s*\\{`, 'm').exec(text);
    if (!opening) return undefined;
    const start = opening.index + opening[0].length;
    let depth = 1;
    for (let i = start; i < text.length; i++) {
        if (text[i] === '"') i = stringEnd(text, i);
        else if (text[i] === '{') depth++;
        else if (text[i] === '}' && --depth === 0) return { start, end: i, depth: 1 };
    }
    return undefined;
}

/** Replaces the string value of member `key` directly inside `span` (not in nested objects); undefined when absent. */
function replaceInObject(text, span, key, value) {
    let depth = 1;
    for (let i = span.start; i < span.end; i++) {
        const c = text[i];
        if (c === '{' || c === '[') depth++;
        else if (c === '}' || c === ']') depth--;
        else if (c === '"') {
            const end = stringEnd(text, i);
            const member = depth === span.depth && JSON.parse(text.slice(i, end + 1)) === key;
            const value0 = member ? /^\s*:\s*"/.exec(text.slice(end + 1)) : null;
            if (value0) {
                const valueStart = end + 1 + value0[0].length - 1;
                const valueEnd = stringEnd(text, valueStart);
                return text.slice(0, valueStart) + JSON.stringify(value) + text.slice(valueEnd + 1);
            }
            i = end;
        }
    }
    return undefined;
}

/** The index of the closing quote of the JSON string opening at `start`. */
function stringEnd(text, start) {
    for (let i = start + 1; i < text.length; i++) {
        if (text[i] === '\\') i++;
        else if (text[i] === '"') return i;
    }
    throw new Error('unterminated string in package.json');
}

function escapeRegExp(s) {
    return s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
}

/**
 * Packs the named workspace packages into `dest` with `npm pack` (their prepack scripts run);
 * resolves to `[{ name, version, filename, size, unpackedSize, files }]` (size in bytes).
 */
export function packPackages(repo, names, dest) {
    const args = ['pack', '--json', '--pack-destination', dest, ...names.flatMap((n) => ['--workspace', n])];
    return new Promise((resolve, reject) => {
        const child = spawn(process.platform === 'win32' ? 'npm.cmd' : 'npm', args, { cwd: repo, stdio: ['ignore', 'pipe', 'pipe'] });
        let out = '';
        let err = '';
        child.stdout.on('data', (d) => {
            out += d;
        });
        child.stderr.on('data', (d) => {
            err += d;
        });
        child.on('error', reject);
        child.on('close', (code) => {
            if (code !== 0) return reject(new Error(`npm pack exited with ${code}: ${err.trim().split('\n').slice(-5).join('\n')}`));
            const packed = JSON.parse(out.slice(out.indexOf('[')));
            resolve(packed.map((p) => ({ ...p, files: p.files.map((f) => f.path) })));
        });
    });
}
