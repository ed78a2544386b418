import { readFileSync } from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { LOCKSTEP_FILE_NAME, lockstepContract } from '@maa/protocol';
import { lockstepOf } from '../src/timesync/lockstep.js';
// @ts-expect-error: a plain ESM script shared with scripts/update-golden.mjs
import { goldenCases, goldenDir } from '../scripts/golden-lib.mjs';
import { ensureVenv, packageDir, run, venvPython } from './python-env.js';

interface GoldenCase {
    name: string;
    platform: string;
}

/**
 * Loads a build the way maa-sim's lock-step mode does (sim-server/src/maa_sim/lockstep.py): the
 * `python_path` folders relative to lockstep.json on sys.path, the factory `module:callable`
 * called with `parameters`; then one time slice without inputs. Prints the topics of the slice.
 * The golden folders leave out the copied run-time environments: argv[2] (rte/) stands in for them.
 */
const LOAD_AND_STEP = `
import importlib, json, os, sys
spec = json.load(open(sys.argv[1]))
base = os.path.dirname(os.path.abspath(sys.argv[1]))
sys.path[:0] = [os.path.join(base, p) for p in spec.get("python_path", ["."])]
sys.path.append(sys.argv[2])
module, _, name = spec["factory"].partition(":")
controller = getattr(importlib.import_module(module), name)(spec.get("parameters", {}))
print(json.dumps(sorted(controller.step({}))))
`;

const timesyncCases = (goldenCases() as GoldenCase[]).filter((c) => c.platform === 'timesync');

describe('lockstep.json of python-timesync builds', () => {
    it('the written interface keeps the Lockstep contract of @maa/protocol', () => {
        expect(lockstepContract.issues(lockstepOf())).toEqual([]);
        expect(lockstepOf().factory).toBe('maa_app:create_controller');
    });

    it.each(timesyncCases)('$name: maa-sim can load the build through it and step the controller', async (c) => {
        const file = path.join(goldenDir as string, c.name, LOCKSTEP_FILE_NAME);
        expect(lockstepContract.parse(JSON.parse(readFileSync(file, 'utf8')), file)).toEqual(lockstepOf());
        await ensureVenv();
        // Run from elsewhere: only python_path may put the build on sys.path.
        const r = await run(venvPython, ['-c', LOAD_AND_STEP, file, path.join(packageDir, 'rte')], packageDir);
        expect(r.status, r.stderr).toBe(0);
        const topics = JSON.parse(r.stdout) as string[];
        // The first slice publishes the automaton states at least; every key is an absolute topic.
        expect(topics.length).toBeGreaterThan(0);
        for (const t of topics) expect(t.startsWith('/'), t).toBe(true);
    });
});
