// A Vitest setup file (vitest.config.ts): when MAA_VITEST_CPU_DIR names a folder, each test file
// writes there, after its last hook, the CPU time (user + sys) its worker process used and that of
// the child processes the worker waited for (maa-gen, the simulator, servers: /proc/self/stat's
// cutime and cstime, Linux only). Each file runs in a fresh worker process (Vitest's default
// isolation), so these are the file's own figures; scripts/vitest-outcome-reporter.mjs reads them
// and lists the test files that cost the most CPU, which is what a 2-core machine runs out of.
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { afterAll, beforeAll } from 'vitest';

const dir = process.env.MAA_VITEST_CPU_DIR;

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
        // the whole worker process: its start, the imports of the test file, the tests and hooks
        const self = process.cpuUsage();
        const record = {
            file,
            pid: process.pid,
            selfMs: Math.round((self.user + self.system) / 1000),
            childrenMs: childrenCpuMs(),
        };
        writeFileSync(path.join(dir, `${path.basename(file)}-${process.pid}-${Date.now()}.json`), JSON.stringify(record));
    });
}
