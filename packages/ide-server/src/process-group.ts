import { readdirSync, readFileSync } from 'node:fs';

/**
 * Signalling a simulation's processes as a whole. maa-sim runs in a process group of its own
 * (spawned detached), and it may start helpers in further groups of their own (maa-sim's ROS 2
 * nodes are session leaders, so that it can stop each node with its children). A stop therefore
 * signals maa-sim's group and, on Linux, the groups of every descendant found in /proc.
 */

/** `/proc/<pid>/stat` → [ppid, pgid]; the command name (field 2) may hold blanks and parentheses. */
function parentAndGroup(pid: string): [number, number] | undefined {
    try {
        const stat = readFileSync(`/proc/${pid}/stat`, 'utf8');
        const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
        return [Number(fields[1]), Number(fields[2])];
    } catch {
        return undefined; // gone meanwhile, or no /proc (not Linux)
    }
}

/**
 * The process groups of `pid`'s descendants other than `pid`'s own group (empty without /proc).
 * Synchronous: it also runs in a `process.on('exit')` handler.
 */
export function descendantGroups(pid: number): number[] {
    let names: string[];
    try {
        names = readdirSync('/proc').filter((n) => /^\d+$/.test(n));
    } catch {
        return [];
    }
    const children = new Map<number, number[]>();
    const groupOf = new Map<number, number>();
    for (const name of names) {
        const info = parentAndGroup(name);
        if (!info) continue;
        const [ppid, pgid] = info;
        const p = Number(name);
        groupOf.set(p, pgid);
        const list = children.get(ppid);
        if (list) list.push(p);
        else children.set(ppid, [p]);
    }
    const groups = new Set<number>();
    const queue = [...(children.get(pid) ?? [])];
    while (queue.length > 0) {
        const p = queue.pop()!;
        const g = groupOf.get(p);
        if (g !== undefined && g !== pid && g > 1) groups.add(g);
        queue.push(...(children.get(p) ?? []));
    }
    return [...groups];
}

/** Signals a whole process group; false when it no longer exists. */
export function signalGroup(pgid: number, signal: NodeJS.Signals | 0): boolean {
    try {
        process.kill(-pgid, signal);
        return true;
    } catch (e) {
        // EPERM: members we may not signal; nothing more we can do about them.
        return (e as NodeJS.ErrnoException).code === 'EPERM';
    }
}

/** Whether any process of the group is left. */
export function groupAlive(pgid: number): boolean {
    return signalGroup(pgid, 0);
}

/** Whether a process with this id exists (EPERM: it does, as another user's; a zombie counts until reaped). */
export function processAlive(pid: number): boolean {
    try {
        process.kill(pid, 0);
        return true;
    } catch (e) {
        return (e as NodeJS.ErrnoException).code === 'EPERM';
    }
}
