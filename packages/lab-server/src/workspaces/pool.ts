// The workspaces in use: one runtime (folder and services) each, created on first use and
// disposed of (simulation stopped, folder removed) when idle, or all of them when the server stops.
import type { LabStore } from '../storage/index.js';
import type { OpenedWorkspace } from './resolve.js';
import { type RuntimeSettings, WorkspaceRuntime } from './runtime.js';

export class RuntimePool {
    private readonly runtimes = new Map<number, WorkspaceRuntime>();

    constructor(
        private readonly store: LabStore,
        private readonly settings: RuntimeSettings,
        /** how long a workspace without requests or simulation keeps its folder */
        private readonly idleMs: number,
    ) {}

    /** The workspace's runtime, created on first use. */
    get(opened: OpenedWorkspace): WorkspaceRuntime {
        let runtime = this.runtimes.get(opened.workspace.id);
        if (!runtime) {
            runtime = new WorkspaceRuntime(opened.workspace.id, opened.exercise.name, this.store, this.settings);
            this.runtimes.set(opened.workspace.id, runtime);
        }
        runtime.lastUsed = Date.now();
        return runtime;
    }

    /** The runtime of a workspace if it is in use. */
    find(workspaceId: number): WorkspaceRuntime | undefined {
        return this.runtimes.get(workspaceId);
    }

    all(): WorkspaceRuntime[] {
        return [...this.runtimes.values()];
    }

    /** Disposes of the runtimes idle for longer than the idle time (no request, no simulation). */
    async removeIdle(now = Date.now()): Promise<void> {
        for (const runtime of this.all()) {
            if (runtime.busy > 0 || runtime.sim || runtime.sims.status().preparing) continue;
            if (runtime.sims.processGroup() !== undefined || now - runtime.lastUsed < this.idleMs) continue;
            this.runtimes.delete(runtime.workspaceId);
            await runtime.dispose();
        }
    }

    /** Disposes of every runtime (the server stops). */
    async closeAll(): Promise<void> {
        const all = this.all();
        this.runtimes.clear();
        await Promise.all(all.map((r) => r.dispose()));
    }
}
