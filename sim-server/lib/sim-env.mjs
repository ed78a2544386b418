// Where maa-sim runs from (docs/releasing.md "The simulator"). In a clone, the development venv
// that sim-server/scripts/setup_env.sh creates (sim-server/.venv). Installed from the registry,
// this package carries maa-sim's Python sources; on first use they are installed with pip into a
// venv in the user's cache folder, keyed by the sources' hash and the interpreter, so an update
// of this package gets a fresh venv and an unchanged one is reused at once.
import { spawn } from 'node:child_process';
import { createHash } from 'node:crypto';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { homedir, tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

/** This package's folder: pyproject.toml and src/maa_sim/ (sim-server/ in a clone). */
export const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

const STAMP = '.maa-sim-installed';

/** The development venv's maa-sim (a clone with `bash sim-server/scripts/setup_env.sh` run). */
export function developmentMaaSim(dir = packageDir) {
    return path.join(dir, '.venv', 'bin', 'maa-sim');
}

/** The folder of cached venvs: $MAA_CACHE_DIR, else $XDG_CACHE_HOME/maa, else ~/.cache/maa. */
export function cacheDir(env = process.env) {
    if (env.MAA_CACHE_DIR) return path.resolve(env.MAA_CACHE_DIR);
    return path.join(env.XDG_CACHE_HOME ? path.resolve(env.XDG_CACHE_HOME) : path.join(homedir(), '.cache'), 'maa');
}

/** A hash of what pip installs: pyproject.toml and every file of src/maa_sim (caches left out), path and contents. */
export function sourcesHash(dir = packageDir) {
    const hash = createHash('sha256');
    const visit = (rel) => {
        const entries = readdirSync(path.join(dir, rel), { withFileTypes: true }).sort((a, b) => (a.name < b.name ? -1 : 1));
        for (const e of entries) {
            if (e.name === '__pycache__' || e.name.endsWith('.egg-info')) continue;
            const child = path.join(rel, e.name);
            if (e.isDirectory()) visit(child);
            else if (e.isFile())
                hash.update(`${child}\0`)
                    .update(readFileSync(path.join(dir, child)))
                    .update('\0');
        }
    };
    hash.update(readFileSync(path.join(dir, 'pyproject.toml')));
    visit(path.join('src', 'maa_sim'));
    return hash.digest('hex').slice(0, 16);
}

/** The cached venv for these sources (it may not exist yet). */
export function cachedVenv(env = process.env, dir = packageDir) {
    return path.join(cacheDir(env), `sim-${sourcesHash(dir)}`);
}

/**
 * The maa-sim to run, installing it first when needed: $MAA_SIM when set, else the development
 * venv's when it exists, else the cached venv's (created with `python` on first use, which takes
 * minutes: MuJoCo, rclpy, viser come from PyPI). Progress lines go to `onProgress`; `dir` is the
 * folder with pyproject.toml and src/maa_sim (this package's; tests pass another).
 */
export async function ensureMaaSim({
    env = process.env,
    python = env.MAA_PYTHON || 'python3',
    onProgress = (line) => console.error(line),
    dir = packageDir,
    extras = [],
} = {}) {
    if (env.MAA_SIM) return env.MAA_SIM;
    if (existsSync(developmentMaaSim(dir))) return developmentMaaSim(dir);
    const venv = cachedVenv(env, dir);
    const maaSim = path.join(venv, 'bin', 'maa-sim');
    const want = `${sourcesHash(dir)} ${await pythonVersion(python)}`;
    if (existsSync(maaSim) && hasInstalled(readIfExists(path.join(venv, STAMP)), want, extras)) return maaSim;
    // A venv is reinstalled with the extras it had and the new ones, so users of different extras
    // (maa-gen sim, the grading engine) do not take turns reinstalling it.
    const had = installedExtras(readIfExists(path.join(venv, STAMP)), want);
    const all = [...new Set([...had, ...extras])].sort();
    await installVenv(dir, venv, python, all.length > 0 ? `${want} [${all.join(',')}]` : want, onProgress, all);
    return maaSim;
}

/** The extras a venv's stamp says were installed with these sources (none when it is of other sources). */
function installedExtras(stamp, want) {
    if (stamp === want) return [];
    const match = stamp?.startsWith(`${want} [`) ? /\[([^\]]*)\]$/.exec(stamp) : null;
    return match ? match[1].split(',').filter(Boolean) : [];
}

function hasInstalled(stamp, want, extras) {
    if (stamp !== want && !stamp?.startsWith(`${want} [`)) return false;
    const had = installedExtras(stamp, want);
    return extras.every((e) => had.includes(e));
}

/** `python --version`, failing with a clear message when it is missing or older than 3.11. */
async function pythonVersion(python) {
    const run = await capture(python, [
        '-c',
        'import sys; print(sys.version.split()[0]); sys.exit(0 if sys.version_info >= (3, 11) else 3)',
    ]);
    if (run.code === 3) throw new Error(`maa-sim needs Python 3.11 or newer; ${python} is ${run.stdout.trim()} (set MAA_PYTHON)`);
    if (run.code !== 0)
        throw new Error(`maa-sim needs Python 3.11 or newer; could not run ${python} (set MAA_PYTHON): ${run.stderr.trim()}`);
    return run.stdout.trim();
}

/**
 * Installs maa-sim into `venv` (venvs cannot be moved, so in place); the stamp is written last,
 * so a venv an interrupted install left behind has none and is removed and made again.
 */
async function installVenv(dir, venv, python, stamp, onProgress, extras) {
    rmSync(venv, { recursive: true, force: true });
    mkdirSync(path.dirname(venv), { recursive: true });
    // pip builds in the source tree; the installed package's folder may be read-only, so build from a copy.
    const sources = mkdtempSync(path.join(tmpdir(), 'maa-sim-src-'));
    try {
        for (const entry of ['pyproject.toml', 'README.md', path.join('src', 'maa_sim')]) {
            if (existsSync(path.join(dir, entry))) cpSync(path.join(dir, entry), path.join(sources, entry), { recursive: true });
        }
        const what = extras.includes('grade') ? 'MuJoCo, rclpy, viser, Ray' : 'MuJoCo, rclpy, viser';
        onProgress(`maa-sim: first use: installing the simulator into ${venv} (${what} from PyPI; a few minutes)`);
        await streamed(python, ['-m', 'venv', venv], onProgress, 'creating the venv');
        const target = extras.length > 0 ? `${sources}[${extras.join(',')}]` : sources;
        const pip = ['-m', 'pip', 'install', '--disable-pip-version-check', '--progress-bar', 'off', target];
        await streamed(path.join(venv, 'bin', 'python'), pip, onProgress, 'pip install');
        writeFileSync(path.join(venv, STAMP), stamp);
        onProgress(`maa-sim: installed (${path.join(venv, 'bin', 'maa-sim')})`);
    } finally {
        rmSync(sources, { recursive: true, force: true });
    }
}

function readIfExists(file) {
    try {
        return readFileSync(file, 'utf8');
    } catch {
        return undefined;
    }
}

function capture(command, args) {
    return new Promise((resolve) => {
        const child = spawn(command, args, { stdio: ['ignore', 'pipe', 'pipe'] });
        let stdout = '';
        let stderr = '';
        child.stdout.on('data', (d) => {
            stdout += d;
        });
        child.stderr.on('data', (d) => {
            stderr += d;
        });
        child.on('error', (e) => resolve({ code: -1, stdout, stderr: e.message }));
        child.on('close', (code) => resolve({ code, stdout, stderr }));
    });
}

/** Runs a setup command, passing each line it prints to `onProgress`; rejects when it fails. */
function streamed(command, args, onProgress, what) {
    return new Promise((resolve, reject) => {
        const child = spawn(command, args, { stdio: ['ignore', 'pipe', 'pipe'] });
        let tail = '';
        const lines = (d) => {
            tail = (tail + d).slice(-4000);
            for (const line of String(d).split('\n')) if (line.trim()) onProgress(`maa-sim: ${what}: ${line.trimEnd()}`);
        };
        child.stdout.on('data', lines);
        child.stderr.on('data', lines);
        child.on('error', (e) => reject(new Error(`maa-sim: ${what}: could not start ${command}: ${e.message}`)));
        child.on('close', (code) =>
            code === 0 ? resolve() : reject(new Error(`maa-sim: ${what} failed (exit ${code}):\n${tail.trim()}`)),
        );
    });
}
