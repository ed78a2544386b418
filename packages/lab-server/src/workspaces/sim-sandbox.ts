// Students' live simulations run in sim-server's sandbox (`python -m maa_sim.sandbox`, bubblewrap;
// docs/lab.md "Sandbox"): maa-sim and the student's generated and handwritten components see the
// workspace's generated folder read-only, write only the workspace's simulation folder, run as a
// uid of their own with rlimits, and get a ROS 2 domain of the workspace's own. They keep the
// host's network (loopback): the lab proxies its students to maa-sim's rosbridge and viser ports
// on 127.0.0.1.
import { mkdirSync } from 'node:fs';
import path from 'node:path';
import type { SimCommandWrapper } from '@maa/ide-server';

/**
 * Limits of a live simulation (per process, rlimits; a simulation ends when its student leaves,
 * so there is no wall-clock limit): MuJoCo, viser and seven rclpy nodes in ros2 mode need about a
 * gigabyte of address space each and a few hundred threads in all.
 */
export const LIVE_SIM_LIMITS = {
    cpuSeconds: 4 * 3600,
    memoryMB: 8192,
    processes: 512,
    fileSizeMB: 256,
    openFiles: 1024,
} as const;

/**
 * ROS 2 domains of this server's running workspaces. On Linux 1..101 and 215..232 give DDS ports
 * below the ephemeral range; a workspace holds its domain while its runtime lives.
 */
const DOMAINS = [...Array.from({ length: 101 }, (_, i) => i + 1), ...Array.from({ length: 18 }, (_, i) => i + 215)];
const taken = new Map<number, number>();

/** The ROS 2 domain of a workspace (the same while it has one; a free one otherwise). */
export function rosDomainOf(workspaceId: number): number {
    const held = taken.get(workspaceId);
    if (held !== undefined) return held;
    const used = new Set(taken.values());
    const free = DOMAINS.find((d) => !used.has(d));
    if (free === undefined) throw new Error(`every ROS 2 domain (${DOMAINS.length}) is in use by another workspace's simulation`);
    taken.set(workspaceId, free);
    return free;
}

/** The workspace's runtime ended: its domain is free again. */
export function releaseRosDomain(workspaceId: number): void {
    taken.delete(workspaceId);
}

export interface SimSandboxOptions {
    /** the interpreter that runs maa_sim.sandbox (sim-server's venv) */
    python: string;
    workspaceId: number;
    /** the workspace's generated folder (the platforms maa-sim runs), read-only in the sandbox */
    generated: string;
    /** the workspace's simulation folder (ROS 2 logs), the only writable one; made when missing */
    runDir: string;
}

/** The SimSessions wrapper that runs maa-sim in the sandbox. */
export function simSandbox(options: SimSandboxOptions): SimCommandWrapper {
    return (launch) => {
        mkdirSync(options.runDir, { recursive: true });
        const l = LIVE_SIM_LIMITS;
        const args = [
            '-m',
            'maa_sim.sandbox',
            '--network',
            'host',
            '--ros-domain',
            String(rosDomainOf(options.workspaceId)),
            '--ro',
            options.generated,
            '--rw',
            options.runDir,
            '--cwd',
            launch.cwd,
            // the token is a secret: passed in the environment, not on the command line
            '--pass-env',
            'MAA_SIM_TOKEN',
            '--env',
            `ROS_LOG_DIR=${path.join(options.runDir, 'ros-log')}`,
            '--cpu-seconds',
            String(l.cpuSeconds),
            '--memory-mb',
            String(l.memoryMB),
            '--processes',
            String(l.processes),
            '--file-size-mb',
            String(l.fileSizeMB),
            '--open-files',
            String(l.openFiles),
            '--',
            launch.command,
            ...launch.args,
        ];
        return { command: options.python, args };
    };
}

/** sim-server's venv interpreter beside its maa-sim (`.venv/bin/maa-sim` → `.venv/bin/python`). */
export function sandboxPython(maaSim: string): string {
    return path.join(path.dirname(maaSim), 'python');
}
