// A Vitest setup file (vitest.config.ts): when MAA_VITEST_CPU_DIR names a folder, each test file
// writes there, after its last hook, the CPU time (user + sys) its worker process used and that of
// the child processes the worker waited for (maa-gen, the simulator, servers: /proc/self/stat's
// cutime and cstime, Linux only). A worker process runs many test files one after the other
// (vitest.config.ts: isolate false), so a file's figures are what the worker used since the
// previous file's record (or since it started: its first file also carries the worker's start);
// the records of one worker add up to all it used. scripts/vitest-outcome-reporter.mjs reads them
// and lists the test files that cost the most CPU, which is what a 2-core machine runs out of.
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll } from 'vitest';

const dir = process.env.MAA_VITEST_CPU_DIR;
/** Where the worker keeps the CPU figures of its previous record: this module runs again for every test file. */
const MARK = Symbol.for('maa.vitest-file-cpu.mark');

/** CPU time of the waited-for children of this process, in ms; undefined off Linux. */
function childrenCpuMs() {
    try {
        const stat = readFileSync('/proc/self/stat', 'utf8');
        // the fields after the command name in parentheses (which may hold spaces)
        const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
        // fields 16 and 17 (1-based, of the whole line) are cutime and cstime, in clock ticks (100 Hz on Linux)
        return (Number(fields[13]) + Number(fields[14])) * 10;
    } catch {
        return undefined;
    }
}

if (dir) {
    let file;
    beforeAll((suite) => {
        file = suite.file?.filepath ?? suite.filepath;
    });
    afterAll(() => {
        if (!file) return;
        // since the previous record: the imports of the test file (those not yet loaded), the tests and hooks
        const self = process.cpuUsage();
        const now = { selfMs: Math.round((self.user + self.system) / 1000), childrenMs: childrenCpuMs() };
        const before = globalThis[MARK] ?? { selfMs: 0, childrenMs: 0 };
        globalThis[MARK] = now;
        const record = {
            file,
            pid: process.pid,
            selfMs: now.selfMs - before.selfMs,
            childrenMs: now.childrenMs === undefined ? undefined : now.childrenMs - (before.childrenMs ?? 0),
        };
        writeFileSync(path.join(dir, `${path.basename(file)}-${process.pid}-${Date.now()}.json`), JSON.stringify(record));
    });
}
