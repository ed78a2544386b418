#!/usr/bin/env node
// The lab load benchmark (`npm run bench:lab` at the repository root; docs/lab.md "Load
// benchmark"; not a test: it prints figures with their goals and exits 1 only for failed
// requests or a setup that does not work).
//
// 1. Setup through the real components: a fresh data directory (embedded PGlite, or the empty
//    PostgreSQL database of --database-url / DATABASE_URL), a course with an instructor and
//    --students students, the toast-controller exercise released; `maa-lab serve` on port 0
//    (loopback) as its own process, so the load does not share its event loop.
// 2. Load for --duration seconds: every student logs in (/api/login: session cookie and CSRF
//    token) and loops with think time: save their Controller automaton (every 5th save with an
//    error), list the files, generate (timesync), every --test-every rounds the stream tests; the
//    instructor polls the dashboard (the server-side diagnostics of changed workspaces) every 5 s.
// 3. Simulations: 1, 2, 3, ... lock-step simulations of the exercise in students' workspaces
//    until the median real-time factor drops below 0.95 or --max-sims.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { runLoad } from './load.mjs';
import { databaseBytes, peakRss, processesUnder, setUpLab, startServer } from './setup.mjs';
import { measureSimulations } from './sims.mjs';
import { summarize } from './stats.mjs';

const HELP = `npm run bench:lab -- [options]

The classroom lab under load: a lab server (maa-lab serve, its own process) with a course of
simulated students editing, generating and testing, then how many simulations run at real time.

  --students N        simulated students (default 30)
  --duration S        seconds of load (default 60)
  --think-ms MS       mean think time between a student's steps (default 3000)
  --test-every N      a student runs the stream tests every N-th round (default 4)
  --max-sims N        at most this many concurrent simulations (default 8; 0 skips them)
  --database-url URL  an empty PostgreSQL database instead of PGlite (default: DATABASE_URL)
  --data-dir DIR      the data directory (default: a fresh temporary one, removed after)
  --json              print the figures as JSON (instead of the table)
  --help              this text
`;

const GOALS = { errors: 0, saveP99Ms: 200, filesP99Ms: 200, realTimeFactor: 0.95 };

function options() {
    const { values } = parseArgs({
        options: {
            students: { type: 'string', default: '30' },
            duration: { type: 'string', default: '60' },
            'think-ms': { type: 'string', default: '3000' },
            'test-every': { type: 'string', default: '4' },
            'max-sims': { type: 'string', default: '8' },
            'database-url': { type: 'string' },
            'data-dir': { type: 'string' },
            json: { type: 'boolean', default: false },
            help: { type: 'boolean', default: false },
        },
    });
    if (values.help) {
        process.stdout.write(HELP);
        process.exit(0);
    }
    const whole = (name, min) => {
        const n = Number(values[name]);
        if (!/^\d+$/.test(values[name]) || n < min) {
            process.stderr.write(`lab-bench: --${name} must be a whole number of at least ${min}, not ${values[name]}\n`);
            process.exit(2);
        }
        return n;
    };
    return {
        students: whole('students', 1),
        seconds: whole('duration', 1),
        thinkMs: whole('think-ms', 0),
        testEvery: whole('test-every', 1),
        maxSims: whole('max-sims', 0),
        databaseUrl: values['database-url'] || process.env.DATABASE_URL || undefined,
        dataDir: values['data-dir'],
        json: values.json,
    };
}

const ms = (x) => (Number.isFinite(x) ? `${x.toFixed(0)} ms` : '—');
const mib = (b) => (b === undefined ? '—' : `${(b / 1024 / 1024).toFixed(1)} MiB`);
const verdict = (ok) => (ok ? 'ok' : 'MISSED');

function printTable(r) {
    const out = (s = '') => process.stdout.write(`${s}\n`);
    out(`lab load: ${r.students} students for ${r.elapsedSeconds.toFixed(0)} s on ${r.backend}, think time ~${r.thinkMs} ms`);
    out('');
    out('kind        count   req/s     p50      p90      p99   errors');
    for (const k of r.kinds)
        out(
            `${k.kind.padEnd(10)} ${String(k.count).padStart(6)} ${k.perSecond.toFixed(2).padStart(7)} ${ms(k.p50).padStart(8)} ${ms(k.p90).padStart(8)} ${ms(k.p99).padStart(8)} ${String(k.errors).padStart(8)}`,
        );
    out('');
    const kind = (name) => r.kinds.find((k) => k.kind === name);
    const overall = kind('overall');
    out(`errors ${overall.errors} (goal ${GOALS.errors})  ${overall.errors === 0 ? 'ok' : 'FAIL'}`);
    if (kind('save'))
        out(`p99 save ${ms(kind('save').p99)} (goal < ${GOALS.saveP99Ms} ms)  ${verdict(kind('save').p99 < GOALS.saveP99Ms)}`);
    if (kind('files'))
        out(`p99 files ${ms(kind('files').p99)} (goal < ${GOALS.filesP99Ms} ms)  ${verdict(kind('files').p99 < GOALS.filesP99Ms)}`);
    out(`database size at the end ${mib(r.databaseBytes)} (${r.backend})`);
    out(`server peak RSS ${mib(r.serverPeakRss)} (the maa-lab serve process, not its simulators)`);
    for (const f of r.failures) out(`FAIL ${f.kind}: ${f.status} ${f.detail ?? ''}`);
    if (!r.sims) return;
    out('');
    out(`simulations (lock-step, speed 1; real-time factor from the simulator's status, median of ${r.sims.samples} readings each)`);
    out('count  median RTF  min     max');
    for (const row of r.sims.rows)
        out(`${String(row.count).padStart(5)}  ${row.median.toFixed(3).padStart(10)}  ${row.min.toFixed(3)}  ${row.max.toFixed(3)}`);
    const capped = r.sims.rows.length > 0 && r.sims.rows.at(-1).median >= r.sims.threshold;
    out(
        `concurrent simulations at real time: ${r.sims.held}${capped ? ` (or more: the cap --max-sims ${r.sims.maxSims} was reached)` : ''} (goal: median real-time factor >= ${r.sims.threshold})`,
    );
    if (r.sims.orphans.length > 0)
        out(`FAIL ${r.sims.orphans.length} simulator processes were left: ${r.sims.orphans.map((o) => o.pid).join(', ')}`);
    else out('simulator processes left after the stop: 0 (goal 0)  ok');
}

async function main() {
    const o = options();
    const temporary = o.dataDir === undefined;
    const dataDir = path.resolve(o.dataDir ?? mkdtempSync(path.join(tmpdir(), 'maa-lab-bench-')));
    const log = (s) => o.json || process.stderr.write(`${s}\n`);
    let server;
    try {
        log(`setting up ${o.students} students in ${o.databaseUrl ? 'PostgreSQL' : dataDir} ...`);
        await setUpLab({ dataDir, databaseUrl: o.databaseUrl, students: o.students });
        // every student may run one simulation (the default); the measurement uses one per student
        server = await startServer({ dataDir, databaseUrl: o.databaseUrl, extraArgs: ['--max-sim-seconds-per-hour', '36000'] });
        log(`maa-lab serve at ${server.url} (pid ${server.pid}); load for ${o.seconds} s ...`);
        const { samples, elapsed } = await runLoad({
            url: server.url,
            students: o.students,
            seconds: o.seconds,
            thinkMs: o.thinkMs,
            testEvery: o.testEvery,
        });
        const result = {
            backend: o.databaseUrl ? 'PostgreSQL' : 'PGlite',
            students: o.students,
            thinkMs: o.thinkMs,
            elapsedSeconds: elapsed,
            kinds: summarize(samples, elapsed),
            failures: samples.filter((s) => !s.ok).slice(0, 20),
            goals: GOALS,
        };
        if (o.maxSims > 0) {
            log('simulations ...');
            const sims = await measureSimulations({
                url: server.url,
                maxSims: o.maxSims,
                students: o.students,
                samples: 5,
                log: (row) => log(`  ${row.count} simulation(s): median real-time factor ${row.median.toFixed(3)}`),
            });
            result.sims = { ...sims, samples: 5, maxSims: o.maxSims, orphans: [] };
        }
        result.serverPeakRss = peakRss(server.pid);
        const stopped = await server.stop();
        server = undefined;
        if (stopped.code !== 0 && stopped.signal !== 'SIGTERM') log(`maa-lab serve ended with ${stopped.code ?? stopped.signal}`);
        if (result.sims) {
            result.sims.orphans = processesUnder(dataDir);
            for (const p of result.sims.orphans) process.kill(p.pid, 'SIGKILL');
        }
        result.databaseBytes = await databaseBytes({ dataDir, databaseUrl: o.databaseUrl });
        if (o.json) process.stdout.write(`${JSON.stringify(result, null, 2)}\n`);
        else printTable(result);
        const failed = result.kinds.at(-1).errors > 0 || (result.sims?.orphans.length ?? 0) > 0;
        process.exitCode = failed ? 1 : 0;
    } finally {
        if (server) {
            process.stderr.write(`${server.stderrTail()}\n`);
            await server.stop();
        }
        if (temporary) rmSync(dataDir, { recursive: true, force: true });
    }
}

main().catch((e) => {
    process.stderr.write(`lab-bench: FAIL ${e instanceof Error ? e.stack : e}\n`);
    process.exitCode = 1;
});
