// Students' workspaces over HTTP (docs/lab.md "Workspaces"): the IDE backend's API per workspace
// below `/api/ws/<course>/<exercise>/<owner>`, files in the database, generation, stream tests
// and simulation on a materialized folder, within the quotas (docs/lab.md "Quotas").
import { mkdirSync, mkdtempSync } from 'node:fs';
import { rm } from 'node:fs/promises';
import type { IncomingMessage } from 'node:http';
import { tmpdir } from 'node:os';
import path from 'node:path';
import type { Duplex } from 'node:stream';
import type { Worker } from 'node:worker_threads';
import { defaults } from '@maa/ide-server';
import type { SessionService } from '../auth/sessions.js';
import type { LabRoutes } from '../http/routes.js';
import { type QuotaOptions, quotaOptions } from '../quotas/index.js';
import type { LabStore } from '../storage/index.js';
import { addFileRoutes } from './file-routes.js';
import { GeneratePool } from './generate-pool.js';
import { addInfoRoute } from './info-route.js';
import { RuntimePool } from './pool.js';
import { addProxyRoutes, WorkspaceUpgrades } from './proxy.js';
import { addResetRoute } from './reset.js';
import { addRunRoutes } from './run-routes.js';
import { LabSimulations } from './simulations.js';

export { entriesOf } from './file-routes.js';
export { finishedLine } from './simulations.js';
export { type OpenedWorkspace, WS_PREFIX, workspacePrefix } from './resolve.js';

export interface LabWorkspaceOptions {
    /** the lab's data directory: workspaces are materialized in its `workspaces/` (default: a folder in the temp directory) */
    dataDir?: string;
    quotas?: Partial<QuotaOptions>;
    /** the maa-sim executable (default: maa-ide's) */
    maaSim?: string;
    /** the venv ROS 2 simulations run in (default: maa-ide's) */
    ros2Venv?: string;
    /** a simulation ends when its student's last connection has been gone this long (default 60 s) */
    simIdleSeconds?: number;
    simReadyTimeoutMs?: number;
    simStopGraceMs?: number;
    /** a workspace nobody used this long loses its folder (default 10 min) */
    workspaceIdleSeconds?: number;
    /** how often simulations are checked against their student's session and time quota (default 2 s) */
    sweepMs?: number;
    /** how many worker threads run generators (default: the cores but one, at least 1, at most 4) */
    generateThreads?: number;
    /** starts one generator thread (default: generate-worker.js; tests give their own) */
    generateThread?: () => Worker;
}

export const WORKSPACE_DEFAULTS = { simIdleSeconds: 60, workspaceIdleSeconds: 600, sweepMs: 2000 };

export interface LabWorkspacesDeps {
    routes: LabRoutes;
    store: LabStore;
    sessions: SessionService;
    originRefusal(req: IncomingMessage): string | undefined;
    log: (line: string) => void;
}

/** The workspaces part of a running lab server: its routes, its upgrade handler, its stop. */
export class LabWorkspaces {
    readonly quotas: QuotaOptions;
    readonly pool: RuntimePool;
    readonly simulations: LabSimulations;
    /** the generator threads every workspace's generation runs in */
    readonly generators: GeneratePool;
    private readonly upgrades: WorkspaceUpgrades;
    private readonly timer: NodeJS.Timeout;
    private closing: Promise<void> | undefined;
    /** the folder made for the workspaces when no data directory was given (removed at the stop) */
    private readonly temporary: string | undefined;
    /** the lab's data directory (or the temporary folder standing for it) */
    readonly dataDir: string;

    constructor(deps: LabWorkspacesDeps, options: LabWorkspaceOptions = {}) {
        this.quotas = quotaOptions(options.quotas);
        const base = options.dataDir ?? mkdtempSync(path.join(tmpdir(), 'maa-lab-'));
        if (options.dataDir === undefined) this.temporary = base;
        this.dataDir = path.resolve(base);
        const root = path.resolve(base, 'workspaces');
        mkdirSync(root, { recursive: true, mode: 0o700 });
        this.generators = new GeneratePool(options.generateThreads, options.generateThread);
        this.pool = new RuntimePool(
            deps.store,
            {
                root,
                maaSim: path.resolve(options.maaSim ?? defaults.maaSim),
                ros2Venv: options.ros2Venv,
                simIdleMs: (options.simIdleSeconds ?? WORKSPACE_DEFAULTS.simIdleSeconds) * 1000,
                simReadyTimeoutMs: options.simReadyTimeoutMs,
                simStopGraceMs: options.simStopGraceMs,
                generate: this.generators.run,
            },
            (options.workspaceIdleSeconds ?? WORKSPACE_DEFAULTS.workspaceIdleSeconds) * 1000,
        );
        this.simulations = new LabSimulations(deps.store, deps.sessions, this.pool, this.quotas, deps.log);
        this.upgrades = new WorkspaceUpgrades(this.pool, deps);
        addInfoRoute(deps.routes);
        addFileRoutes(deps.routes, this.pool, this.quotas);
        addRunRoutes(deps.routes, this.pool, this.simulations);
        addProxyRoutes(deps.routes, this.pool);
        addResetRoute(deps.routes, this.pool, this.simulations);
        this.timer = setInterval(() => void this.sweep(), options.sweepMs ?? WORKSPACE_DEFAULTS.sweepMs);
        this.timer.unref();
    }

    /** The server's `upgrade` listener: a workspace's simulation endpoint, else 404. */
    upgrade(req: IncomingMessage, socket: Duplex, head: Buffer): void {
        void this.upgrades.handle(req, socket, head);
    }

    /** Ends simulations whose student left or ran out of time, records ended ones, frees idle folders. */
    async sweep(): Promise<void> {
        if (this.closing) return;
        await this.simulations.sweep().catch(() => undefined);
        await this.pool.removeIdle().catch(() => undefined);
    }

    /** Stops every simulation (recording it), ends the proxied sockets, removes the folders. */
    close(): Promise<void> {
        this.closing ??= (async () => {
            clearInterval(this.timer);
            await this.simulations.stopAll();
            this.upgrades.closeAll();
            await this.pool.closeAll();
            await this.generators.close();
            if (this.temporary) await rm(this.temporary, { recursive: true, force: true });
        })();
        return this.closing;
    }
}
