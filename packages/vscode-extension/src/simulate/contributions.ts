/** The simulate commands and settings in the manifest (src/contributions.ts adds them). */
export { SIMULATE_SETTINGS } from './launch.js';

export const SIMULATE_COMMANDS = [
    { command: 'maa.simulate.start', title: 'MontiArc: Start Simulation', category: 'MontiArc' },
    { command: 'maa.simulate.stop', title: 'MontiArc: Stop Simulation', category: 'MontiArc' },
    { command: 'maa.simulate.reset', title: 'MontiArc: Reset Simulation', category: 'MontiArc' },
] as const;

// Both entries register the commands (desktop: index.ts, web: web.ts), so the palette shows them everywhere (no `when`).
