#!/usr/bin/env node
// `npm test`: builds every workspace package, sets up the Python venvs (Vitest uses them too), runs
// every Vitest suite of the workspace (vitest.config.ts at the root), the browser end-to-end
// suite (e2e/), the Python suites (PYTHON_SUITES below: sim-server, the ROS 2 family with real
// rclpy, the Python RTEs; each with pytest and its linters) and the pack-and-install test
// (scripts/pack-install.mjs), prints a table of its stages (wall and CPU time), and closes with
//   failures: <every kind of failure, counted and named>     (only when something failed)
//   tests: N passed, N failed, N skipped
// where "failed" counts every failure of every kind (failed tests, unhandled errors, test files
// that did not run, failed hooks, setups, linters, runners that wrote no report), and the exit
// code is 0 exactly when that number is 0 and some test passed.
// Installs no npm packages: run `npm ci` first (the README's test command does).
// Two lanes run side by side to use both cores of a small machine: the main lane builds (two
// workspaces at a time in the order of their dependencies, scripts/build-graph.mjs), then runs
// Vitest (two workers, or one less than the cores on a bigger machine) and then the e2e suite,
// printing as it goes; the side lane sets up the venvs and the Debian packages and runs the
// linters while the build runs, then the Python suites and the pack-and-install test (each
// stage's output is printed when it ends). MAA_TEST_SERIAL=1 runs every stage one after the other.
// Extra arguments go to Vitest, e.g. `npm test -- packages/cli`; MAA_TEST_PYTHON=0 skips the
// Python suites except ROS 2, MAA_TEST_ROS2=0 skips ROS 2, MAA_TEST_E2E=0 the browser tests,
// MAA_TEST_BUILD=0 the build (for a tree that is built already), MAA_TEST_LINT=0 the linters,
// MAA_TEST_PACK=0 the pack-and-install test.
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { availableParallelism, tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { runGraph, workspaceGraph } from './build-graph.mjs';
import { junitCounts, parseTimes, stageTable, Tally } from './test-summary.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const npx = process.platform === 'win32' ? 'npx.cmd' : 'npx';
const started = Date.now();
const machineAtStart = machineBusyMs();
const serial = process.env.MAA_TEST_SERIAL === '1';
const enabled = (name) => process.env[name] !== '0';

const tally = new Tally();

/** Each stage run: its title, when it started, its wall time and the CPU time (user + sys) of the processes it ran. */
const stages = [];

// A stage runs under bash, whose `times` (written to fd 3) gives the CPU time of the processes it
// waited for: the stage's command and every descendant reaped along the way.
const TIMED = '"$@"; status=$?; times >&3; exit $status';

/**
 * Runs a command under bash's `times` and resolves to its exit status, its CPU time and, with
 * `capture`, its output (else it goes to this process's stdout and stderr).
 */
function runTimed(command, args, { cwd = repo, env = process.env, capture = false } = {}) {
    return new Promise((resolve) => {
        const output = [];
        const times = [];
        const child = spawn('bash', ['-c', TIMED, 'bash', command, ...args], {
            cwd,
            env,
            stdio: [capture ? 'ignore' : 'inherit', capture ? 'pipe' : 'inherit', capture ? 'pipe' : 'inherit', 'pipe'],
        });
        if (capture) {
            child.stdout.on('data', (chunk) => output.push(chunk));
            child.stderr.on('data', (chunk) => output.push(chunk));
        }
        child.stdio[3].on('data', (chunk) => times.push(chunk));
        child.on('error', (error) => output.push(Buffer.from(`test-all: could not start ${command}: ${error.message}\n`)));
        child.on('close', (code) =>
            resolve({ code: code ?? 1, output: Buffer.concat(output).toString(), cpuMs: parseTimes(Buffer.concat(times).toString()) }),
        );
    });
}

/** Records a stage for the closing table and prints its closing line. */
function stageDone(title, begun, code, cpuMs) {
    const stage = { title, startMs: begun - started, wallMs: Date.now() - begun, cpuMs };
    stages.push(stage);
    const cpu = cpuMs === undefined ? '' : `, ${(cpuMs / 1000).toFixed(1)} s CPU`;
    return `=== ${title}: exit ${code} after ${(stage.wallMs / 1000).toFixed(1)} s${cpu}\n`;
}

/**
 * Runs one stage and resolves to its exit status. The main lane's output goes straight to the
 * terminal; a side stage's (`side: true`) is kept and printed in one piece when it ends, so that
 * the two lanes do not interleave line by line.
 */
async function step(title, command, args, { cwd = repo, env = process.env, side = false } = {}) {
    const banner = `\n=== ${title}: ${[command, ...args].join(' ')}\n`;
    if (!side) process.stdout.write(banner);
    const begun = Date.now();
    const { code, output, cpuMs } = await runTimed(command, args, { cwd, env, capture: side });
    const done = stageDone(title, begun, code, cpuMs);
    process.stdout.write(side ? `${banner}${output}${done}` : `${output}${done}`);
    return code;
}

/** The workspaces built so far, and who waits for one (whenBuilt). */
const built = { dirs: new Set(), over: false, waiting: [] };

/**
 * Resolves to true once `dir` is built (without `dir`: once the whole build succeeded), to false
 * when the build ended without it; true at once when MAA_TEST_BUILD=0.
 */
function whenBuilt(dir) {
    const ready = () => (dir === undefined ? built.over && buildStatus === 0 : built.dirs.has(dir));
    if (!enabled('MAA_TEST_BUILD') || ready()) return Promise.resolve(true);
    if (built.over) return Promise.resolve(false);
    return new Promise((resolve) => built.waiting.push({ ready, resolve }));
}

/** Wakes the waiters of whenBuilt after a workspace was built, or the build ended. */
function wakeBuildWaiters() {
    built.waiting = built.waiting.filter(({ ready, resolve }) => {
        if (ready()) resolve(true);
        else if (built.over) resolve(false);
        else return true;
        return false;
    });
}

/**
 * The build: each workspace's `npm run build` as soon as those it depends on are built, as many
 * at once as there are cores (scripts/build-graph.mjs; one at a time with MAA_TEST_SERIAL=1).
 * Each workspace's output is printed when its build ends; the stage's CPU time is their sum.
 */
async function buildStage() {
    const jobs = serial ? 1 : Math.max(2, availableParallelism());
    process.stdout.write(`\n=== build: npm run build -w <workspace>, ${jobs} at a time in the order of their dependencies\n`);
    const begun = Date.now();
    let cpuMs = 0;
    let status;
    try {
        status = await runGraph(workspaceGraph(repo), {
            jobs,
            // the side lane's Python suites wait for maa-gen: among ready builds it goes first
            first: ['packages/cli'],
            run: async (dir) => {
                const from = Date.now();
                const r = await runTimed(npm, ['run', 'build', '-w', dir], { capture: true });
                cpuMs += r.cpuMs ?? 0;
                if (r.code === 0) {
                    built.dirs.add(dir);
                    wakeBuildWaiters();
                }
                const cpu = r.cpuMs === undefined ? '' : `, ${(r.cpuMs / 1000).toFixed(1)} s CPU`;
                process.stdout.write(
                    `\n--- build ${dir}\n${r.output}--- build ${dir}: exit ${r.code} after ${((Date.now() - from) / 1000).toFixed(1)} s${cpu}\n`,
                );
                return r.code;
            },
        });
    } catch (error) {
        // a workspace that depends on itself or on no workspace: no build started
        process.stdout.write(`test-all: cannot order the build: ${error.message}\n`);
        status = 1;
    }
    process.stdout.write(stageDone('build', begun, status, cpuMs));
    buildStatus = status; // before waking the waiters of the whole build
    built.over = true;
    wakeBuildWaiters();
    return status;
}

/** Prints what failed, by kind, and the closing line, and exits with the code that agrees with it. */
function finish() {
    stages.sort((a, b) => a.startMs - b.startMs);
    for (const line of stageTable(stages, Date.now() - started)) console.log(line);
    const machineAtEnd = machineBusyMs();
    if (machineAtStart !== undefined && machineAtEnd !== undefined) {
        // what every process on the machine used meanwhile, this run's and others' (a shared machine)
        const busy = (machineAtEnd - machineAtStart) / 1000;
        const capacity = ((Date.now() - started) / 1000) * availableParallelism();
        console.log(
            `test-all: the machine's ${availableParallelism()} cores were busy ${busy.toFixed(0)} s of ${capacity.toFixed(0)} s meanwhile`,
        );
    }
    for (const line of tally.summary((Date.now() - started) / 60_000)) console.log(line);
    process.exit(tally.exitCode);
}

/** CPU time every process of the machine has used since boot (Linux: /proc/stat), in ms; undefined elsewhere. */
function machineBusyMs() {
    try {
        const [user, nice, system, , , irq, softirq, steal] = readFileSync('/proc/stat', 'utf8')
            .split('\n')[0]
            .trim()
            .split(/\s+/)
            .slice(1)
            .map(Number);
        return ((user + nice + system + irq + softirq + (steal ?? 0)) * 1000) / 100; // USER_HZ is 100 on Linux
    } catch {
        return undefined;
    }
}

/** Runs the lanes side by side, or one after the other with MAA_TEST_SERIAL=1. */
async function lanes(...runs) {
    if (serial) for (const run of runs) await run();
    else await Promise.all(runs.map((run) => run()));
}

if (!existsSync(path.join(repo, 'node_modules'))) {
    tally.fail('setups that failed', 'node_modules is missing; run "npm ci" first');
    finish();
}

// The Python suites: each sets up its venv (idempotent scripts), runs pytest (JUnit XML for the
// counts), then its linters; a failing linter counts as one failure.
const PYTHON_SUITES = [
    {
        // The simulation sidecar (MuJoCo, rclpy, rosbridge, viser).
        title: 'sim-server',
        enabled: enabled('MAA_TEST_PYTHON'),
        dir: 'sim-server',
        setup: 'sim-server/scripts/setup_env.sh',
        python: 'sim-server/.venv/bin/python',
        tests: 'sim-server/tests',
        // ruff (lint and format): scripts/lint.mjs
        lint: [['mypy', ['-m', 'mypy']]],
    },
    {
        // The ros2-python family with real ROS 2 (rclpy, the rosidl toolchain): generated code
        // compiles and is ruff-clean, the interface package builds, the ToastService nodes run, and
        // serve the toast in the simulator (maa-sim is installed into this venv by its setup script).
        title: 'ros2',
        enabled: enabled('MAA_TEST_ROS2'),
        dir: 'packages/generators-python',
        setup: 'packages/generators-python/scripts/setup_ros2_venv.sh',
        python: 'packages/generators-python/.venv-ros2/bin/python',
        tests: 'packages/generators-python/test/ros2',
        lint: [],
    },
    {
        // The Python generators' run-time environments (maa_behavior, maa_timesync).
        title: 'generators-python',
        enabled: enabled('MAA_TEST_PYTHON'),
        dir: 'packages/generators-python',
        setup: 'packages/generators-python/scripts/setup_venv.sh',
        python: 'packages/generators-python/.venv/bin/python',
        tests: 'packages/generators-python/test/python',
        lint: [], // ruff (lint and format): scripts/lint.mjs
    },
];

// The build beside the setups, then the tests. The venv setups run one after the other
// (sim-server's and the ROS 2 one both install sim-server editable, which writes into its source
// folder), as do the Debian packages (apt-get takes a lock). Vitest starts when the build and the
// setups are done, the e2e suite after it; the Python suites need only maa-gen (packages/cli)
// built and start as soon as it is, beside the rest of the build; the pack-and-install test needs
// the whole build. A failed build or setup stops the run there: no further test starts.
let buildStatus = 0;
/** The exit status of ensure-chromium (run with the setups). */
let chromiumStatus = 0;
let setupsOk = true;
const setupsDone = deferred();
if (serial) {
    if (enabled('MAA_TEST_BUILD')) buildStatus = await buildStage();
    setupsOk = await setupsAndLint();
    if (buildStatus === 0 && setupsOk) {
        await vitestSuite(process.argv.slice(2));
        await pythonSuites();
        await wholeBuildSuites();
    }
} else {
    await lanes(
        async () => {
            if (enabled('MAA_TEST_BUILD')) buildStatus = await buildStage();
            if (buildStatus === 0 && (await setupsDone.promise)) {
                await vitestSuite(process.argv.slice(2));
                // The e2e suite after Vitest, not beside it: its scenarios wait on a browser, the
                // language server and the simulator, and beside Vitest's workers on two cores they
                // timed out (a click, an editor opening) in a fresh-clone run.
                if (enabled('MAA_TEST_E2E')) await e2eSuite();
            }
        },
        async () => {
            setupsOk = await setupsAndLint();
            setupsDone.resolve(setupsOk);
            if (!setupsOk) return;
            if (await whenBuilt('packages/cli')) await pythonSuites();
            if ((await whenBuilt()) && enabled('MAA_TEST_PACK')) await packInstallSuite();
        },
    );
}
if (buildStatus !== 0) tally.fail('setups that failed', `the build exited with ${buildStatus}; the tests that need it did not run`);
finish();

/** A promise with its resolve function. */
function deferred() {
    let resolve;
    const promise = new Promise((r) => {
        resolve = r;
    });
    return { promise, resolve };
}

/** The venv and Debian package setups, then the linters (a finding counts as one failure, the tests run anyway); false when a setup failed. */
async function setupsAndLint() {
    const ok = await setups();
    // The house rules (scripts/lint.mjs: Biome for TypeScript/JavaScript, ruff for Python, lint and formatting).
    if (enabled('MAA_TEST_LINT')) {
        const lintStatus = await step('lint', process.execPath, [path.join(repo, 'scripts', 'lint.mjs')], { side: !serial });
        if (lintStatus !== 0) tally.fail('linters that failed', `npm run lint exited with ${lintStatus}`);
    }
    return ok;
}

async function pythonSuites() {
    for (const suite of PYTHON_SUITES.filter((x) => x.enabled)) await pythonSuite(suite);
}

/** The suites that use the whole build: the pack-and-install test and the e2e suite. */
async function wholeBuildSuites() {
    // The pack-and-install test (scripts/pack-install.mjs): the public packages packed, installed
    // into an empty folder outside the repository, and used there as a user would (one result per step).
    if (enabled('MAA_TEST_PACK')) await packInstallSuite();
    // The browser end-to-end suite (e2e/run.mjs): maa-ide with the built app on a fresh copy of
    // examples/, driven through playwright-core in Debian's chromium. Its results (one per
    // scenario) are in e2e/artifacts/results.json, screenshots beside them.
    if (enabled('MAA_TEST_E2E')) await e2eSuite();
}

/**
 * The venvs (Vitest uses sim-server's and the ROS 2 one too: the generated example runs in the
 * simulator, the IDE backend's ROS 2 session runs the generated nodes) and the Debian packages
 * some tests need; false when a venv setup failed (then no test is run).
 */
async function setups() {
    const side = !serial;
    for (const suite of PYTHON_SUITES.filter((x) => x.enabled)) {
        const status = await step(`${suite.title} setup`, 'bash', [path.join(repo, suite.setup)], { side });
        if (status !== 0) {
            tally.fail('setups that failed', `${suite.title} setup exited with ${status}; no test was run`);
            return false;
        }
    }
    // The lab server's storage tests run on PGlite and on a real PostgreSQL they start in a temporary
    // cluster (packages/lab-server/test/postgres-cluster.ts): Debian's postgresql is installed when missing.
    if ((await step('lab storage: postgresql', process.execPath, [path.join(repo, 'scripts', 'ensure-postgresql.mjs')], { side })) !== 0) {
        tally.fail('setups that failed', 'PostgreSQL for the lab storage tests is missing and could not be installed');
    }
    // maa_sim.sandbox (grading runs, the lab's live simulations; sim-server/tests/test_sandbox.py)
    // runs students' code in bubblewrap: Debian's bubblewrap is installed when missing.
    if ((await step('sandbox: bubblewrap', process.execPath, [path.join(repo, 'scripts', 'ensure-bubblewrap.mjs')], { side })) !== 0) {
        tally.fail('setups that failed', 'bubblewrap for the sandbox is missing and could not be installed');
    }
    if (enabled('MAA_TEST_E2E')) {
        chromiumStatus = await step('e2e: chromium', process.execPath, [path.join(repo, 'scripts', 'ensure-chromium.mjs')], { side });
    }
    return true;
}
/**
 * Vitest with the default reporter for people and scripts/vitest-outcome-reporter.mjs for the
 * counts: its outcome names failed tests, unhandled errors, test files that did not run and
 * failed hooks separately, which Vitest's own JSON report folds into a bare exit code.
 */
async function vitestSuite(extraArgs) {
    const outcomeDir = mkdtempSync(path.join(tmpdir(), 'maa-test-all-'));
    const outcomeFile = path.join(outcomeDir, 'vitest-outcome.json');
    // each test file's CPU time (scripts/vitest-file-cpu.mjs), for the list of the costliest files
    const cpuDir = path.join(outcomeDir, 'cpu');
    mkdirSync(cpuDir);
    const status = await step(
        'vitest',
        npx,
        [
            '--no-install',
            'vitest',
            'run',
            '--reporter=default',
            `--reporter=${path.join(repo, 'scripts', 'vitest-outcome-reporter.mjs')}`,
            ...extraArgs,
        ],
        { env: { ...process.env, MAA_VITEST_OUTCOME: outcomeFile, MAA_VITEST_CPU_DIR: cpuDir } },
    );
    let outcome;
    try {
        outcome = JSON.parse(readFileSync(outcomeFile, 'utf8'));
    } catch {
        outcome = undefined;
    } finally {
        rmSync(outcomeDir, { recursive: true, force: true });
    }
    if (!outcome) {
        tally.fail('runners that reported nothing', `vitest exited with ${status} and wrote no outcome`);
        return;
    }
    tally.passed += outcome.passed;
    tally.skipped += outcome.skipped;
    for (const what of outcome.failedTests) tally.fail('failed tests', what);
    for (const what of outcome.unhandledErrors) tally.fail('unhandled errors', `vitest: ${what}`);
    for (const what of outcome.brokenFiles) tally.fail('test files that did not run', what);
    for (const what of outcome.suiteErrors) tally.fail('failed hooks and suites', what);
    // Vitest failing for a reason none of the above names (e.g. no test file matched a filter).
    const named = outcome.failedTests.length + outcome.unhandledErrors.length + outcome.brokenFiles.length + outcome.suiteErrors.length;
    if (status !== 0 && named === 0) tally.fail('runners that failed without a reason', `vitest exited with ${status} (${outcome.reason})`);
    const seconds = (ms) => `${(ms / 1000).toFixed(1).padStart(6)} s`;
    if (outcome.slowestFiles.length > 0) {
        console.log('\ntest-all: the slowest Vitest files (hooks included):');
        for (const { file, ms } of outcome.slowestFiles) console.log(`  ${seconds(ms)}  ${file}`);
        console.log('test-all: the slowest Vitest tests:');
        for (const { test, ms } of outcome.slowest) console.log(`  ${seconds(ms)}  ${test}`);
    }
    if (outcome.cpu) {
        // what a 2-core machine runs out of: CPU, the file's worker and the processes it started
        const { files, ms, childrenMs } = outcome.cpu;
        console.log(
            `test-all: the Vitest files that used the most CPU (of ${seconds(ms).trim()} over ${files} files, ${seconds(childrenMs).trim()} in their child processes):`,
        );
        for (const f of outcome.costliestFiles) console.log(`  ${seconds(f.ms)}  ${f.file} (children ${seconds(f.childrenMs).trim()})`);
    }
}

async function pythonSuite(suite) {
    const side = !serial;
    const python = path.join(repo, suite.python);
    const junitDir = mkdtempSync(path.join(tmpdir(), `maa-test-all-${suite.title}-`));
    const junitFile = path.join(junitDir, 'pytest.xml');
    const pytestStatus = await step(
        `${suite.title} tests`,
        python,
        ['-m', 'pytest', suite.tests, '-q', '-p', 'no:cacheprovider', `--junitxml=${junitFile}`],
        { side },
    );
    let junit;
    try {
        junit = readFileSync(junitFile, 'utf8');
    } catch {
        junit = undefined;
    } finally {
        rmSync(junitDir, { recursive: true, force: true });
    }
    const counts = junit === undefined ? undefined : junitCounts(junit);
    if (!counts) {
        tally.fail('runners that reported nothing', `pytest (${suite.title}) exited with ${pytestStatus} and wrote no report`);
    } else {
        tally.passed += counts.passed;
        tally.skipped += counts.skipped;
        for (const what of counts.failed) tally.fail('failed tests', `${suite.title}: ${what}`);
        for (const what of counts.errors) tally.fail('test errors outside a test body', `${suite.title}: ${what}`);
        if (pytestStatus !== 0 && counts.failed.length + counts.errors.length === 0) {
            tally.fail('runners that failed without a reason', `pytest (${suite.title}) exited with ${pytestStatus}`);
        }
    }
    for (const [name, args] of suite.lint) {
        const lintStatus = await step(`${suite.title} ${name}`, python, args, { cwd: path.join(repo, suite.dir), side });
        if (lintStatus !== 0) tally.fail('linters that failed', `${suite.title} ${name} exited with ${lintStatus}`);
    }
}

async function packInstallSuite() {
    const resultsDir = mkdtempSync(path.join(tmpdir(), 'maa-test-all-pack-'));
    const resultsFile = path.join(resultsDir, 'results.json');
    const status = await step(
        'pack and install',
        process.execPath,
        [path.join(repo, 'scripts', 'pack-install.mjs'), '--results', resultsFile],
        {
            side: !serial,
        },
    );
    let results;
    try {
        results = JSON.parse(readFileSync(resultsFile, 'utf8')).results;
    } catch {
        tally.fail('runners that reported nothing', `the pack-and-install test exited with ${status} and wrote no results`);
        return;
    } finally {
        rmSync(resultsDir, { recursive: true, force: true });
    }
    for (const r of results) {
        if (r.skipped) tally.skipped += 1;
        else if (r.ok) tally.passed += 1;
        else tally.fail('failed tests', `pack-install: ${r.name}: ${String(r.error ?? '').split('\n')[0]}`);
    }
    if (status !== 0 && results.every((r) => r.ok))
        tally.fail('runners that failed without a reason', `the pack-and-install test exited with ${status}`);
}

async function e2eSuite() {
    if (chromiumStatus !== 0) {
        tally.fail('setups that failed', 'chromium for the e2e tests is missing and could not be installed');
        return;
    }
    const resultsFile = path.join(repo, 'e2e', 'artifacts', 'results.json');
    rmSync(resultsFile, { force: true });
    const status = await step('e2e', process.execPath, [path.join(repo, 'e2e', 'run.mjs')]); // the main lane, after Vitest
    let results;
    try {
        results = JSON.parse(readFileSync(resultsFile, 'utf8'));
    } catch {
        tally.fail('runners that reported nothing', `the e2e run exited with ${status} and wrote no results`);
        return;
    }
    for (const r of results) {
        if (r.ok) tally.passed += 1;
        else tally.fail('failed tests', `e2e: ${r.name}: ${String(r.error ?? '').split('\n')[0]}`);
    }
    if (status !== 0 && results.every((r) => r.ok)) tally.fail('runners that failed without a reason', `the e2e run exited with ${status}`);
    // the e2e checks that run on their own pages, outside the IDE's scenario runner (e2e/run.mjs)
    for (const script of ['vscode-diagram-webview.mjs', 'vscode-simulate.mjs', 'lab-dashboard.mjs', 'lab-ide.mjs']) {
        // each is one test: it prints its checks and exits 0 only when all pass
        if ((await step(`e2e: ${script}`, process.execPath, [path.join(repo, 'e2e', script)])) === 0) tally.passed += 1;
        else tally.fail('failed tests', `e2e: ${script} (its checks are printed above)`);
    }
}
