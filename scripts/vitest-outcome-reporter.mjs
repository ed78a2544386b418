// A Vitest reporter for scripts/test-all.mjs: writes the run's outcome to the JSON file named by
// MAA_VITEST_OUTCOME, with every kind of failure counted on its own, because Vitest's JSON
// reporter leaves two of them out of its numbers: errors outside any test ("unhandled errors",
// e.g. `[vitest-worker]: Timeout calling "onTaskUpdate"`) and test files that never ran their
// tests (an import that throws, a worker that died). The slowest tests are listed with their
// durations so that the closing summary can show what the suite's time is spent on.
import { readdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';

const SLOWEST = 10;

/** @param {{ message?: string, name?: string } | undefined} error */
function describe(error) {
    if (!error) return 'unknown error';
    const name = error.name && !String(error.message ?? '').startsWith(error.name) ? `${error.name}: ` : '';
    return `${name}${String(error.message ?? error).split('\n')[0]}`;
}

export default class OutcomeReporter {
    onInit(vitest) {
        this.root = vitest.config.root;
    }

    /**
     * @param {ReadonlyArray<import('vitest/node').TestModule>} modules
     * @param {ReadonlyArray<{ message?: string, name?: string }>} unhandledErrors
     * @param {'passed' | 'interrupted' | 'failed'} reason
     */
    onTestRunEnd(modules, unhandledErrors, reason) {
        const target = process.env.MAA_VITEST_OUTCOME;
        if (!target) return;
        const outcome = {
            reason,
            passed: 0,
            skipped: 0,
            failedTests: [],
            /** Test files whose tests did not run (load error, crashed worker, never started). */
            brokenFiles: [],
            /** beforeAll/afterAll hooks and suites that failed outside any single test. */
            suiteErrors: [],
            unhandledErrors: unhandledErrors.map(describe),
            slowest: [],
            /** Test files by their whole time (hooks included: a beforeAll that generates and runs code). */
            slowestFiles: [],
            /**
             * Test files by CPU time (ms): their worker's and that of the processes it started, as
             * scripts/vitest-file-cpu.mjs records them when MAA_VITEST_CPU_DIR is set; the total
             * over every file that recorded, and how many did.
             */
            costliestFiles: [],
            cpu: undefined,
        };
        const durations = [];
        const fileDurations = [];
        for (const module of modules) {
            const file = path.relative(this.root ?? process.cwd(), module.moduleId);
            const state = module.state();
            let ran = 0;
            for (const test of module.children.allTests()) {
                const result = test.result();
                if (result.state === 'passed') outcome.passed += 1;
                else if (result.state === 'skipped') outcome.skipped += 1;
                else if (result.state === 'failed') outcome.failedTests.push(`${file} > ${test.fullName}: ${describe(result.errors?.[0])}`);
                else outcome.failedTests.push(`${file} > ${test.fullName}: did not finish (${result.state})`);
                if (result.state !== 'skipped') ran += 1;
                const duration = test.diagnostic()?.duration;
                if (typeof duration === 'number') durations.push({ test: `${file} > ${test.fullName}`, ms: Math.round(duration) });
            }
            const fileDuration = module.diagnostic()?.duration;
            if (typeof fileDuration === 'number') fileDurations.push({ file, ms: Math.round(fileDuration) });
            const moduleErrors = module.errors();
            if (state === 'queued' || state === 'pending') {
                outcome.brokenFiles.push(`${file}: did not start or finish (${state})`);
            } else if (moduleErrors.length > 0 && ran === 0) {
                outcome.brokenFiles.push(`${file}: ${describe(moduleErrors[0])}`);
            } else if (moduleErrors.length > 0) {
                outcome.suiteErrors.push(`${file}: ${describe(moduleErrors[0])}`);
            }
            for (const suite of module.children.allSuites()) {
                for (const error of suite.errors()) outcome.suiteErrors.push(`${file} > ${suite.fullName}: ${describe(error)}`);
            }
        }
        outcome.slowest = durations.sort((a, b) => b.ms - a.ms).slice(0, SLOWEST);
        outcome.slowestFiles = fileDurations.sort((a, b) => b.ms - a.ms).slice(0, SLOWEST);
        const cpu = fileCpu(process.env.MAA_VITEST_CPU_DIR, this.root ?? process.cwd());
        if (cpu.length > 0) {
            outcome.costliestFiles = cpu.sort((a, b) => b.ms - a.ms).slice(0, SLOWEST);
            outcome.cpu = {
                files: cpu.length,
                ms: cpu.reduce((sum, f) => sum + f.ms, 0),
                childrenMs: cpu.reduce((sum, f) => sum + f.childrenMs, 0),
            };
        }
        writeFileSync(target, JSON.stringify(outcome, null, 2));
    }
}

/** The records of scripts/vitest-file-cpu.mjs: per test file, its worker's CPU time and its children's (ms). */
function fileCpu(dir, root) {
    if (!dir) return [];
    let names;
    try {
        names = readdirSync(dir).filter((name) => name.endsWith('.json'));
    } catch {
        return [];
    }
    const files = [];
    for (const name of names) {
        try {
            const record = JSON.parse(readFileSync(`${dir}/${name}`, 'utf8'));
            const childrenMs = record.childrenMs ?? 0;
            files.push({ file: path.relative(root, record.file), ms: record.selfMs + childrenMs, childrenMs });
        } catch {
            // a record cut short (its worker killed while writing): left out
        }
    }
    return files;
}
