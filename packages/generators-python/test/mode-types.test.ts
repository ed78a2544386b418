import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { maaGen } from './maa-gen.js';
import { ensureVenv, lintPython, packageDir, pythonFiles, repoDir, run, venvPython } from './python-env.js';

// A mode component with an enum port (read by its guards) and a class port (routed by its modes):
// the mode-types fixture (route.GearRouter) generated for both platforms. The ROS 2 mode manager
// imports the generated message module; the behavior generators' Imports rendered that import as an
// empty `from gear_router_interfaces.msg import ` line. test/ros2/test_ros2_mode_types.py runs the
// ROS 2 nodes with real rclpy; here the timesync build runs.
const APP = 'packages/generators-python/test/fixtures/mode-types/GearRouter.arcapp';

let out = '';
beforeAll(async () => {
    out = mkdtempSync(path.join(tmpdir(), 'maa-mode-types-'));
    const r = await run(process.execPath, [maaGen, 'generate', APP, '--out', out], repoDir);
    expect(r.status, r.stdout + r.stderr).toBe(0);
}, 180_000);
afterAll(() => {
    if (out) rmSync(out, { recursive: true, force: true });
});

/** The import block of a generated module: its lines from the first import to the first other statement. */
function importBlock(file: string): string[] {
    const lines = readFileSync(file, 'utf8').split('\n');
    const first = lines.findIndex((l) => /^(import|from) /.test(l) && !l.startsWith('from __future__'));
    const end = lines.findIndex((l, i) => i > first && l !== '' && !/^(import|from) /.test(l));
    return lines.slice(first, end).filter((l, i, all) => l !== '' || i < all.length - 1);
}

describe('a mode component with enum and class ports on ROS 2', () => {
    it('the mode manager imports the message module with `import` (snapshot of its import block)', () => {
        const manager = path.join(out, 'rospython', 'gear_router', 'gear_router', 'nodes', 'maa_modes.py');
        expect(importBlock(manager)).toEqual([
            'from collections.abc import Mapping',
            '',
            'import gear_router_interfaces.msg',
            'from gear_router.model.route.signals import Gear, Sample',
            'from maa_ros2 import InPort, ModeManagerNode, Relay, class_port, enum_port, run_node, std_port',
            'from std_msgs.msg import Int32',
        ]);
        const text = readFileSync(manager, 'utf8');
        expect(text).toContain('InPort("gear", "/gear_router/gear", enum_port(gear_router_interfaces.msg.Gear, Gear), sampled=False)');
    });

    it('a comparison with null tests identity (`is not None`, ruff E711)', () => {
        const behavior = path.join(out, 'rospython', 'gear_router', 'gear_router', 'model', 'route', 'times_behavior.py');
        expect(readFileSync(behavior, 'utf8')).toContain(
            '        if (self.i is not None):\n            self._emit("o", (self.i.value * self.factor))',
        );
    });

    it('no generated module has a from-import without names', () => {
        const files = pythonFiles(path.join(out, 'rospython'));
        expect(files.length).toBeGreaterThan(10);
        const empty = files.filter((f) => /^from \S+ import\s*(,|$)/m.test(readFileSync(f, 'utf8')));
        expect(empty).toEqual([]);
    });

    it('the generated ROS 2 code passes ruff check (the settings of test/ros2) and py_compile', async () => {
        await ensureVenv();
        const platform = path.join(out, 'rospython');
        const known = ['gear_router', 'gear_router_interfaces', 'maa_behavior', 'maa_ros2'].map((x) => `'${x}'`).join(',');
        const ruff = await run(
            venvPython,
            [
                '-m',
                'ruff',
                'check',
                '--no-cache',
                '--output-format',
                'concise',
                '--config',
                path.join(packageDir, 'test', 'ros2', 'ruff-generated.toml'),
                '--config',
                `lint.isort.known-third-party=[${known}]`,
                '--extend-exclude',
                'maa_behavior',
                '.',
            ],
            platform,
        );
        expect(ruff.status, ruff.stdout + ruff.stderr).toBe(0);
        const compile = await run(venvPython, ['-c', COMPILE, ...pythonFiles(platform)], platform);
        expect(compile.status, compile.stderr).toBe(0);
    }, 180_000);
});

const COMPILE = [
    'import os, sys, py_compile, tempfile',
    'with tempfile.TemporaryDirectory() as d:',
    '    for i, f in enumerate(sys.argv[1:]):',
    '        py_compile.compile(f, cfile=os.path.join(d, f"{i}.pyc"), doraise=True)',
].join('\n');

// The timesync build fed slice by slice: gear LOW, HIGH, no message, LOW, each with a sample.
const DRIVER = `import json, sys
sys.path.insert(0, sys.argv[1])
from route.gear_router import GearRouter
from route.signals import Gear, Sample
from maa_timesync import TICK, System
system = System(GearRouter)
system.init()
for gear, value in [(Gear.LOW, 2), (Gear.HIGH, 3), (None, 4), (Gear.LOW, 5)]:
    if gear is not None:
        system.receive("gear", gear)
    system.receive("gear", TICK)
    system.receive("s", Sample(value, Gear.HIGH))
    system.receive("s", TICK)
system.run()
def plain(x):
    if x is TICK:
        return "Tk"
    return {"value": x.value, "gear": x.gear.name} if isinstance(x, Sample) else x
print(json.dumps({p: [plain(x) for x in system.outputs[p]] for p in ("o", "echo")}))
`;

describe('a mode component with enum and class ports on python-timesync', () => {
    it('its guards read the enum port and its modes route the class port', async () => {
        await ensureVenv();
        const build = path.join(out, 'timesync');
        expect(importBlock(path.join(build, 'route', 'gear_router.py'))).toContain('from route.signals import Gear, Sample');
        expect(await lintPython(build)).toEqual([]);
        writeFileSync(path.join(out, 'driver.py'), DRIVER);
        const r = await run(venvPython, [path.join(out, 'driver.py'), build], repoDir);
        expect(r.status, r.stderr).toBe(0);
        expect(JSON.parse(r.stdout)).toEqual({
            o: [2, 'Tk', 30, 'Tk', 40, 'Tk', 5, 'Tk'],
            echo: ['Tk', { value: 3, gear: 'HIGH' }, 'Tk', { value: 4, gear: 'HIGH' }, 'Tk', 'Tk'],
        });
    }, 180_000);
});
