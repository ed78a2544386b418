// A lower CPU priority for the lab server's worker threads (the generator threads and the
// dashboard's checker thread; docs/lab.md "Load benchmark"): on a machine with few cores they
// compete with the thread that answers the students' requests (saves, file lists, logins), and
// that thread should win. On Linux the nice value is an attribute of each thread, so a worker
// thread raises its own (its id from /proc/thread-self) and the server's main thread keeps its
// priority. Elsewhere (no /proc) nothing changes.
import { readlinkSync } from 'node:fs';
import { getPriority, setPriority } from 'node:os';

/** The nice value the worker threads run at (0 is the default, 19 the lowest priority). */
export const WORKER_NICE = 10;

/**
 * Lowers the calling thread's priority to `nice` (never raises it). Call it in a worker thread.
 * @returns the thread's id when its priority is now at most that (Linux), else undefined
 */
export function lowerThreadPriority(nice = WORKER_NICE): number | undefined {
    try {
        const tid = Number(readlinkSync('/proc/thread-self').split('/').pop());
        if (!Number.isSafeInteger(tid) || tid <= 0) return undefined;
        if (getPriority(tid) < nice) setPriority(tid, nice);
        return tid;
    } catch {
        return undefined;
    }
}
