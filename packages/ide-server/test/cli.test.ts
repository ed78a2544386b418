import { spawn, type ChildProcess } from 'node:child_process';
import { chmodSync, cpSync, existsSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { createServer, type Server } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { processAlive } from '../src/process-group.js';
import { repo, TEST_TOKEN, until } from './basics.js';

// The built `maa-ide` bin as a user starts it (`npm test` builds first): the URL it prints, the
// token options, the umask of what it writes, and its simulations ending with it.
const BIN = path.join(repo, 'packages', 'ide-server', 'bin', 'maa-ide.js');
const built = existsSync(path.join(repo, 'packages', 'ide-server', 'dist', 'cli.js'));

interface Running {
    child: ChildProcess;
    url: string;
    output: string[];
    exited: Promise<{ code: number | null; signal: NodeJS.Signals | null }>;
}

/** Starts the bin (through bash when `umask` is given) and waits for the URL it prints. */
function startBin(
    args: string[],
    { env = {}, umask }: { env?: Record<string, string | undefined>; umask?: string } = {},
): Promise<Running> {
    const command = umask ? 'bash' : process.execPath;
    const argv = umask ? ['-c', `umask ${umask} && exec "$0" "$@"`, process.execPath, BIN, ...args] : [BIN, ...args];
    const fullEnv: NodeJS.ProcessEnv = { ...process.env, ...env };
    if (env['MAA_IDE_TOKEN'] === undefined) delete fullEnv['MAA_IDE_TOKEN'];
    const child = spawn(command, argv, { cwd: repo, env: fullEnv, stdio: ['ignore', 'pipe', 'pipe'] });
    const output: string[] = [];
    const exited = new Promise<{ code: number | null; signal: NodeJS.Signals | null }>((resolve) =>
        child.once('exit', (code, signal) => resolve({ code, signal })),
    );
    return new Promise((resolve, reject) => {
        const onData = (chunk: Buffer) => {
            output.push(chunk.toString());
            const match = /serving .* at (http:\/\/\S+)/.exec(output.join(''));
            if (match) resolve({ child, url: match[1]!, output, exited });
        };
        child.stdout!.on('data', onData);
        child.stderr!.on('data', onData);
        void exited.then(({ code }) => reject(new Error(`maa-ide exited (${code}) before printing its URL:\n${output.join('')}`)));
    });
}

async function stopBin(running: Running): Promise<void> {
    if (running.child.exitCode === null && running.child.signalCode === null) running.child.kill('SIGKILL');
    await running.exited;
}

describe.skipIf(!built)('the maa-ide bin', () => {
    let dir: string;
    let workspace: string;
    /** Accepts TCP connections: the stand-in's "rosbridge port". */
    let listener: Server;
    let port: number;

    beforeAll(async () => {
        dir = mkdtempSync(path.join(tmpdir(), 'maa-ide-cli-'));
        workspace = path.join(dir, 'ws');
        cpSync(path.join(repo, 'examples'), workspace, { recursive: true });
        listener = createServer((socket) => socket.destroy());
        await new Promise<void>((resolve) => listener.listen(0, '127.0.0.1', resolve));
        port = (listener.address() as { port: number }).port;
    });
    afterAll(async () => {
        await new Promise<void>((resolve) => listener.close(() => resolve()));
        rmSync(dir, { recursive: true, force: true });
    });

    const base = ['--workspace', '', '--port', '0', '--app-dir', ''];
    const args = (...more: string[]) => [...base.map((a, i) => (i === 1 ? workspace : i === 5 ? path.join(dir, 'no-app') : a)), ...more];

    it('prints http://127.0.0.1:<port>/?token=<t> with a new random token per start', async () => {
        const tokens: string[] = [];
        for (let i = 0; i < 2; i++) {
            const running = await startBin(args());
            try {
                const url = new URL(running.url);
                expect(url.hostname).toBe('127.0.0.1');
                expect(url.pathname).toBe('/');
                const token = url.searchParams.get('token')!;
                expect(token).toMatch(/^[A-Za-z0-9_-]{43}$/);
                tokens.push(token);
                expect((await fetch(new URL('/api/files', url))).status).toBe(401);
                expect((await fetch(new URL('/api/files', url), { headers: { Authorization: `Bearer ${token}` } })).status).toBe(200);
            } finally {
                await stopBin(running);
            }
        }
        expect(tokens[0]).not.toBe(tokens[1]);
    });

    it('takes the token from MAA_IDE_TOKEN or --token, and refuses a weak one (exit 2)', async () => {
        for (const [extra, env] of [
            [[], { MAA_IDE_TOKEN: TEST_TOKEN }],
            [['--token', TEST_TOKEN], {}],
        ] as const) {
            const running = await startBin(args(...extra), { env });
            try {
                expect(new URL(running.url).searchParams.get('token')).toBe(TEST_TOKEN);
            } finally {
                await stopBin(running);
            }
        }
        for (const [extra, env] of [
            [['--token', 'weak'], {}],
            [[], { MAA_IDE_TOKEN: 'weak' }],
            [['--session-idle', '0'], {}],
        ] as const) {
            const running = startBin(args(...extra), { env });
            await expect(running).rejects.toThrow(/exited \(2\)/);
            await expect(running).rejects.toThrow(/at least 16 characters|positive number of seconds/);
        }
    });

    it.each([
        ['000', 0o664, 0o775],
        ['022', 0o644, 0o755],
        ['077', 0o600, 0o700],
    ])('with umask %s writes files %o and folders %o (never writable by others)', async (umask, fileMode, folderMode) => {
        const running = await startBin(args(), { env: { MAA_IDE_TOKEN: TEST_TOKEN }, umask });
        try {
            const rel = `umask-${umask}/sub/New.arc`;
            const res = await fetch(new URL(`/api/file?path=${encodeURIComponent(rel)}`, running.url), {
                method: 'PUT',
                body: 'component N {}\n',
                headers: { Authorization: `Bearer ${TEST_TOKEN}` },
            });
            expect(res.status).toBe(200);
            expect(statSync(path.join(workspace, rel)).mode & 0o777).toBe(fileMode);
            expect(statSync(path.join(workspace, `umask-${umask}`)).mode & 0o777).toBe(folderMode);
            expect(statSync(path.join(workspace, `umask-${umask}/sub`)).mode & 0o777).toBe(folderMode);
        } finally {
            await stopBin(running);
        }
    });

    /** A stand-in maa-sim: writes "<its pid> <its child's pid>" and prints a ready line. */
    function fakeSim(name: string, prelude: string): string {
        const file = path.join(dir, name);
        writeFileSync(
            file,
            `#!/bin/bash\n${prelude}\nsleep 300 &\necho "$$ $!" > "${dir}/${name}.pids"\necho '{"event": "ready", "rosbridge": "ws://127.0.0.1:${port}", "viser": null}'\nwait\n`,
        );
        chmodSync(file, 0o755);
        return file;
    }

    async function startSession(running: Running, pidsFile: string): Promise<number[]> {
        rmSync(pidsFile, { force: true });
        const res = await fetch(new URL('/api/sim/start', running.url), {
            method: 'POST',
            body: JSON.stringify({ app: 'toast-service/TR.arcapp', platform: 'timesync', mode: 'lockstep' }),
            headers: { Authorization: `Bearer ${TEST_TOKEN}` },
        });
        const body = await res.text();
        expect(res.status, body).toBe(200);
        await until(() => existsSync(pidsFile) && readFileSync(pidsFile, 'utf8').endsWith('\n'), 'the stand-in wrote its pids');
        return readFileSync(pidsFile, 'utf8').trim().split(' ').map(Number);
    }

    it('stops the simulation with its whole group on SIGTERM (exit 0)', async () => {
        const sim = fakeSim('polite-sim', '');
        const running = await startBin(args('--maa-sim', sim), { env: { MAA_IDE_TOKEN: TEST_TOKEN } });
        try {
            const pids = await startSession(running, path.join(dir, 'polite-sim.pids'));
            running.child.kill('SIGTERM');
            expect((await running.exited).code).toBe(0);
            await until(() => pids.every((p) => !processAlive(p)), 'maa-sim and its child are gone');
        } finally {
            await stopBin(running);
        }
    });

    it('kills a simulation that ignores SIGTERM when a second Ctrl-C makes maa-ide exit at once', async () => {
        // `trap '' TERM` is inherited by the background sleep: neither stops on SIGTERM.
        const sim = fakeSim('stubborn-sim', "trap '' TERM");
        const running = await startBin(args('--maa-sim', sim), { env: { MAA_IDE_TOKEN: TEST_TOKEN } });
        try {
            const pids = await startSession(running, path.join(dir, 'stubborn-sim.pids'));
            running.child.kill('SIGINT');
            await until(() => running.output.join('').includes('shutting down'), 'maa-ide reports the shutdown');
            running.child.kill('SIGINT');
            expect((await running.exited).code).toBe(130);
            // The exit handler sent SIGKILL synchronously; the processes disappear once reaped.
            await until(() => pids.every((p) => !processAlive(p)), 'maa-sim and its child are gone');
        } finally {
            await stopBin(running);
        }
    });
});
