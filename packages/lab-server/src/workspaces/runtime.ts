// What one workspace needs on disk while it is in use: its materialized folder and, on it, the
// IDE backend's own services (generation, stream tests, one simulation session with its proxy),
// imported from @maa/ide-server so that answers are the same as maa-ide's.
import { realpathSync } from 'node:fs';
import path from 'node:path';
import {
    createApiRouter,
    type GenerateRunner,
    GenerationService,
    PathRedactor,
    packageDir,
    ros2Environment,
    type Router,
    SimProxy,
    SimSessions,
    StreamTestService,
    Workspace,
} from '@maa/ide-server';
import type { LabStore } from '../storage/index.js';
import { MaterializedFolder } from './materialize.js';
import { releaseRosDomain, sandboxPython, simSandbox } from './sim-sandbox.js';

/** A largest accepted file body of the IDE router (files are saved by the lab's own routes). */
const ROUTER_FILE_LIMIT = 1;

export interface RuntimeSettings {
    /** the folder every workspace's folder lies in */
    root: string;
    maaSim: string;
    ros2Venv: string | undefined;
    /** a simulation ends when it had no client for this long */
    simIdleMs: number;
    simReadyTimeoutMs: number | undefined;
    simStopGraceMs: number | undefined;
    /** runs the generator (the lab's generator threads, generate-pool.ts) */
    generate: GenerateRunner;
}

/** A simulation one student started in this workspace (until the sweep records its end). */
export interface RunningSim {
    userId: number;
    /** the login session that started it (its end ends the simulation) */
    sessionId: string;
    startedAt: number;
    /** simulated seconds per wall second (1 when the start named none) */
    speed: number;
}

export class WorkspaceRuntime {
    readonly folder: MaterializedFolder;
    readonly ide: Workspace;
    readonly generation: GenerationService;
    readonly tests: StreamTestService;
    readonly sims: SimSessions;
    readonly proxy: SimProxy;
    readonly redact: PathRedactor;
    /** the IDE backend's router on this workspace (generation, generated files, simulation) */
    readonly router: Router;
    sim: RunningSim | undefined;
    lastUsed = Date.now();
    /** requests in progress (the folder is not removed under them) */
    busy = 0;

    constructor(
        readonly workspaceId: number,
        exerciseName: string,
        store: LabStore,
        settings: RuntimeSettings,
    ) {
        const base = path.join(settings.root, String(workspaceId));
        this.folder = new MaterializedFolder(path.join(base, exerciseName), store, workspaceId);
        this.ide = new Workspace(this.folder.root);
        const outDir = path.join(base, 'generated');
        this.generation = new GenerationService(this.ide, outDir, [packageDir], settings.generate);
        this.tests = new StreamTestService(this.ide, this.generation);
        this.sims = new SimSessions(
            settings.maaSim,
            {
                idleMs: settings.simIdleMs,
                readyTimeoutMs: settings.simReadyTimeoutMs,
                stopGraceMs: settings.simStopGraceMs,
                // maa-sim and the student's components run sandboxed (sim-sandbox.ts)
                wrap: simSandbox({
                    python: sandboxPython(settings.maaSim),
                    workspaceId,
                    generated: outDir,
                    runDir: path.join(base, 'sim'),
                }),
            },
            ros2Environment(settings.ros2Venv),
        );
        this.proxy = new SimProxy(this.sims);
        this.redact = new PathRedactor([
            [this.folder.root, ''],
            [realRoot(settings.root, this.folder.root), ''],
            [outDir, '<generated>'],
            [settings.maaSim, 'maa-sim'],
            [path.resolve(packageDir, '..', '..'), ''],
        ]);
        this.router = createApiRouter({
            workspace: this.ide,
            generation: this.generation,
            sims: this.sims,
            maxFileBytes: ROUTER_FILE_LIMIT,
            redact: this.redact,
        });
    }

    /** Runs `body` with the workspace marked in use. */
    async use<T>(body: () => Promise<T>): Promise<T> {
        this.busy++;
        this.lastUsed = Date.now();
        try {
            return await body();
        } finally {
            this.busy--;
            this.lastUsed = Date.now();
        }
    }

    /** Stops its simulation (if any) and removes its folder. */
    async dispose(): Promise<void> {
        await this.sims.stop().catch(() => undefined);
        this.sims.dispose();
        releaseRosDomain(this.workspaceId);
        this.proxy.close();
        await this.folder.remove();
    }
}

/** The folder as the file system resolves it (a symlinked temp folder), for redaction. */
function realRoot(root: string, folder: string): string {
    try {
        return path.join(realpathSync(root), path.relative(root, folder));
    } catch {
        return folder;
    }
}
