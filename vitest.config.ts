import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';

// One Vitest run over every package of the workspace (`npm test` builds first, see
// scripts/test-all.mjs). Tests of the CLI start the built `maa-gen` as a child process.
export default defineConfig({
    test: {
        include: ['packages/*/test/**/*.test.ts', 'scripts/test/**/*.test.ts'],
        exclude: ['**/node_modules/**', '**/dist/**'],
        testTimeout: 120_000,
        hookTimeout: 120_000,
        // Vitest's default is one worker less than the cores: one on a 2-core machine. Most test
        // files wait on child processes (maa-gen, the simulator, servers) for much of their time,
        // so two files at once fit two cores (docs/testing.md, Where the time goes).
        maxWorkers: Math.max(2, availableParallelism() - 1),
        // A worker process runs test file after test file without loading their modules again
        // (Langium, the language services, the servers, Vite's transforms of the sources): with
        // Vitest's default, a fresh process per file, loading took most of a file's CPU
        // (docs/testing.md, Where the time goes). A file that changes what the process shares
        // (environment variables, spies, globals) restores it in its own afterEach/afterAll;
        // Vitest itself restores spies and, per file, the test environment (happy-dom). A worker
        // keeps the modules as it first loaded them: a package rebuilt while Vitest runs (or a
        // module that failed to load) stays so for the worker's later files; `--isolate` runs
        // each file in a fresh process again.
        isolate: false,
        // With MAA_VITEST_CPU_DIR set (npm test sets it), each test file records the CPU time of its
        // worker and of the processes it started: the slowest files by CPU in npm test's summary.
        setupFiles: ['scripts/vitest-file-cpu.mjs'],
    },
});
