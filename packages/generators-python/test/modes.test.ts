import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { maaGen, type StreamResult } from './maa-gen.js';
import { ensureVenv, lintPython, repoDir, run, venvPython } from './python-env.js';

// Mode automata on python-timesync, end to end: the fixture's mode component (test/fixtures/modes,
// also a golden case) is generated and its stream tests run on the build by `maa-gen test`:
// switching in the transition's own slice, resting subcomponents keeping their state, guards
// reading Java's default of a slice without message.
describe('mode automata on python-timesync (maa-gen test)', () => {
    it('every stream test of the modes fixture passes', async () => {
        await ensureVenv();
        const r = await run(
            process.execPath,
            [maaGen, 'test', 'packages/generators-python/test/fixtures/modes/Modes.arcapp', '--format', 'json', '--python', venvPython],
            repoDir,
        );
        const out = JSON.parse(r.stdout) as { results: StreamResult[]; summary: { passed: number; failed: number } };
        expect(out.results.filter((x) => !x.passed)).toEqual([]);
        expect(out.summary.passed).toBe(3);
        expect(r.status).toBe(0);
    }, 180_000);

    it('a guard over an enum parameter switches only the instance whose parameter allows it (mode-params fixture)', async () => {
        await ensureVenv();
        const r = await run(
            process.execPath,
            [
                maaGen,
                'test',
                'packages/generators-python/test/fixtures/mode-params/SelectorPair.arcapp',
                '--format',
                'json',
                '--python',
                venvPython,
            ],
            repoDir,
        );
        const out = JSON.parse(r.stdout) as { results: StreamResult[]; summary: { passed: number; failed: number } };
        expect(out.results.filter((x) => !x.passed)).toEqual([]);
        expect(out.summary.passed).toBe(1);
        expect(r.status).toBe(0);
    }, 180_000);
});

describe('mode automata on ROS 2', () => {
    it('generate a mode manager node and gated subcomponent nodes (no components.NoModes refusal); test/ros2/test_ros2_modes.py runs them', async () => {
        const out = mkdtempSync(path.join(tmpdir(), 'maa-modes-ros2-'));
        try {
            const r = await run(
                process.execPath,
                [
                    maaGen,
                    'generate',
                    'packages/generators-python/test/fixtures/modes/Modes.arcapp',
                    '--platform',
                    'rospython',
                    '--out',
                    out,
                ],
                repoDir,
            );
            expect(r.stdout + r.stderr).not.toContain('components.NoModes');
            expect(r.status).toBe(0);
            const deployment = JSON.parse(readFileSync(path.join(out, 'rospython', 'gearbox', 'deployment.json'), 'utf8')) as {
                nodes: Array<{
                    name: string;
                    namespace: string;
                    subscribes: Array<{ topic: string }>;
                    publishes: Array<{ port?: string; topic: string }>;
                }>;
            };
            const byName = new Map(deployment.nodes.map((n) => [n.name, n]));
            expect([...byName.keys()].sort()).toEqual(['maa_modes', 's1', 's10', 't']);
            const manager = byName.get('maa_modes')!;
            expect(manager.publishes.map((t) => t.topic)).toEqual([
                '/gearbox/maa_modes/mode',
                '/gearbox/maa_modes/s1/i',
                '/gearbox/o',
                '/gearbox/maa_modes/s10/i',
                '/gearbox/maa_modes/t/i',
                '/gearbox/total',
            ]);
            for (const n of ['s1', 's10', 't']) expect(byName.get(n)!.subscribes.map((t) => t.topic)).toContain('/gearbox/maa_modes/mode');
        } finally {
            rmSync(out, { recursive: true, force: true });
        }
    }, 180_000);

    it('a mode manager takes enum parameters as the regular nodes do (by ordinal, converted back for the guards)', async () => {
        const out = mkdtempSync(path.join(tmpdir(), 'maa-mode-params-ros2-'));
        try {
            const r = await run(
                process.execPath,
                [
                    maaGen,
                    'generate',
                    'packages/generators-python/test/fixtures/mode-params/SelectorPair.arcapp',
                    '--platform',
                    'rospython',
                    '--out',
                    out,
                ],
                repoDir,
            );
            expect(r.stdout + r.stderr).not.toContain('primitive types only');
            expect(r.status, r.stdout + r.stderr).toBe(0);
            const pkg = path.join(out, 'rospython', 'selector_pair');
            const deployment = JSON.parse(readFileSync(path.join(pkg, 'deployment.json'), 'utf8')) as {
                nodes: Array<{ name: string; namespace: string; parameters: Record<string, unknown> }>;
            };
            const managers = new Map(deployment.nodes.filter((n) => n.name === 'maa_modes').map((n) => [n.namespace, n.parameters]));
            expect(managers.get('/selector_pair/a')).toEqual({ kind: 0 });
            expect(managers.get('/selector_pair/b')).toEqual({ kind: 1 });
            const manager = readFileSync(path.join(pkg, 'selector_pair', 'nodes', 'b__maa_modes.py'), 'utf8');
            expect(manager).toContain('values["kind"] = list(Kind)[int(values["kind"])]');
            expect(manager).toContain('convert_parameters=convert_parameters');
            expect(manager).toContain('params["kind"] == Kind.FAST');
        } finally {
            rmSync(out, { recursive: true, force: true });
        }
    }, 180_000);
});

// The event-based mode automaton of the fixture (gear.Shifter), generated and fed message by
// message: a message `true` on flip switches to negating before it is forwarded, `false` does
// not (guard), and the tick switches back.
const DRIVER = `import json, sys
sys.path.insert(0, sys.argv[1])
from gear.shifter import Shifter
from maa_timesync import TICK, System
system = System(Shifter)
system.init()
for port, item in [("i", 1), ("flip", True), ("i", 2), ("i", TICK), ("flip", TICK), ("i", 3), ("flip", False), ("i", 4), ("i", TICK), ("flip", TICK)]:
    system.receive(port, item)
system.run()
print(json.dumps(["Tk" if x is TICK else x for x in system.outputs["o"]]))
`;

describe('event-based mode automata on python-timesync', () => {
    it('switch on the message of their trigger port before forwarding it, and back on the tick', async () => {
        await ensureVenv();
        const out = mkdtempSync(path.join(tmpdir(), 'maa-modes-event-'));
        try {
            const gen = await run(
                process.execPath,
                [
                    maaGen,
                    'generate',
                    'packages/generators-python/test/fixtures/modes/Shifter.arcapp',
                    '--platform',
                    'timesync',
                    '--out',
                    out,
                ],
                repoDir,
            );
            expect(gen.status, gen.stdout + gen.stderr).toBe(0);
            const build = path.join(out, 'timesync');
            expect(await lintPython(build)).toEqual([]);
            writeFileSync(path.join(out, 'driver.py'), DRIVER);
            const r = await run(venvPython, [path.join(out, 'driver.py'), build], repoDir);
            expect(r.status, r.stderr).toBe(0);
            expect(JSON.parse(r.stdout)).toEqual([1, -2, 'Tk', 3, 4, 'Tk']);
        } finally {
            rmSync(out, { recursive: true, force: true });
        }
    }, 180_000);
});
