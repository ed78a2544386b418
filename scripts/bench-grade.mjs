#!/usr/bin/env node
// npm run bench:grade: how fast the grading driver (python -m maa_sim.grading, docs/lab.md
// "Grading") runs a class's scenario runs on Ray. Not a test.
//
// The toast-controller exercise (examples/lab/toast-controller): N submissions (default 30), each
// the reference solution or, every fifth, a broken variant (wrong-transition: the toast never
// reaches the plate, so its runs take the whole 60 s of simulated time) x the 3 scenarios of its
// grading.json = 3N tasks, each `maa-sim run` of the generated timesync build in lock-step in the
// sandbox (the argv @maa/grading plans, packages/grading/src/plan.ts). The same job runs
//   1. local Ray with 1 worker (one task after the other: the baseline),
//   2. local Ray with 2 workers (ray.init(num_cpus=2) on this machine),
//   3. a local 2-node Ray cluster (ray start --head + a worker node, 1 CPU each, on 127.0.0.1),
// and the table gives each mode's wall time, tasks/s and speed-up over mode 1. One more row grades
// the first 3 submissions end to end with @maa/grading's gradeSubmissions (check, generate, plan,
// driver, scores). Needs a build (packages/grading/dist).
//
// usage: node scripts/bench-grade.mjs [--submissions N] [--modes serial,local,cluster] [--keep]
import { spawn, spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { cp, mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import readline from 'node:readline';
import { fileURLToPath, pathToFileURL } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const gradingDist = path.join(repo, 'packages', 'grading', 'dist', 'index.js');
if (!existsSync(gradingDist)) {
    console.error(`bench:grade: ${path.relative(repo, gradingDist)} is missing: build first (npm run build)`);
    process.exit(1);
}
/** @maa/grading as built: the scenario tasks' argv and limits as it plans them, and gradeSubmissions. */
const grading = await import(pathToFileURL(gradingDist).href);
const python = path.join(repo, 'sim-server', '.venv', 'bin', 'python');
const exercise = path.join(repo, 'examples', 'lab', 'toast-controller');
const variants = path.join(repo, 'packages', 'lab-server', 'test', 'fixtures', 'grading', 'toast-controller');
const maaGen = path.join(repo, 'packages', 'cli', 'bin', 'maa-gen.js');
const BROKEN_EVERY = 5;
const BROKEN = 'wrong-transition';
const MODES = ['serial', 'local', 'cluster'];

function parseArgs(argv) {
    const options = { submissions: 30, modes: MODES, keep: false };
    for (let i = 0; i < argv.length; i++) {
        const arg = argv[i];
        if (arg === '--submissions') options.submissions = Number(argv[++i]);
        else if (arg === '--modes') options.modes = String(argv[++i]).split(',');
        else if (arg === '--keep') options.keep = true;
        else {
            console.error('usage: node scripts/bench-grade.mjs [--submissions N] [--modes serial,local,cluster] [--keep]');
            process.exit(2);
        }
    }
    if (!Number.isInteger(options.submissions) || options.submissions < 1) throw new Error('--submissions must be a positive integer');
    for (const mode of options.modes) if (!MODES.includes(mode)) throw new Error(`unknown mode ${mode} (${MODES.join(', ')})`);
    return options;
}

/** The exercise's model root of a submission: base minus `omit`, the solution over it, a variant's overlay over that. */
async function assemble(dir, variant) {
    const config = JSON.parse(await readFile(path.join(exercise, 'exercise.json'), 'utf8'));
    await cp(path.resolve(exercise, config.base), dir, { recursive: true });
    for (const omitted of config.omit ?? []) await rm(path.join(dir, omitted), { recursive: true, force: true });
    await cp(path.join(exercise, 'solution'), dir, { recursive: true });
    if (variant) await cp(path.join(variants, variant), dir, { recursive: true });
    return path.join(dir, config.app);
}

function generate(app, out) {
    const result = spawnSync(process.execPath, [maaGen, 'generate', app, '--platform', 'timesync', '--out', out], { encoding: 'utf8' });
    if (result.status !== 0) throw new Error(`maa-gen generate ${app} failed:\n${result.stdout}\n${result.stderr}`);
    return path.join(out, 'timesync');
}

/** Writes the task input folders (a copy of the build and world.json each) and the job file. */
async function writeJob(work, builds, submissions) {
    const spec = JSON.parse(await readFile(path.join(exercise, 'grading', 'grading.json'), 'utf8'));
    const scenarios = spec.criteria.filter((c) => c.kind === 'scenarios').flatMap((c) => c.scenarios);
    const tasks = [];
    for (let s = 0; s < submissions; s++) {
        const variant = (s + 1) % BROKEN_EVERY === 0 ? BROKEN : 'solution';
        for (const scenario of scenarios) {
            const id = `s${String(s + 1).padStart(2, '0')}-${variant}.scenario.${scenario.id}`;
            const input = path.join(work, 'inputs', id);
            await cp(builds[variant], path.join(input, 'build', 'timesync'), { recursive: true, dereference: true });
            await writeFile(path.join(input, 'world.json'), `${JSON.stringify(scenario.world)}\n`);
            tasks.push({
                id,
                input,
                argv: grading.scenarioArgv(scenario),
                limits: grading.DEFAULT_LIMITS.scenarios,
                env: { PYTHONPATH: '{input}/build/timesync', PYTHONDONTWRITEBYTECODE: '1' },
            });
        }
    }
    const job = path.join(work, 'job.json');
    await writeFile(job, JSON.stringify({ format: 'maa-grade-job/1', tasks }, null, 1));
    return { job, tasks: tasks.length, scenarios: scenarios.length };
}

/** Runs the driver, printing a progress line per task; resolves with its lines. */
function runDriver(label, job, out, args, env) {
    return new Promise((resolve, reject) => {
        const started = performance.now();
        const child = spawn(python, ['-m', 'maa_sim.grading', 'run', '--job', job, '--out', out, ...args], {
            env: { ...process.env, ...env },
            stdio: ['ignore', 'pipe', 'pipe'],
        });
        let stderr = '';
        child.stderr.on('data', (chunk) => {
            stderr = (stderr + chunk).slice(-4000);
        });
        const lines = [];
        let total = 0;
        readline.createInterface({ input: child.stdout }).on('line', (text) => {
            const line = JSON.parse(text);
            lines.push(line);
            if (line.event === 'started') {
                total = line.tasks;
                console.log(`[${label}] ${line.mode}, ${line.nodes} node(s), ${line.cpus} CPU(s), ${line.tasks} tasks`);
            } else if (line.event === 'task') {
                const done = lines.filter((l) => l.event === 'task').length;
                const elapsed = ((performance.now() - started) / 1000).toFixed(0);
                console.log(
                    `[${label}] ${done}/${total} ${line.id} ${line.status} ${line.seconds.toFixed(1)} s on ${line.node} (${elapsed} s)`,
                );
            }
        });
        child.on('error', reject);
        child.on('close', (code) => {
            const seconds = (performance.now() - started) / 1000;
            if (code !== 0) reject(new Error(`the driver (${label}) exited with ${code}:\n${stderr}`));
            else resolve({ lines, seconds });
        });
    });
}

function startCluster(dir) {
    const result = spawnSync(python, ['-m', 'maa_sim.grading', 'cluster', 'start', '--dir', dir, '--nodes', '2', '--cpus-per-node', '1'], {
        encoding: 'utf8',
    });
    if (result.status !== 0) throw new Error(`the cluster did not start:\n${result.stderr}`);
    return Object.fromEntries(
        result.stdout
            .trim()
            .split('\n')
            .map((l) => [l.slice(0, l.indexOf('=')), l.slice(l.indexOf('=') + 1)]),
    );
}

function stopCluster(dir) {
    spawnSync(python, ['-m', 'maa_sim.grading', 'cluster', 'stop', '--dir', dir], { stdio: 'inherit' });
}

function summary(label, workers, run) {
    const tasks = run.lines.filter((l) => l.event === 'task');
    const finished = run.lines.find((l) => l.event === 'finished');
    const busy = tasks.reduce((sum, t) => sum + t.seconds, 0);
    const nodes = new Set(tasks.map((t) => t.node)).size;
    return { label, workers, tasks: tasks.length, wall: finished.wallSeconds, busy, nodes, counts: finished.counts };
}

async function runModes(options, job, work) {
    const rows = [];
    for (const mode of options.modes) {
        const out = path.join(work, `out-${mode}`);
        if (mode === 'serial')
            rows.push(summary('local Ray, 1 worker (one after the other)', 1, await runDriver(mode, job, out, ['--workers', '1'], {})));
        if (mode === 'local') rows.push(summary('local Ray, 2 workers', 2, await runDriver(mode, job, out, ['--workers', '2'], {})));
        if (mode === 'cluster') {
            const dir = path.join(work, 'cluster');
            const env = startCluster(dir);
            try {
                rows.push(summary('2-node local Ray cluster (1 CPU each)', 2, await runDriver(mode, job, out, [], env)));
            } finally {
                stopCluster(dir);
            }
        }
    }
    return rows;
}

/** One end-to-end row with @maa/grading: gradeSubmissions of 3 submissions. */
async function engineRow(work) {
    const { gradeSubmissions } = grading;
    const submissions = [];
    for (const [i, variant] of ['solution', 'solution', BROKEN].entries()) {
        const root = path.join(work, 'engine', `sub${i + 1}`);
        const app = await assemble(root, variant === 'solution' ? undefined : variant);
        submissions.push({ id: `sub${i + 1}-${variant}`, root, appFile: app });
    }
    const started = performance.now();
    const grades = await gradeSubmissions({
        gradingDir: path.join(exercise, 'grading'),
        submissions,
        workDir: path.join(work, 'engine', 'work'),
        python,
        onProgress: (event) => {
            if (event.kind === 'graded') console.log(`[engine] ${event.submission}: ${event.score} / ${event.maxScore}`);
            else if (event.kind === 'driver' && event.line.event === 'task') console.log(`[engine] ${event.line.id} ${event.line.status}`);
        },
    });
    const seconds = (performance.now() - started) / 1000;
    const tasks = grades.reduce((n, g) => n + g.tasks.length, 0);
    return { seconds, tasks, scores: grades.map((g) => `${g.submission} ${g.score}/${g.maxScore}`) };
}

function table(rows, base) {
    const lines = [
        '| mode | workers | tasks | wall time (s) | tasks/s | speed-up over 1 worker | task time sum (s) | nodes used | statuses |',
        '|---|---:|---:|---:|---:|---:|---:|---:|---|',
    ];
    for (const r of rows) {
        const speedup = base ? (base.wall / r.wall).toFixed(2) : 'n/a';
        const statuses = Object.entries(r.counts)
            .filter(([, n]) => n > 0)
            .map(([s, n]) => `${s} ${n}`)
            .join(', ');
        lines.push(
            `| ${r.label} | ${r.workers} | ${r.tasks} | ${r.wall.toFixed(1)} | ${(r.tasks / r.wall).toFixed(2)} | ${speedup} | ${r.busy.toFixed(1)} | ${r.nodes} | ${statuses} |`,
        );
    }
    return lines.join('\n');
}

/** What a course of 300 would need, from the measured time per task and the measured efficiency of 2 workers. */
function projection(rows, base, scenarios) {
    const perTask = base.wall / base.tasks;
    const two = rows.filter((r) => r.workers === 2);
    const measured = two.length > 0;
    // without a 2-worker row the projection can only assume linear scaling, and says so
    const efficiency = measured ? Math.max(...two.map((r) => base.wall / r.wall)) / 2 : 1;
    const tasks = 300 * (scenarios + 1); // the scenarios and one hidden-tests task per submission
    const minutes = (workers) => ((tasks * perTask) / (workers === 1 ? 1 : workers * efficiency) / 60).toFixed(1);
    return [
        `One worker: ${perTask.toFixed(2)} s per task (wall time / tasks). ${
            measured
                ? `Efficiency of 2 workers: ${(efficiency * 100).toFixed(0)} %.`
                : 'Efficiency of more workers: not measured (run the local or cluster mode); assumed 100 %.'
        }`,
        `A course of 300 submissions x (${scenarios} scenarios + 1 hidden-tests task) = ${tasks} tasks at that efficiency:`,
        `${minutes(1)} min on 1 worker, ${minutes(2)} min on 2, ${minutes(8)} min on 8, ${minutes(32)} min on 32 (e.g. 4 nodes of 8 cores).`,
    ].join('\n');
}

async function main() {
    const options = parseArgs(process.argv.slice(2));
    if (!existsSync(python)) throw new Error(`${python} is missing: run bash sim-server/scripts/setup_env.sh`);
    const work = await mkdtemp(path.join(os.tmpdir(), 'maa-bench-grade-'));
    try {
        console.log(
            `bench:grade in ${work}: ${options.submissions} submissions of toast-controller (every ${BROKEN_EVERY}th ${BROKEN}) x its scenarios`,
        );
        const builds = {};
        for (const variant of ['solution', BROKEN]) {
            const app = await assemble(path.join(work, 'models', variant), variant === 'solution' ? undefined : variant);
            builds[variant] = generate(app, path.join(work, 'gen', variant));
            console.log(`generated ${variant}: ${builds[variant]}`);
        }
        const { job, tasks, scenarios } = await writeJob(work, builds, options.submissions);
        console.log(`job: ${tasks} tasks (${options.submissions} x ${scenarios} scenarios) in ${job}`);
        const rows = await runModes(options, job, work);
        const engine = await engineRow(work);
        const base = rows.find((r) => r.workers === 1);
        console.log(
            `\n## bench:grade (${new Date().toISOString().slice(0, 16)} UTC, ${os.cpus().length} cores, ${(os.totalmem() / 2 ** 30).toFixed(0)} GiB)\n`,
        );
        console.log(table(rows, base));
        console.log(
            `\n@maa/grading end to end (check, generate, plan, driver on local Ray, scores): ${engine.tasks} tasks of 3 submissions in ${engine.seconds.toFixed(1)} s: ${engine.scores.join('; ')}`,
        );
        if (base) console.log(`\n${projection(rows, base, scenarios)}`);
    } finally {
        if (!options.keep) await rm(work, { recursive: true, force: true });
        else console.log(`kept ${work}`);
    }
}

main().catch((error) => {
    console.error(error instanceof Error ? error.message : error);
    process.exit(1);
});
