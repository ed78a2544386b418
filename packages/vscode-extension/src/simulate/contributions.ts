/** The simulate commands and settings in the manifest (src/contributions.ts adds them). */
export { SIMULATE_SETTINGS } from './launch.js';

export const SIMULATE_COMMANDS = [
    { command: 'maa.simulate.start', title: 'MontiArc: Start Simulation', category: 'MontiArc' },
    { command: 'maa.simulate.stop', title: 'MontiArc: Stop Simulation', category: 'MontiArc' },
    { command: 'maa.simulate.reset', title: 'MontiArc: Reset Simulation', category: 'MontiArc' },
] as const;

/** In the command palette only where the commands are registered: the desktop entry (the web entry has no backend of its own to start). */
export const SIMULATE_PALETTE = SIMULATE_COMMANDS.map((c) => ({ command: c.command, when: '!isWeb' }));
