// Where maa-sim runs from (sim-server/lib/sim-env.mjs, docs/releasing.md "The simulator"): $MAA_SIM,
// the clone's development venv, or a cached venv installed on first use. The install runs with a
// stand-in python3 (a shell script that answers the version check, `-m venv` and `-m pip install`
// as the real ones would, without PyPI), so every path is taken in seconds.
import { chmodSync, existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
// @ts-expect-error -- a plain .mjs module; its declarations (lib/sim-env.d.mts) are for packages that install it
import { cacheDir, cachedVenv, ensureMaaSim, sourcesHash } from '../../sim-server/lib/sim-env.mjs';

let root: string;
let sources: string;
let python: string;
let control: string;
let progress: string[];

/** A python3 stand-in; `control/<name>` files switch its failures on. */
function fakePython(file: string): void {
    writeFileSync(
        file,
        `#!/usr/bin/env bash
control=${JSON.stringify(control)}
if [[ "$1" == "-c" ]]; then
  version=$(cat "$control/version" 2>/dev/null || echo 3.11.7)
  echo "$version"
  [[ "$version" == 3.1[1-9]* ]] && exit 0 || exit 3
fi
if [[ "$1 $2" == "-m venv" ]]; then mkdir -p "$3/bin" && cp "$0" "$3/bin/python" && echo "created $3" && exit 0; fi
if [[ "$1 $2" == "-m pip" ]]; then
  src="\${@: -1}"
  extras=""
  if [[ "$src" == *"["*"]" ]]; then extras="\${src##*[}"; extras="\${extras%]}"; src="\${src%[*}"; fi
  echo "$extras" > "$(dirname "$0")/extras"
  [[ -f "$src/pyproject.toml" && -f "$src/src/maa_sim/cli.py" ]] || { echo "no sources in $src" >&2; exit 1; }
  echo "Collecting mujoco==4.0.0"
  if [[ -f "$control/pip-fails" ]]; then echo "ERROR: No matching distribution found for mujoco" >&2; exit 1; fi
  printf '#!/bin/sh\\necho fake maa-sim\\n' > "$(dirname "$0")/maa-sim" && chmod +x "$(dirname "$0")/maa-sim"
  echo "Successfully installed maa-sim-0.1.0"
  exit 0
fi
exit 9
`,
    );
    chmodSync(file, 0o755);
}

function ensure(env: Record<string, string> = {}, extras: string[] = []): Promise<string> {
    return ensureMaaSim({
        env: { MAA_CACHE_DIR: path.join(root, 'cache'), ...env },
        python,
        dir: sources,
        extras,
        onProgress: (l: string) => progress.push(l),
    });
}

/** The extras the stand-in pip installed last in the venv of `maaSim`. */
const installedExtras = (maaSim: string) => readFileSync(path.join(path.dirname(maaSim), 'extras'), 'utf8').trim();

beforeEach(() => {
    root = mkdtempSync(path.join(tmpdir(), 'maa-sim-env-'));
    sources = path.join(root, 'sim-server');
    control = path.join(root, 'control');
    mkdirSync(path.join(sources, 'src', 'maa_sim'), { recursive: true });
    mkdirSync(control);
    writeFileSync(path.join(sources, 'pyproject.toml'), '[project]\nname = "maa-sim"\n');
    writeFileSync(path.join(sources, 'src', 'maa_sim', 'cli.py'), 'def main() -> int:\n    return 0\n');
    python = path.join(root, 'python3');
    fakePython(python);
    progress = [];
});

afterEach(() => {
    rmSync(root, { recursive: true, force: true });
});

describe('ensureMaaSim', () => {
    it('takes $MAA_SIM as it is', async () => {
        expect(await ensure({ MAA_SIM: '/opt/maa-sim' })).toBe('/opt/maa-sim');
        expect(progress).toEqual([]);
    });

    it("takes a clone's development venv when it exists", async () => {
        mkdirSync(path.join(sources, '.venv', 'bin'), { recursive: true });
        writeFileSync(path.join(sources, '.venv', 'bin', 'maa-sim'), '');
        expect(await ensure()).toBe(path.join(sources, '.venv', 'bin', 'maa-sim'));
        expect(existsSync(path.join(root, 'cache'))).toBe(false);
    });

    it('installs into the cached venv on first use with progress, and reuses it after', async () => {
        const maaSim = await ensure();
        const venv = cachedVenv({ MAA_CACHE_DIR: path.join(root, 'cache') }, sources);
        expect(maaSim).toBe(path.join(venv, 'bin', 'maa-sim'));
        expect(readFileSync(maaSim, 'utf8')).toContain('fake maa-sim');
        expect(progress[0]).toMatch(/^maa-sim: first use: installing the simulator into /);
        expect(progress).toContain('maa-sim: pip install: Successfully installed maa-sim-0.1.0');
        expect(progress.at(-1)).toBe(`maa-sim: installed (${maaSim})`);
        progress = [];
        expect(await ensure()).toBe(maaSim);
        expect(progress).toEqual([]);
    });

    it("installs maa-sim's extras when asked (the grading engine's Ray) and keeps them for callers without", async () => {
        const plain = await ensure();
        expect(installedExtras(plain)).toBe('');
        progress = [];
        // the venv lacks the grade extra: it is installed again, with it
        expect(await ensure({}, ['grade'])).toBe(plain);
        expect(progress[0]).toMatch(/first use: installing the simulator into .* \(MuJoCo, rclpy, viser, Ray from PyPI/);
        expect(installedExtras(plain)).toBe('grade');
        progress = [];
        // a caller without extras and one with them both take it as it is
        expect(await ensure()).toBe(plain);
        expect(await ensure({}, ['grade'])).toBe(plain);
        expect(progress).toEqual([]);
    });

    it('gets a new venv when the sources change', async () => {
        const first = await ensure();
        writeFileSync(path.join(sources, 'src', 'maa_sim', 'cli.py'), 'def main() -> int:\n    return 1\n');
        const second = await ensure();
        expect(second).not.toBe(first);
        expect(path.basename(path.dirname(path.dirname(second)))).toBe(`sim-${sourcesHash(sources)}`);
    });

    it('starts over after an install that did not finish', async () => {
        const maaSim = await ensure();
        rmSync(path.join(path.dirname(path.dirname(maaSim)), '.maa-sim-installed'));
        progress = [];
        expect(await ensure()).toBe(maaSim);
        expect(progress[0]).toMatch(/first use/);
    });

    it('fails with pip’s message when pip fails, and leaves no venv that counts as installed', async () => {
        writeFileSync(path.join(control, 'pip-fails'), '');
        await expect(ensure()).rejects.toThrow(/pip install failed \(exit 1\):[\s\S]*No matching distribution found for mujoco/);
        rmSync(path.join(control, 'pip-fails'));
        progress = [];
        await ensure();
        expect(progress[0]).toMatch(/first use/);
    });

    it('needs Python 3.11 or newer', async () => {
        writeFileSync(path.join(control, 'version'), '3.10.12');
        await expect(ensure()).rejects.toThrow('maa-sim needs Python 3.11 or newer; ');
        await expect(ensureMaaSim({ env: { MAA_CACHE_DIR: root }, python: path.join(root, 'missing'), dir: sources })).rejects.toThrow(
            /could not run .*missing \(set MAA_PYTHON\)/,
        );
    });
});

describe('cacheDir', () => {
    it('is $MAA_CACHE_DIR, else $XDG_CACHE_HOME/maa, else ~/.cache/maa', () => {
        expect(cacheDir({ MAA_CACHE_DIR: '/c', XDG_CACHE_HOME: '/x' })).toBe('/c');
        expect(cacheDir({ XDG_CACHE_HOME: '/x' })).toBe('/x/maa');
        expect(cacheDir({})).toMatch(/[/\\]\.cache[/\\]maa$/);
    });
});
