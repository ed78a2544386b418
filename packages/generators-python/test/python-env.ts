import { spawn } from 'node:child_process';
import { existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const packageDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const repoDir = path.resolve(packageDir, '..', '..');
export const venvPython = path.join(packageDir, '.venv', 'bin', 'python');
export const ruffConfig = path.join(packageDir, 'ruff.toml');

/** Creates the package's venv (pytest, ruff) when needed; idempotent and fast when up to date. */
export async function ensureVenv(): Promise<void> {
    const r = await run('bash', [path.join(packageDir, 'scripts', 'setup_venv.sh')], packageDir);
    if (r.status !== 0 || !existsSync(venvPython)) throw new Error(`setup_venv.sh failed:\n${r.stdout}\n${r.stderr}`);
}

export interface RunResult {
    status: number;
    stdout: string;
    stderr: string;
}

/**
 * Runs a command to its end. Asynchronous on purpose: a Vitest worker blocked in spawnSync for
 * over a minute (the montiarc-io cases, a simulation on a loaded machine) cannot answer Vitest's
 * own RPC, which then fails the run with `[vitest-worker]: Timeout calling "onTaskUpdate"`.
 */
export function run(command: string, args: string[], cwd: string, input?: string): Promise<RunResult> {
    return new Promise((resolve) => {
        const child = spawn(command, args, { cwd, env: { ...process.env, PYTHONDONTWRITEBYTECODE: '1' }, stdio: ['pipe', 'pipe', 'pipe'] });
        const stdout: Buffer[] = [];
        const stderr: Buffer[] = [];
        let spawnError = '';
        child.stdout.on('data', (chunk: Buffer) => stdout.push(chunk));
        child.stderr.on('data', (chunk: Buffer) => stderr.push(chunk));
        child.on('error', (e) => {
            spawnError = String(e);
        });
        child.on('close', (code, signal) => {
            const tail = signal ? `\n(killed by ${signal})` : '';
            resolve({
                status: code ?? 1,
                stdout: Buffer.concat(stdout).toString('utf8'),
                stderr: `${Buffer.concat(stderr).toString('utf8')}${spawnError}${tail}`,
            });
        });
        child.stdin.on('error', () => undefined); // a command that exits without reading its input
        child.stdin.end(input);
    });
}

/** Every file below a folder whose name ends with `suffix` (not in __pycache__), sorted. */
export function filesUnder(dir: string, suffix = ''): string[] {
    const out: string[] = [];
    const visit = (d: string): void => {
        for (const e of readdirSync(d, { withFileTypes: true })) {
            if (e.name === '__pycache__') continue;
            const full = path.join(d, e.name);
            if (e.isDirectory()) visit(full);
            else if (e.name.endsWith(suffix)) out.push(full);
        }
    };
    visit(dir);
    return out.sort();
}

/** Every .py file below a folder. */
export function pythonFiles(dir: string): string[] {
    return filesUnder(dir, '.py');
}

/** `ruff check` (inside the folder, with the package's settings) and `py_compile` of every file. */
export async function lintPython(dir: string): Promise<string[]> {
    const problems: string[] = [];
    const ruff = await run(
        venvPython,
        ['-m', 'ruff', 'check', '--config', ruffConfig, '--no-cache', '--output-format', 'concise', '.'],
        dir,
    );
    if (ruff.status !== 0) problems.push(`ruff check in ${dir}:\n${ruff.stdout}${ruff.stderr}`);
    const files = pythonFiles(dir);
    // Compiled into a temporary folder, so the generated folder stays free of __pycache__.
    const compile = await run(
        venvPython,
        [
            '-c',
            [
                'import os, sys, py_compile, tempfile',
                'with tempfile.TemporaryDirectory() as d:',
                '    for i, f in enumerate(sys.argv[1:]):',
                '        py_compile.compile(f, cfile=os.path.join(d, f"{i}.pyc"), doraise=True)',
            ].join('\n'),
            ...files,
        ],
        dir,
    );
    if (compile.status !== 0) problems.push(`py_compile in ${dir}:\n${compile.stderr}`);
    return problems;
}
