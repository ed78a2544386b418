// The test helpers that need none of the server's modules: a test of the built bin
// (cli.test.ts) imports these alone, so Vitest does not transform the server's source for it.
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');

/** The token of every test server (startSite passes it; tests that start servers themselves do too). */
export const TEST_TOKEN = 'test-token-0123456789abcdef';

/** Waits until `check` holds, polling; fails after a bound generous for a loaded machine. */
export async function until(check: () => boolean | Promise<boolean>, what: string, boundMs = 60_000): Promise<void> {
    const deadline = Date.now() + boundMs;
    while (!(await check())) {
        if (Date.now() > deadline) throw new Error(`not within ${boundMs / 1000} s: ${what}`);
        await new Promise((r) => setTimeout(r, 100));
    }
}
