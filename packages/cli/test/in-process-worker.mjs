// The worker thread behind runCliInProcess (helpers.ts): runs the built maa-gen's main() with a
// captured CliIo for each request, in one Node thread that stays up for the whole test file. The
// language services are imported once and warm, so a command costs milliseconds instead of a
// cold process each (about a second of CPU for a check, three for a diagram). Node loads the
// built modules itself (not through Vitest's transform), and the checks run off the thread that
// talks to Vitest.
import { parentPort } from 'node:worker_threads';

const { main, CapturedIo } = await import(new URL('../dist/main.js', import.meta.url).href);

parentPort.on('message', async ({ id, args, cwd, env }) => {
    // the pipes of runCli: not terminals
    const io = new CapturedIo(cwd, env);
    try {
        const code = await main(['node', 'maa-gen', ...args], io);
        parentPort.postMessage({ id, code, stdout: io.stdout, stderr: io.stderr });
    } catch (error) {
        // main() catches everything a command throws; this would be a bug of the runner itself
        parentPort.postMessage({ id, error: error instanceof Error ? (error.stack ?? error.message) : String(error) });
    }
});
