#!/usr/bin/env node
// `npm test`: builds every workspace package, then runs every Vitest suite of the workspace
// (vitest.config.ts at the root), and closes with one line "tests: N passed, N failed, N skipped".
// Installs nothing: run `npm ci` first (the README's test command does).
// Extra arguments go to Vitest, e.g. `npm test -- packages/cli`.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const npm = process.platform === 'win32' ? 'npm.cmd' : 'npm';
const npx = process.platform === 'win32' ? 'npx.cmd' : 'npx';

function step(title, command, args) {
  console.log(`\n=== ${title}: ${[command, ...args].join(' ')}`);
  const result = spawnSync(command, args, { cwd: repo, stdio: 'inherit' });
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
const passed = report.numPassedTests ?? 0;
// A test file that fails to load has no failed test, only a failed suite: count it too.
const failedTests = report.numFailedTests ?? 0;
const failed = failedTests > 0 ? failedTests : (report.numFailedTestSuites ?? 0);
const skipped = (report.numPendingTests ?? 0) + (report.numTodoTests ?? 0);
if (passed === 0 && failed === 0) console.log('test-all: no test was run');
const code = testStatus !== 0 ? testStatus : failed > 0 || passed === 0 ? 1 : 0;
finish(code, `tests: ${passed} passed, ${failed} failed, ${skipped} skipped`);
