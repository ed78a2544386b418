// Concurrent simulations per student: a slot is taken before a simulation starts (so two starts
// at once cannot both pass) and given back when it ends. A workspace holds one simulation, so a
// restart in the same workspace keeps its slot.
import { tooMany } from './errors.js';

export class SimulationSlots {
    /** user id → the workspaces (ids) that hold a slot */
    private readonly held = new Map<number, Set<number>>();

    constructor(private readonly perStudent: number) {}

    /** Takes a slot for the workspace's simulation (429 when the student holds every slot elsewhere). */
    take(userId: number, workspaceId: number): void {
        const set = this.held.get(userId) ?? new Set<number>();
        if (!set.has(workspaceId) && set.size >= this.perStudent) {
            throw tooMany(
                'concurrentSimulations',
                this.perStudent,
                `simulation quota: ${set.size} of your simulations run already (at most ${this.perStudent} at a time); stop one first (POST .../sim/stop) — a slot frees when one ends`,
                new Date(Date.now() + 60_000),
            );
        }
        set.add(workspaceId);
        this.held.set(userId, set);
    }

    release(userId: number, workspaceId: number): void {
        const set = this.held.get(userId);
        set?.delete(workspaceId);
        if (set?.size === 0) this.held.delete(userId);
    }

    count(userId: number): number {
        return this.held.get(userId)?.size ?? 0;
    }
}
