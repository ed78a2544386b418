/**
 * The IDE backend (`maa-ide`, @maa/ide-server) the extension's simulate view talks to on the
 * desktop: started on loopback with a random token for one workspace folder, reused by every
 * later run in that folder, stopped on deactivate. It runs under backend-launcher (one process,
 * stopped when the extension host's pipe closes). Node only: no `vscode`, so the tests drive it
 * with the real backend.
 */
import { type ChildProcess, spawn } from 'node:child_process';
import { randomBytes } from 'node:crypto';

/** How maa-ide is run. */
export interface BackendCommand {
    /** The Node executable that runs the launcher (maa-ide needs Node 20.10 or newer). */
    node: string;
    /** maa-ide's bin script (`@maa/ide-server/bin/maa-ide.js`). */
    bin: string;
    /** Extra maa-ide options (tests: a short `--session-idle`). */
    extraArgs?: readonly string[];
}

/** A running backend: where it listens and the token its requests carry. */
export interface RunningBackend {
    readonly workspace: string;
    readonly port: number;
    readonly token: string;
    readonly pid: number;
}

/** The port of maa-ide's `serving … at http://127.0.0.1:<port>/?token=…` line, undefined for other lines. Pure. */
export function servingPort(line: string): number | undefined {
    const m = /^maa-ide: serving .* at http:\/\/(?:127\.0\.0\.1|localhost|\[::1\]):(\d+)\//.exec(line);
    return m?.[1] ? Number(m[1]) : undefined;
}

/** The arguments of the launcher: maa-ide on loopback, any free port, for one folder. Pure. */
export function backendArgs(launcher: string, bin: string, workspace: string, extra: readonly string[] = []): string[] {
    return [launcher, bin, '--workspace', workspace, '--host', '127.0.0.1', '--port', '0', ...extra];
}

/** One backend at a time: `ensure(folder, command)` reuses the running one of that folder and command, or replaces it. */
export class IdeBackend {
    private child: ChildProcess | undefined;
    private current: Promise<RunningBackend> | undefined;
    private currentKey: string | undefined;
    private queue: Promise<unknown> = Promise.resolve();

    /**
     * @param launcher backend-launcher.mjs (out/simulate/ in the extension)
     * @param log receives the lines maa-ide prints (the output channel)
     */
    constructor(
        private readonly launcher: string,
        private readonly log?: (line: string) => void,
    ) {}

    /**
     * The backend of `workspace`, started when none runs for it (a backend of another folder or
     * command is stopped first). Calls take turns, so two at once never start two backends.
     */
    ensure(workspace: string, command: BackendCommand): Promise<RunningBackend> {
        const turn = this.queue.then(() => this.ensureNow(workspace, command));
        this.queue = turn.catch(() => undefined);
        return turn;
    }

    private async ensureNow(workspace: string, command: BackendCommand): Promise<RunningBackend> {
        const key = JSON.stringify([workspace, command.node, command.bin, command.extraArgs ?? []]);
        if (this.current && this.currentKey === key && this.alive()) return this.current;
        await this.stop();
        this.currentKey = key;
        const started = this.start(workspace, command);
        this.current = started;
        started.catch(() => {
            if (this.current !== started) return;
            this.current = undefined;
            this.currentKey = undefined;
        });
        return started;
    }

    private alive(): boolean {
        return this.child !== undefined && this.child.exitCode === null && this.child.signalCode === null;
    }

    /** The process id of the running backend (tests). */
    get pid(): number | undefined {
        return this.alive() ? this.child?.pid : undefined;
    }

    /** Stops the backend (SIGTERM: maa-ide stops its simulation first; SIGKILL after `graceMs`). */
    async stop(graceMs = 15_000): Promise<void> {
        const child = this.child;
        this.child = undefined;
        this.current = undefined;
        this.currentKey = undefined;
        if (!child || child.exitCode !== null || child.signalCode !== null) return;
        const exited = new Promise<void>((resolve) => child.once('exit', () => resolve()));
        child.kill('SIGTERM');
        const timer = setTimeout(() => child.kill('SIGKILL'), graceMs);
        await exited;
        clearTimeout(timer);
    }

    private start(workspace: string, { node, bin, extraArgs }: BackendCommand): Promise<RunningBackend> {
        const { launcher, log } = this;
        const token = randomBytes(32).toString('base64url');
        // The token goes by environment, not argv (other users' `ps` shows argv).
        const child = spawn(node, backendArgs(launcher, bin, workspace, extraArgs), {
            stdio: ['pipe', 'pipe', 'pipe'],
            env: { ...process.env, MAA_IDE_TOKEN: token, ELECTRON_RUN_AS_NODE: '1' },
            windowsHide: true,
        });
        this.child = child;
        return new Promise<RunningBackend>((resolve, reject) => {
            const output: string[] = [];
            const onLine = (line: string): void => {
                log?.(line);
                output.push(line);
                if (output.length > 40) output.shift();
                const port = servingPort(line);
                if (port !== undefined && child.pid !== undefined) resolve({ workspace, port, token, pid: child.pid });
            };
            lines(child.stdout, onLine);
            lines(child.stderr, onLine);
            child.once('error', (e) => reject(new Error(`could not start maa-ide (${node}): ${e.message}`)));
            child.once('exit', (code, signal) => {
                if (this.child === child) this.child = undefined;
                reject(new Error(`maa-ide exited (${signal ?? `code ${code}`}) before it served: ${output.slice(-5).join(' | ')}`));
            });
        });
    }
}

/** Calls `onLine` for every line of a stream. */
function lines(stream: NodeJS.ReadableStream | null, onLine: (line: string) => void): void {
    if (!stream) return;
    let rest = '';
    stream.setEncoding('utf8');
    stream.on('data', (chunk: string) => {
        rest += chunk;
        let nl = rest.indexOf('\n');
        while (nl >= 0) {
            onLine(rest.slice(0, nl).replace(/\r$/, ''));
            rest = rest.slice(nl + 1);
            nl = rest.indexOf('\n');
        }
    });
}
