import { defineConfig } from 'vitest/config';

// One Vitest run over every package of the workspace (`npm test` builds first, see
// scripts/test-all.mjs). Tests of the CLI start the built `maa-gen` as a child process.
export default defineConfig({
    test: {
        include: ['packages/*/test/**/*.test.ts', 'scripts/test/**/*.test.ts'],
        exclude: ['**/node_modules/**', '**/dist/**'],
        testTimeout: 120_000,
        hookTimeout: 120_000,
    },
});
