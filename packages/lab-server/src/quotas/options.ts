// The lab's per-student limits (docs/lab.md "Quotas"), their defaults and their checks.

export interface QuotaOptions {
    /** simulations one student may run at the same time (over all their workspaces) */
    concurrentSimulations: number;
    /** simulated seconds one student may run within any hour */
    simulatedSecondsPerHour: number;
    /** the bytes of a workspace's current files */
    workspaceBytes: number;
    /** the number of a workspace's current files */
    workspaceFiles: number;
}

export const DEFAULT_QUOTAS: QuotaOptions = {
    concurrentSimulations: 1,
    simulatedSecondsPerHour: 1800,
    workspaceBytes: 5 * 1024 * 1024,
    workspaceFiles: 500,
};

/** The defaults with the given limits; an Error names a limit that is not a positive whole number. */
export function quotaOptions(given: Partial<QuotaOptions> = {}): QuotaOptions {
    const quotas = { ...DEFAULT_QUOTAS, ...given };
    for (const [name, value] of Object.entries(quotas))
        if (!Number.isInteger(value) || value < 1) throw new Error(`the quota ${name} must be a positive whole number, not ${value}`);
    return quotas;
}
