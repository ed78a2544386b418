import { execFile } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const BIN = fileURLToPath(new URL('../bin/maa-gen.js', import.meta.url));
const BUILT_MAIN = fileURLToPath(new URL('../dist/main.js', import.meta.url));

export interface CliResult {
    code: number | null;
    stdout: string;
    stderr: string;
}

/** Fails early with a clear message when the CLI has not been built (`npm run build`). */
export function requireBuiltCli(): void {
    if (!existsSync(BUILT_MAIN)) {
        throw new Error(`${BUILT_MAIN} is missing: run "npm run build" at the repository root first`);
    }
}

/** Runs the built `maa-gen` as a child process (stdout/stderr are pipes, so not TTYs). */
export function runCli(args: string[], cwd: string): Promise<CliResult> {
    return new Promise((resolve, reject) => {
        execFile(
            process.execPath,
            [BIN, ...args],
            { cwd, env: { ...process.env, NO_COLOR: '1' }, maxBuffer: 64 * 1024 * 1024 },
            (error, stdout, stderr) => {
                if (error && typeof error.code !== 'number') {
                    reject(error);
                    return;
                }
                resolve({ code: error ? (error.code as number) : 0, stdout, stderr });
            },
        );
    });
}

/** A temporary folder with model files; `write` creates parent folders as needed. */
export class ModelDir {
    readonly dir: string;

    constructor() {
        this.dir = mkdtempSync(path.join(tmpdir(), 'maa-cli-test-'));
    }

    write(relative: string, content: string | Buffer): string {
        const file = path.join(this.dir, relative);
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, content);
        return file;
    }

    path(relative = ''): string {
        return path.join(this.dir, relative);
    }

    dispose(): void {
        rmSync(this.dir, { recursive: true, force: true });
    }
}

/** A line of the text format: `file:line:col: severity code message`. */
export const TEXT_LINE =
    /^(?<file>[^:]+):(?<line>\d+):(?<column>\d+): (?<severity>error|warning|info|hint) (?<code>[a-z]+\/[a-z0-9-]+) (?<message>.+)$/;

export function parseTextLines(stdout: string): Array<Record<string, string>> {
    return stdout
        .split('\n')
        .filter((l) => l.length > 0)
        .map((l) => {
            const m = TEXT_LINE.exec(l);
            if (!m?.groups) throw new Error(`not a diagnostic line: ${JSON.stringify(l)}`);
            return { ...m.groups };
        });
}
