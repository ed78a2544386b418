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
        // With MAA_VITEST_CPU_DIR set (npm test sets it), each test file records the CPU time of its
        // worker and of the processes it started: the slowest files by CPU in npm test's summary.
        setupFiles: ['scripts/vitest-file-cpu.mjs'],
    },
});
