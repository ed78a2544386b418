#!/usr/bin/env node
// Completes package-lock.json with the platform-specific optional packages that the npm
// registry reachable from our machines does not serve (e.g. rollup's darwin/win32 builds).
//
// Why: `npm install` here cannot fetch their metadata, so it leaves them out of the lock; `npm ci`
// then refuses the lock ("Missing: @rollup/rollup-darwin-x64@ from lock file"). An entry with
// the version and the platform fields (os/cpu/libc) is all npm needs: on a machine of another
// platform npm skips the package without fetching it, exactly as it would with a complete lock.
//
// Run after every `npm install` that rewrites the lock:  node scripts/complete-lockfile.mjs
// (--check: only report, exit 1 when entries are missing).
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const lockFile = path.join(repo, 'package-lock.json');
const check = process.argv.includes('--check');

const OS = ['aix', 'android', 'darwin', 'freebsd', 'linux', 'netbsd', 'openbsd', 'openharmony', 'sunos', 'win32'];
const CPU = {
    arm: 'arm',
    arm64: 'arm64',
    x64: 'x64',
    ia32: 'ia32',
    loong64: 'loong64',
    ppc64: 'ppc64',
    riscv64: 'riscv64',
    s390x: 's390x',
    mips64el: 'mips64el',
};

/** os/cpu/libc from a package name such as `@rollup/rollup-linux-arm64-musl`, if it names a platform. */
function platformOf(name) {
    if (name === 'fsevents') return { os: ['darwin'] };
    const parts = name.split('/').pop().split('-');
    const i = parts.findIndex((p) => OS.includes(p));
    if (i < 0) return undefined;
    const cpu = CPU[parts[i + 1]];
    if (!cpu) return undefined;
    const rest = parts.slice(i + 2).join('-');
    const fields = { os: [parts[i]], cpu: [cpu] };
    if (parts[i] === 'linux' && /gnu/.test(rest)) fields.libc = ['glibc'];
    if (parts[i] === 'linux' && /musl/.test(rest)) fields.libc = ['musl'];
    return fields;
}

/** Where npm would find `dep` from the package at `location` (node_modules lookup upwards). */
function resolves(packages, location, dep) {
    let dir = location;
    for (;;) {
        if (packages[`${dir ? `${dir}/` : ''}node_modules/${dep}`]) return true;
        if (!dir) return false;
        const at = dir.lastIndexOf('/node_modules/');
        dir = at >= 0 ? dir.slice(0, at) : '';
    }
}

const lock = JSON.parse(readFileSync(lockFile, 'utf8'));
const packages = lock.packages ?? {};
const added = [];
for (const [location, pkg] of Object.entries(packages)) {
    for (const [dep, range] of Object.entries(pkg.optionalDependencies ?? {})) {
        if (resolves(packages, location, dep)) continue;
        const platform = platformOf(dep);
        const version = /^\d+\.\d+\.\d+(?:-[\w.]+)?$/.test(range) ? range : range.replace(/^[~^]/, '');
        if (!platform || !/^\d+\.\d+\.\d+/.test(version)) {
            console.error(`complete-lockfile: cannot complete ${dep}@${range} (needed by ${location || 'the root'}); left as is`);
            continue;
        }
        const fields = { ...platform, optional: true };
        if (pkg.dev) fields.dev = true;
        if (pkg.devOptional) fields.devOptional = true;
        // Key order as npm writes it: version first, then alphabetical.
        const sorted = Object.keys(fields)
            .sort()
            .map((k) => [k, fields[k]]);
        packages[`node_modules/${dep}`] = { version, ...Object.fromEntries(sorted) };
        added.push(`${dep}@${version}`);
    }
}

if (added.length === 0) {
    console.log('complete-lockfile: package-lock.json lists every optional platform package');
} else if (check) {
    console.error(`complete-lockfile: ${added.length} optional platform packages missing from package-lock.json:\n  ${added.join('\n  ')}`);
    process.exit(1);
} else {
    lock.packages = Object.fromEntries(
        Object.entries(packages).sort(([a], [b]) => (a === '' ? -1 : b === '' ? 1 : a.localeCompare(b, 'en'))),
    );
    writeFileSync(lockFile, `${JSON.stringify(lock, null, 2)}\n`);
    console.log(`complete-lockfile: added ${added.length} optional platform packages to package-lock.json:\n  ${added.join('\n  ')}`);
}
