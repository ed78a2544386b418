// The Node side of warm_maa_gen.py: runs the built maa-gen's main() for each JSON line on stdin
// ({"args": [...], "cwd": "..."}) with a captured CliIo, and answers one JSON line on stdout
// ({"code", "stdout", "stderr"}). One process for a whole pytest session: the language services
// are loaded once, so a `maa-gen generate` costs about half a second of CPU instead of the two
// of a cold process (the CLI's own tests do the same in a worker thread: runCliInProcess).
import { createInterface } from 'node:readline';

const { main, CapturedIo } = await import(new URL('../../packages/cli/dist/main.js', import.meta.url).href);

for await (const line of createInterface({ input: process.stdin })) {
    const { args, cwd } = JSON.parse(line);
    // pipes, as for a maa-gen process started by subprocess.run
    const io = new CapturedIo(cwd, { ...process.env, NO_COLOR: '1' });
    let code;
    try {
        code = await main(['node', 'maa-gen', ...args], io);
    } catch (error) {
        // main() catches what a command throws; this would be a bug of maa-gen itself
        code = 3; // ExitCode.internal
        io.stderr += `warm-maa-gen: ${error instanceof Error ? (error.stack ?? error.message) : String(error)}\n`;
    }
    process.stdout.write(`${JSON.stringify({ code, stdout: io.stdout, stderr: io.stderr })}\n`);
}
