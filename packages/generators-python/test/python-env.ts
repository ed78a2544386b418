import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const repoDir = path.resolve(packageDir, '..', '..');
export const venvPython = path.join(packageDir, '.venv', 'bin', 'python');
export const ruffConfig = path.join(packageDir, 'ruff.toml');

/** Creates the package's venv (pytest, ruff) when needed; idempotent and fast when up to date. */
export function ensureVenv(): void {
    const r = spawnSync('bash', [path.join(packageDir, 'scripts', 'setup_venv.sh')], { encoding: 'utf8' });
    if (r.status !== 0 || !existsSync(venvPython)) throw new Error(`setup_venv.sh failed:\n${r.stdout}\n${r.stderr}`);
}

export function run(command: string, args: string[], cwd: string, input?: string): { status: number; stdout: string; stderr: string } {
    const r = spawnSync(command, args, { cwd, encoding: 'utf8', input, env: { ...process.env, PYTHONDONTWRITEBYTECODE: '1' }, maxBuffer: 64 * 1024 * 1024 });
    return { status: r.status ?? 1, stdout: r.stdout ?? '', stderr: `${r.stderr ?? ''}${r.error ? String(r.error) : ''}` };
}

/** Every .py file below a folder. */
export function pythonFiles(dir: string): string[] {
    const out: string[] = [];
    const visit = (d: string): void => {
        for (const e of readdirSync(d, { withFileTypes: true })) {
            if (e.name === '__pycache__') continue;
            const full = path.join(d, e.name);
            if (e.isDirectory()) visit(full);
            else if (e.name.endsWith('.py')) out.push(full);
        }
    };
    visit(dir);
    return out.sort();
}

/** `ruff check` (inside the folder, with the package's settings) and `py_compile` of every file. */
export function lintPython(dir: string): string[] {
    const problems: string[] = [];
    const ruff = run(venvPython, ['-m', 'ruff', 'check', '--config', ruffConfig, '--no-cache', '--output-format', 'concise', '.'], dir);
    if (ruff.status !== 0) problems.push(`ruff check in ${dir}:\n${ruff.stdout}${ruff.stderr}`);
    const files = pythonFiles(dir);
    // Compiled into a temporary folder, so the generated folder stays free of __pycache__.
    const compile = run(venvPython, ['-c', [
        'import os, sys, py_compile, tempfile',
        'with tempfile.TemporaryDirectory() as d:',
        '    for i, f in enumerate(sys.argv[1:]):',
        '        py_compile.compile(f, cfile=os.path.join(d, f"{i}.pyc"), doraise=True)'
    ].join('\n'), ...files], dir);
    if (compile.status !== 0) problems.push(`py_compile in ${dir}:\n${compile.stderr}`);
    return problems;
}
