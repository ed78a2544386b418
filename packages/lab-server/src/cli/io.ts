// What a maa-lab command talks to: injectable, so the commands run in-process in tests.
import path from 'node:path';
import { type LabStore, openLabStore, storageFromEnvironment } from '../storage/index.js';

export interface LabIo {
    readonly cwd: string;
    readonly env: NodeJS.ProcessEnv;
    out(text: string): void;
    err(text: string): void;
    /** Reads a secret (a password) from standard input: the first line, never echoed or logged. */
    readSecret(prompt: string): Promise<string>;
}

/** A user-facing failure: printed as `maa-lab: error: ...`, exit code 1. */
export class LabCliError extends Error {}

/** The --data-dir every command that opens the store has (DATABASE_URL wins when set). */
export const DATA_DIR_HELP = 'the embedded database folder (default ./lab-data; ignored when DATABASE_URL is set)';
export const DEFAULT_DATA_DIR = 'lab-data';

/** Opens the store a command works on, runs `work`, and closes it. */
export async function withStore<T>(io: LabIo, dataDir: string | undefined, work: (store: LabStore) => Promise<T>): Promise<T> {
    const store = await openLabStore(storageFromEnvironment(io.env, path.resolve(io.cwd, dataDir ?? DEFAULT_DATA_DIR)));
    try {
        return await work(store);
    } finally {
        await store.close();
    }
}

export function processLabIo(): LabIo {
    return {
        cwd: process.cwd(),
        env: process.env,
        out: (text) => void process.stdout.write(text),
        err: (text) => void process.stderr.write(text),
        readSecret: (prompt) => readSecretFromStdin(prompt),
    };
}

/** The first line of stdin; on a terminal with echo off (raw mode), so the password is not shown. */
async function readSecretFromStdin(prompt: string): Promise<string> {
    const stdin = process.stdin;
    if (stdin.isTTY) {
        process.stderr.write(prompt);
        stdin.setRawMode(true);
    }
    const chunks: Buffer[] = [];
    try {
        for await (const chunk of stdin) {
            const buffer = chunk as Buffer;
            if (stdin.isTTY && buffer.includes(3)) throw new LabCliError('cancelled');
            chunks.push(buffer);
            const text = Buffer.concat(chunks).toString('utf8');
            if (/[\r\n]/.test(text)) break;
        }
    } finally {
        if (stdin.isTTY) {
            stdin.setRawMode(false);
            process.stderr.write('\n');
        }
        stdin.pause();
    }
    return (
        Buffer.concat(chunks)
            .toString('utf8')
            .split(/\r?\n|\r/)[0] ?? ''
    ).replace(/\u007f/g, '');
}
