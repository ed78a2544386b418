// The simulations students run (docs/lab.md "Quotas", "Workspaces"): a start takes a slot of the
// student's concurrent-simulation quota and needs simulated time left this hour; a sweep every
// few seconds ends the simulations whose student left (logged out, session expired), that used
// up the hour's simulated time, or that ended by themselves (the idle grace time of the IDE's
// session, a crash), and records each one's result (goal reached, simulated seconds) in LabStore.
import type { SimStartAnswer, SimStartRequest } from '@maa/protocol';
import { ROSBRIDGE_PATH, startSimulation, VISER_PATH } from '@maa/ide-server';
import type { Authenticated, SessionService } from '../auth/sessions.js';
import { SimulatedTimeLedger, SimulationSlots } from '../quotas/index.js';
import type { QuotaOptions } from '../quotas/index.js';
import type { LabStore } from '../storage/index.js';
import type { RuntimePool } from './pool.js';
import type { OpenedWorkspace } from './resolve.js';
import type { RunningSim, WorkspaceRuntime } from './runtime.js';

/** maa-sim's last line (`--status-json`): how the run ended. */
interface FinishedLine {
    event: 'finished';
    reason: string;
    time: number;
    goal_reached: boolean;
}

export class LabSimulations {
    readonly slots: SimulationSlots;
    readonly ledger: SimulatedTimeLedger;
    private sweeping = false;
    /** per workspace: the start in progress (the next one waits for it) */
    private readonly starting = new Map<number, Promise<unknown>>();

    constructor(
        private readonly store: LabStore,
        private readonly sessions: Pick<SessionService, 'find'>,
        private readonly pool: RuntimePool,
        quotas: QuotaOptions,
        private readonly log: (line: string) => void,
        now: () => number = Date.now,
    ) {
        this.slots = new SimulationSlots(quotas.concurrentSimulations);
        this.ledger = new SimulatedTimeLedger(quotas.simulatedSecondsPerHour, now);
    }

    /**
     * Starts the workspace's simulation for its owner within their quotas; the answer's endpoints
     * lie below the workspace's prefix. Starts of one workspace take turns (each restart ends
     * and records the one before).
     */
    start(opened: OpenedWorkspace, runtime: WorkspaceRuntime, auth: Authenticated, request: SimStartRequest): Promise<SimStartAnswer> {
        const previous = this.starting.get(runtime.workspaceId) ?? Promise.resolve();
        const run = previous.then(() => this.startNow(opened, runtime, auth, request));
        this.starting.set(
            runtime.workspaceId,
            run.catch(() => undefined),
        );
        return run;
    }

    private async startNow(
        opened: OpenedWorkspace,
        runtime: WorkspaceRuntime,
        auth: Authenticated,
        request: SimStartRequest,
    ): Promise<SimStartAnswer> {
        const userId = auth.user.id;
        // A restart in the same workspace ends its simulation first (its time counts).
        if (runtime.sim) await this.stop(runtime, 'restarted');
        this.ledger.checkStart(userId, this.runningSeconds(userId));
        this.slots.take(userId, runtime.workspaceId);
        try {
            await runtime.folder.sync();
            const answer = await startSimulation(
                { workspace: runtime.ide, generation: runtime.generation, sims: runtime.sims, maxFileBytes: 1, redact: runtime.redact },
                request,
            );
            runtime.sim = { userId, sessionId: auth.session.id, startedAt: Date.now(), speed: request.speed ?? 1 };
            this.log(`simulation of ${opened.owner.login} in ${opened.course.name}/${opened.exercise.name} started`);
            return { ...answer, rosbridge: `${opened.prefix}${ROSBRIDGE_PATH}`, viser: `${opened.prefix}${VISER_PATH}/` };
        } catch (e) {
            if (!runtime.sim) this.slots.release(userId, runtime.workspaceId);
            throw e;
        }
    }

    /** Stops the workspace's simulation and records it. */
    async stop(runtime: WorkspaceRuntime, why: string): Promise<void> {
        await runtime.sims.stop();
        if (runtime.sim) await this.finish(runtime, why);
    }

    /** One pass over the running simulations (see the file's comment); passes do not overlap. */
    async sweep(): Promise<void> {
        if (this.sweeping) return;
        this.sweeping = true;
        try {
            for (const runtime of this.pool.all()) {
                const sim = runtime.sim;
                if (!sim) continue;
                if (runtime.sims.processGroup() === undefined) await this.finish(runtime, 'ended');
                else if (!(await this.sessions.find(sim.sessionId)))
                    await this.stop(runtime, 'its student logged out or their session expired');
                else if (this.ledger.remaining(sim.userId, this.runningSeconds(sim.userId)) <= 0)
                    await this.stop(runtime, 'the simulated time quota of the hour is used up');
            }
        } finally {
            this.sweeping = false;
        }
    }

    /** Stops every simulation (the server stops) and records them. */
    async stopAll(): Promise<void> {
        await Promise.all(this.pool.all().map((r) => this.stop(r, 'the server stops').catch(() => undefined)));
    }

    /** Simulated seconds the student's running simulations used so far (wall time × speed). */
    runningSeconds(userId: number, now = Date.now()): number {
        return this.pool
            .all()
            .map((r) => r.sim)
            .filter((s): s is RunningSim => s?.userId === userId)
            .reduce((sum, s) => sum + ((now - s.startedAt) / 1000) * s.speed, 0);
    }

    /** Records the ended simulation: its simulated time (maa-sim's last line, else the estimate), the slot back, the result stored. */
    private async finish(runtime: WorkspaceRuntime, why: string): Promise<void> {
        const sim = runtime.sim;
        if (!sim) return;
        runtime.sim = undefined;
        const finished = finishedLine(runtime.sims.status().log);
        const estimate = ((Date.now() - sim.startedAt) / 1000) * sim.speed;
        const simulatedSeconds = finished?.time ?? estimate;
        // Charged: at least wall time × speed (a run that lags behind still held the machine that long).
        this.ledger.add(sim.userId, Math.max(simulatedSeconds, estimate));
        this.slots.release(sim.userId, runtime.workspaceId);
        this.log(`simulation in workspace ${runtime.workspaceId} ended (${why}): ${simulatedSeconds.toFixed(1)} simulated s`);
        await this.store
            .recordSimulationResult({
                workspaceId: runtime.workspaceId,
                submissionId: null,
                goalReached: finished?.goal_reached ?? false,
                simulatedSeconds,
                details: { ended: why, ...(finished ? { finished } : {}) },
            })
            .catch((e: unknown) => this.log(`cannot record the simulation of workspace ${runtime.workspaceId}: ${(e as Error).message}`));
    }
}

/** The last `{"event": "finished", ...}` line of a session's log. */
export function finishedLine(log: readonly string[]): FinishedLine | undefined {
    for (const line of [...log].reverse()) {
        if (!line.startsWith('{')) continue;
        try {
            const value = JSON.parse(line) as Partial<FinishedLine>;
            if (value.event === 'finished' && typeof value.time === 'number' && typeof value.goal_reached === 'boolean')
                return value as FinishedLine;
        } catch {
            // not JSON: a log line of the run
        }
    }
    return undefined;
}
