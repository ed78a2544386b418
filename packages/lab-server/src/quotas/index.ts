// Per-student limits of the lab (docs/lab.md "Quotas").
export { DEFAULT_QUOTAS, type QuotaOptions, quotaOptions } from './options.js';
export { SimulationSlots } from './sim-slots.js';
export { HOUR_MS, SimulatedTimeLedger } from './sim-time.js';
export { checkWorkspaceSize } from './workspace-size.js';
