#!/usr/bin/env node
// `npm test`: builds every workspace package, then runs every Vitest suite of the workspace
// (vitest.config.ts at the root), then the simulation sidecar's Python tests (sim-server/: its
// setup script creates sim-server/.venv when needed, then pytest, ruff and mypy), and closes with
// one line "tests: N passed, N failed, N skipped" counting both.
// Installs no npm packages: run `npm ci` first (the README's test command does).
// Extra arguments go to Vitest, e.g. `npm test -- packages/cli`; MAA_TEST_PYTHON=0 skips sim-server
// and the Python generators' RTE tests (packages/generators-python/test/python).
// The ros2-python family's tests (packages/generators-python/test/ros2: real ROS 2 in its .venv-ros2)
// run too; MAA_TEST_ROS2=0 skips them.
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

// The simulation sidecar (Python): set up its venv, run pytest (JUnit XML for the counts), lint.
if (process.env.MAA_TEST_PYTHON !== '0') {
  const python = simPython();
  passed += python.passed;
  failed += python.failed;
  skipped += python.skipped;
  if (python.failed > 0 || python.passed === 0) code = code || 1;
}
// The ros2-python generator family (packages/generators-python): its venv with real ROS 2 (rclpy
// and the rosidl toolchain), then pytest over test/ros2 (generated code compiles and is ruff-clean,
// the interface package builds, the ToastService nodes run on ROS 2). MAA_TEST_ROS2=0 skips it.
if (process.env.MAA_TEST_ROS2 !== '0') {
  const ros2 = ros2Python();
  passed += ros2.passed;
  failed += ros2.failed;
  skipped += ros2.skipped;
  if (ros2.failed > 0 || ros2.passed === 0) code = code || 1;
}
// The Python generators' run-time environments (packages/generators-python: maa_behavior,
// maa_timesync): their venv (pytest, ruff), pytest over test/python, ruff. MAA_TEST_PYTHON=0 skips it.
if (process.env.MAA_TEST_PYTHON !== '0') {
  const timesync = timesyncPython();
  passed += timesync.passed;
  failed += timesync.failed;
  skipped += timesync.skipped;
  if (timesync.failed > 0 || timesync.passed === 0) code = code || 1;
}
finish(code, `tests: ${passed} passed, ${failed} failed, ${skipped} skipped`);

function simPython() {
  const simDir = path.join(repo, 'sim-server');
  const setupStatus = step('sim-server setup', 'bash', [path.join(simDir, 'scripts', 'setup_env.sh')]);
  if (setupStatus !== 0) {
    console.error(`test-all: FAILED: sim-server setup exited with ${setupStatus}; no Python test was run`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  const venvPython = path.join(simDir, '.venv', 'bin', 'python');
  const junitDir = mkdtempSync(path.join(tmpdir(), 'maa-test-all-py-'));
  const junitFile = path.join(junitDir, 'pytest.xml');
  const pytestStatus = step('sim-server tests', venvPython, [
    '-m', 'pytest', 'sim-server/tests', '-q', '-p', 'no:cacheprovider', `--junitxml=${junitFile}`,
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
    console.error(`test-all: FAILED: pytest exited with ${pytestStatus} and wrote no report`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  if (pytestStatus !== 0 && counts.failed === 0) counts.failed = 1; // e.g. an error outside any test
  // Lint failures count as one failed check each.
  for (const [title, args] of [
    ['sim-server ruff', ['-m', 'ruff', 'check', '.']],
    ['sim-server mypy', ['-m', 'mypy']],
  ]) {
    const lintStatus = step(title, venvPython, args, simDir);
    if (lintStatus !== 0) {
      console.error(`test-all: FAILED: ${title} exited with ${lintStatus}`);
      counts.failed += 1;
    }
  }
  return counts;
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

function ros2Python() {
  const pkgDir = path.join(repo, 'packages', 'generators-python');
  const setupStatus = step('ros2 setup', 'bash', [path.join(pkgDir, 'scripts', 'setup_ros2_venv.sh')]);
  if (setupStatus !== 0) {
    console.error(`test-all: FAILED: ros2 venv setup exited with ${setupStatus}; no ROS 2 test was run`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  const junitDir = mkdtempSync(path.join(tmpdir(), 'maa-test-all-ros2-'));
  const junitFile = path.join(junitDir, 'pytest.xml');
  const pytestStatus = step('ros2 tests', path.join(pkgDir, '.venv-ros2', 'bin', 'python'), [
    '-m', 'pytest', 'packages/generators-python/test/ros2', '-q', '-p', 'no:cacheprovider', `--junitxml=${junitFile}`,
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
    console.error(`test-all: FAILED: pytest (ros2) exited with ${pytestStatus} and wrote no report`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  if (pytestStatus !== 0 && counts.failed === 0) counts.failed = 1;
  return counts;
}

function timesyncPython() {
  const pkgDir = path.join(repo, 'packages', 'generators-python');
  const setupStatus = step('generators-python setup', 'bash', [path.join(pkgDir, 'scripts', 'setup_venv.sh')]);
  if (setupStatus !== 0) {
    console.error(`test-all: FAILED: generators-python venv setup exited with ${setupStatus}; no Python test was run`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  const venvPython = path.join(pkgDir, '.venv', 'bin', 'python');
  const junitDir = mkdtempSync(path.join(tmpdir(), 'maa-test-all-timesync-'));
  const junitFile = path.join(junitDir, 'pytest.xml');
  const pytestStatus = step('generators-python tests', venvPython, [
    '-m', 'pytest', 'packages/generators-python/test/python', '-q', '-p', 'no:cacheprovider', `--junitxml=${junitFile}`,
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
    console.error(`test-all: FAILED: pytest (generators-python) exited with ${pytestStatus} and wrote no report`);
    return { passed: 0, failed: 1, skipped: 0 };
  }
  if (pytestStatus !== 0 && counts.failed === 0) counts.failed = 1;
  const ruffStatus = step('generators-python ruff', venvPython, [
    '-m', 'ruff', 'check', '--config', 'ruff.toml', '--no-cache', 'rte/maa_behavior', 'rte/maa_timesync', 'test/python',
  ], pkgDir);
  if (ruffStatus !== 0) {
    console.error(`test-all: FAILED: generators-python ruff exited with ${ruffStatus}`);
    counts.failed += 1;
  }
  return counts;
}
