// Simulated seconds per student within the last hour: finished runs are entries (their end and
// their simulated seconds), running ones count with what they used so far. A start is refused
// (429) while the hour's budget is spent, saying when the oldest entry leaves the window.
import { tooMany } from './errors.js';

export const HOUR_MS = 3600_000;

interface Entry {
    end: number;
    seconds: number;
}

export class SimulatedTimeLedger {
    private readonly entries = new Map<number, Entry[]>();

    /** @param now the clock (tests may move it) */
    constructor(
        private readonly perHour: number,
        private readonly now: () => number = Date.now,
    ) {}

    /** Records a finished run of the student. */
    add(userId: number, seconds: number): void {
        if (!(seconds > 0)) return;
        const list = this.current(userId);
        list.push({ end: this.now(), seconds });
        this.entries.set(userId, list);
    }

    /** Simulated seconds of finished runs within the last hour. */
    used(userId: number): number {
        return this.current(userId).reduce((sum, e) => sum + e.seconds, 0);
    }

    /** What is left of the hour's budget when runs still going used `running` seconds. */
    remaining(userId: number, running = 0): number {
        return this.perHour - this.used(userId) - running;
    }

    /** 429 when the student has no simulated time left this hour. */
    checkStart(userId: number, running = 0): void {
        if (this.remaining(userId, running) > 0) return;
        const oldest = this.current(userId)[0];
        const freesAt = new Date(oldest ? oldest.end + HOUR_MS : this.now() + 60_000);
        throw tooMany(
            'simulatedSecondsPerHour',
            this.perHour,
            `simulated time quota: you simulated ${Math.round(this.used(userId) + running)} of the ${this.perHour} simulated seconds allowed per hour; more frees at ${freesAt.toISOString()}`,
            freesAt,
        );
    }

    private current(userId: number): Entry[] {
        const since = this.now() - HOUR_MS;
        const list = (this.entries.get(userId) ?? []).filter((e) => e.end > since);
        if (list.length === 0) this.entries.delete(userId);
        else this.entries.set(userId, list);
        return list;
    }
}
