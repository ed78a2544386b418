import { execFile } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { deploymentContract, lockstepContract, traceFileContract, TRACE_FILE_NAME } from '../dist/index.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const run = promisify(execFile);

function find(dir: string, name: string, out: string[] = []): string[] {
    for (const e of readdirSync(dir)) {
        const abs = path.join(dir, e);
        if (statSync(abs).isDirectory()) find(abs, name, out);
        else if (e === name) out.push(abs);
    }
    return out;
}

/** What `maa-gen generate` writes now, through the readers' contracts (a writer that drifts fails here). */
describe('maa-gen output keeps the contracts', () => {
    let out: string;
    beforeAll(async () => {
        out = mkdtempSync(path.join(tmpdir(), 'maa-protocol-'));
        await run(process.execPath, [
            path.join(repo, 'packages/cli/bin/maa-gen.js'),
            'generate',
            path.join(repo, 'examples/toast-service/TR.arcapp'),
            '--out',
            out,
        ]);
    });
    afterAll(() => rmSync(out, { recursive: true, force: true }));

    test.each(['timesync', 'rospython'])('the trace file of %s', (platform) => {
        const trace = traceFileContract.parse(
            JSON.parse(readFileSync(path.join(out, platform, TRACE_FILE_NAME), 'utf8')),
            `${platform}/${TRACE_FILE_NAME}`,
        );
        expect(trace.platform).toBe(platform);
        const ranges = trace.files.flatMap((f) => f.traces.map((t) => t.element.range)).filter((r) => r !== null);
        expect(ranges.length).toBeGreaterThan(0);
        // 0-based: some element starts in the first column of its line.
        expect(ranges.some((r) => r.start.character === 0)).toBe(true);
    });

    test('the deployment.json of rospython and the lockstep.json of timesync', () => {
        const deployments = find(path.join(out, 'rospython'), 'deployment.json');
        expect(deployments.length).toBe(1);
        expect(deploymentContract.issues(JSON.parse(readFileSync(deployments[0]!, 'utf8')))).toEqual([]);
        expect(lockstepContract.issues(JSON.parse(readFileSync(path.join(out, 'timesync', 'lockstep.json'), 'utf8')))).toEqual([]);
    });
});
