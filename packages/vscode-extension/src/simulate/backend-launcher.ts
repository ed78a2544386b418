/**
 * Runs maa-ide for the extension (bundled to `out/simulate/backend-launcher.mjs`):
 * `node backend-launcher.mjs <maa-ide bin> <maa-ide args…>`. It loads maa-ide's bin in this very
 * process, so there is one process to stop, and it watches its stdin, a pipe from the extension
 * host: when that closes (the extension host exited, also when it was killed) maa-ide gets
 * SIGTERM and stops with every simulation process it started. No orphans either way.
 */
import { pathToFileURL } from 'node:url';

const [node = 'node', , bin, ...args] = process.argv;
if (!bin) {
    console.error('backend-launcher: usage: backend-launcher.mjs <maa-ide bin> [maa-ide options]');
    process.exit(2);
}
process.stdin.on('end', () => process.kill(process.pid, 'SIGTERM'));
process.stdin.on('error', () => process.kill(process.pid, 'SIGTERM'));
process.stdin.resume();
process.argv = [node, bin, ...args];
await import(pathToFileURL(bin).href);
