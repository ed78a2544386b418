#!/usr/bin/env node
// `npm test`: builds every workspace package, sets up the simulator's venv (Vitest uses it), runs
// every Vitest suite of the workspace (vitest.config.ts at the root), the browser end-to-end
// suite (e2e/), then the Python suites
// (PYTHON_SUITES below: sim-server, the ROS 2 family with real rclpy, the Python RTEs; each with
// its own idempotent venv setup, pytest and linters), and closes with one line
// "tests: N passed, N failed, N skipped" counting everything.
// Installs no npm packages: run `npm ci` first (the README's test command does).
// Extra arguments go to Vitest, e.g. `npm test -- packages/cli`; MAA_TEST_PYTHON=0 skips the
// Python suites except ROS 2, MAA_TEST_ROS2=0 skips ROS 2, MAA_TEST_E2E=0 the browser tests.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const npx = process.platform === 'win32' ? 'npx.cmd' : 'npx';

function step(title, command, args, cwd = repo) {
  console.log(`\n=== ${title}: ${[command, ...args].join(' ')}`);
  const result = spawnSync(command, args, { cwd, stdio: 'inherit' });
  if (result.error) {
    console.error(`test-all: could not start ${command}: ${result.error.message}`);
    return 1;
  }
  return result.status ?? 1;
}

function finish(code, line) {
  console.log(`\n${line}`);
  process.exit(code);
}

if (!existsSync(path.join(repo, 'node_modules'))) {
  finish(2, 'test-all: FAILED: node_modules is missing; run "npm ci" first');
}

const buildStatus = step('build', npm, ['run', 'build']);
if (buildStatus !== 0) {
  finish(buildStatus, `test-all: FAILED: the build failed (exit ${buildStatus}); no test was run`);
}

// Some Vitest suites use the simulator (the generated example runs in it), so its Python
// environment is set up before Vitest; the setup script is idempotent and fast when up to date.
if (process.env.MAA_TEST_PYTHON !== '0') {
  const simSetup = step('sim-server setup (used by Vitest too)', 'bash', [path.join(repo, 'sim-server', 'scripts', 'setup_env.sh')]);
  if (simSetup !== 0) {
    finish(simSetup, `test-all: FAILED: sim-server setup exited with ${simSetup}; no test was run`);
  }
}

// The IDE backend's ROS 2 session test runs the generated nodes from the ROS 2 venv.
if (process.env.MAA_TEST_ROS2 !== '0') {
  const ros2Setup = step('ROS 2 venv setup (used by Vitest too)', 'bash', [path.join(repo, 'packages', 'generators-python', 'scripts', 'setup_ros2_venv.sh')]);
  if (ros2Setup !== 0) {
    finish(ros2Setup, `test-all: FAILED: the ROS 2 venv setup exited with ${ros2Setup}; no test was run`);
  }
}

const reportDir = mkdtempSync(path.join(tmpdir(), 'maa-test-all-'));
const reportFile = path.join(reportDir, 'vitest.json');
const testStatus = step('test', npx, [
  '--no-install',
  'vitest',
  'run',
  '--reporter=default',
  '--reporter=json',
  `--outputFile.json=${reportFile}`,
  ...process.argv.slice(2),
]);
let report;
try {
  report = JSON.parse(readFileSync(reportFile, 'utf8'));
} catch {
  report = undefined;
} finally {
  rmSync(reportDir, { recursive: true, force: true });
}
if (!report) {
  finish(testStatus || 1, `test-all: FAILED: vitest exited with ${testStatus} and wrote no report`);
}
let passed = report.numPassedTests ?? 0;
// A test file that fails to load has no failed test, only a failed suite: count it too.
const failedTests = report.numFailedTests ?? 0;
let failed = failedTests > 0 ? failedTests : (report.numFailedTestSuites ?? 0);
let skipped = (report.numPendingTests ?? 0) + (report.numTodoTests ?? 0);
let code = testStatus !== 0 ? testStatus : failed > 0 || passed === 0 ? 1 : 0;
if (passed === 0 && failed === 0) console.log('test-all: no vitest test was run');

// The browser end-to-end suite (e2e/run.mjs): maa-ide with the built app on a fresh copy of
// examples/, driven through playwright-core in Debian's chromium (installed here when missing).
// Its results (one per scenario) are in e2e/artifacts/results.json, screenshots beside them.
if (process.env.MAA_TEST_E2E !== '0') {
  const counts = e2eSuite();
  passed += counts.passed;
  failed += counts.failed;
  if (counts.failed > 0 || counts.passed === 0) code = code || 1;
}

// The Python suites: each sets up its venv (idempotent scripts), runs pytest (JUnit XML for the
// counts), then its linters; a failing linter counts as one failed check.
const PYTHON_SUITES = [
  {
    // The simulation sidecar (MuJoCo, rclpy, rosbridge, viser).
    title: 'sim-server', enabled: process.env.MAA_TEST_PYTHON !== '0', dir: 'sim-server',
    setup: 'sim-server/scripts/setup_env.sh', python: 'sim-server/.venv/bin/python', tests: 'sim-server/tests',
    lint: [['ruff', ['-m', 'ruff', 'check', '.']], ['mypy', ['-m', 'mypy']]],
  },
  {
    // The ros2-python family with real ROS 2 (rclpy, the rosidl toolchain): generated code
    // compiles and is ruff-clean, the interface package builds, the ToastService nodes run, and
    // serve the toast in the simulator (maa-sim is installed into this venv by its setup script).
    title: 'ros2', enabled: process.env.MAA_TEST_ROS2 !== '0', dir: 'packages/generators-python',
    setup: 'packages/generators-python/scripts/setup_ros2_venv.sh', python: 'packages/generators-python/.venv-ros2/bin/python',
    tests: 'packages/generators-python/test/ros2', lint: [],
  },
  {
    // The Python generators' run-time environments (maa_behavior, maa_timesync).
    title: 'generators-python', enabled: process.env.MAA_TEST_PYTHON !== '0', dir: 'packages/generators-python',
    setup: 'packages/generators-python/scripts/setup_venv.sh', python: 'packages/generators-python/.venv/bin/python',
    tests: 'packages/generators-python/test/python',
    lint: [['ruff', ['-m', 'ruff', 'check', '--config', 'ruff.toml', '--no-cache', 'rte/maa_behavior', 'rte/maa_timesync', 'test/python']]],
  },
];
for (const suite of PYTHON_SUITES.filter((x) => x.enabled)) {
  const counts = pythonSuite(suite);
  passed += counts.passed;
  failed += counts.failed;
  skipped += counts.skipped;
  if (counts.failed > 0 || counts.passed === 0) code = code || 1;
}
finish(code, `tests: ${passed} passed, ${failed} failed, ${skipped} skipped`);

function pythonSuite(suite) {
  const setupStatus = step(`${suite.title} setup`, 'bash', [path.join(repo, suite.setup)]);
  if (setupStatus !== 0) {
    console.error(`test-all: FAILED: ${suite.title} setup exited with ${setupStatus}; none of its tests was run`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  const python = path.join(repo, suite.python);
  const junitDir = mkdtempSync(path.join(tmpdir(), `maa-test-all-${suite.title}-`));
  const junitFile = path.join(junitDir, 'pytest.xml');
  const pytestStatus = step(`${suite.title} tests`, python, [
    '-m', 'pytest', suite.tests, '-q', '-p', 'no:cacheprovider', `--junitxml=${junitFile}`,
  ]);
  let counts;
  try {
    counts = junitCounts(readFileSync(junitFile, 'utf8'));
  } catch {
    counts = undefined;
  } finally {
    rmSync(junitDir, { recursive: true, force: true });
  }
  if (!counts) {
    console.error(`test-all: FAILED: pytest (${suite.title}) exited with ${pytestStatus} and wrote no report`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  if (pytestStatus !== 0 && counts.failed === 0) counts.failed = 1; // e.g. an error outside any test
  for (const [name, args] of suite.lint) {
    const lintStatus = step(`${suite.title} ${name}`, python, args, path.join(repo, suite.dir));
    if (lintStatus !== 0) {
      console.error(`test-all: FAILED: ${suite.title} ${name} exited with ${lintStatus}`);
      counts.failed += 1;
    }
  }
  return counts;
}

function e2eSuite() {
  const chromium = step('e2e: chromium', process.execPath, [path.join(repo, 'scripts', 'ensure-chromium.mjs')]);
  if (chromium !== 0) {
    console.error('test-all: FAILED: chromium for the e2e tests is missing and could not be installed');
    return { passed: 0, failed: 1 };
  }
  const resultsFile = path.join(repo, 'e2e', 'artifacts', 'results.json');
  rmSync(resultsFile, { force: true });
  const status = step('e2e', process.execPath, [path.join(repo, 'e2e', 'run.mjs')]);
  let results;
  try {
    results = JSON.parse(readFileSync(resultsFile, 'utf8'));
  } catch {
    console.error(`test-all: FAILED: the e2e run exited with ${status} and wrote no results`);
    return { passed: 0, failed: 1 };
  }
  const failedScenarios = results.filter((r) => !r.ok).length;
  return { passed: results.length - failedScenarios, failed: failedScenarios || (status !== 0 ? 1 : 0) };
}

function junitCounts(xml) {
  // pytest writes <testsuites><testsuite name="pytest" errors= failures= skipped= tests=>
  const suite = /<testsuite\b([^>]*)>/.exec(xml);
  if (!suite) return undefined;
  const attribute = (name) => Number((new RegExp(`\\b${name}="(\\d+)"`).exec(suite[1]) ?? [])[1] ?? 0);
  const tests = attribute('tests');
  const failures = attribute('failures') + attribute('errors');
  const skippedTests = attribute('skipped');
  return { passed: tests - failures - skippedTests, failed: failures, skipped: skippedTests };
}
