#!/usr/bin/env node
// Benchmark of the Python generator families (`npm run bench:python` at the root; not a test:
// it asserts nothing about times). Reports, per platform (timesync, rospython):
//   - generation time of the ToastServiceRobot example (`maa-gen generate`, median of 3 runs);
//   - generation time of the 1,000-component model of the check benchmark plus a top component
//     `robot.System` (or the reason a family rejects that synthetic model);
// and the throughput of the example's python-timesync build in time slices per second, driven
// through its lock-step interface (the simulator's way of running it), median of 3 runs.
// Options: --components N (1000)  --slices N (20000)  --keep
import { execFileSync, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { performance } from 'node:perf_hooks';
import { fileURLToPath } from 'node:url';
import { generateModels, writeSystemComponent } from '../../cli/bench/generate-models.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '..', '..', '..');
const CLI = path.join(repo, 'packages', 'cli', 'bin', 'maa-gen.js');
const EXAMPLE_APP = path.join(repo, 'examples', 'toast-service', 'TR.arcapp');
const PLATFORMS = ['timesync', 'rospython'];

const option = (name, fallback) => {
    const i = process.argv.indexOf(`--${name}`);
    return i >= 0 && process.argv[i + 1] !== undefined ? process.argv[i + 1] : fallback;
};
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const seconds = (ms) => `${(ms / 1000).toFixed(2)} s`;

/** Runs `maa-gen generate` and returns its wall time, or the reason it failed. */
function generate(app, platform, out) {
    const t0 = performance.now();
    const r = spawnSync(process.execPath, [CLI, 'generate', app, '--platform', platform, '--out', out], { encoding: 'utf8' });
    const ms = performance.now() - t0;
    if (r.status !== 0) {
        const first = (r.stdout + r.stderr).split('\n').find((l) => / error /.test(l) || /error/i.test(l)) ?? `exit ${r.status}`;
        return { ms, error: first.trim() };
    }
    return { ms };
}

const THROUGHPUT = `
import json, statistics, sys, time
sys.path.insert(0, sys.argv[1])
from maa_app import create_controller
slices = int(sys.argv[2])
runs = []
for _ in range(3):
    app = create_controller({})
    inputs = {"/sensors/distance": {"data": 22}, "/sensors/color": {"data": "WHITE"}}
    t0 = time.perf_counter()
    for _ in range(slices):
        app.step(inputs)
    runs.append(slices / (time.perf_counter() - t0))
print(json.dumps({"median": statistics.median(runs), "runs": runs}))
`;

function python() {
    for (const candidate of [path.join(repo, 'packages', 'generators-python', '.venv', 'bin', 'python'), 'python3']) {
        if (candidate === 'python3' || existsSync(candidate)) return candidate;
    }
    return 'python3';
}

async function main() {
    const components = Number(option('components', '1000'));
    const slices = Number(option('slices', '20000'));
    const work = mkdtempSync(path.join(tmpdir(), 'maa-python-bench-'));
    const rows = [];
    try {
        console.log(`Python generator families benchmark (Node ${process.version}, ${process.platform}/${process.arch})`);
        for (const platform of PLATFORMS) {
            const times = [];
            let error;
            for (let i = 0; i < 3; i++) {
                const r = generate(EXAMPLE_APP, platform, path.join(work, `example-${platform}-${i}`));
                if (r.error) {
                    error = r.error;
                    break;
                }
                times.push(r.ms);
            }
            rows.push([
                `generate the example, ${platform} (median of 3)`,
                error ? `failed: ${error}` : `${seconds(median(times))}  (${times.map(seconds).join(', ')})`,
            ]);
        }

        console.log(`generating a ${components}-component model...`);
        const gen = generateModels(path.join(work, 'big'), components);
        const types = writeSystemComponent(gen.root, gen);
        const app = path.join(gen.root, 'Big.arcapp');
        writeFileSync(
            app,
            `application Big for robot.System {
  platform timesync {
    timesync.Components;
    timesync.AutomataBehavior;
    timesync.RobotArmBehavior;
    timesync.DataTypes;
  }
  platform rospython {
    ros2.Components;
    ros2.AutomataBehavior;
    ros2.RobotArmBehavior;
    ros2.DataTypes;
  }
}
`,
        );
        for (const platform of PLATFORMS) {
            console.log(`generate ${types} component types for ${platform}...`);
            const r = generate(app, platform, path.join(work, `big-${platform}`));
            rows.push([
                `generate ${types} component types, ${platform}`,
                r.error ? `rejected after ${seconds(r.ms)}: ${r.error}` : seconds(r.ms),
            ]);
        }

        console.log(`timesync throughput (${slices} slices x 3)...`);
        const build = path.join(work, 'example-timesync-0', 'timesync');
        const script = path.join(work, 'throughput.py');
        writeFileSync(script, THROUGHPUT);
        try {
            const out = JSON.parse(execFileSync(python(), [script, build, String(slices)], { encoding: 'utf8' }));
            rows.push([
                'timesync runtime, example, slices per second (median of 3)',
                `${Math.round(out.median).toLocaleString('en-US')}  (${out.runs.map((x) => Math.round(x).toLocaleString('en-US')).join(', ')})`,
            ]);
        } catch (e) {
            rows.push(['timesync runtime, example, slices per second', `failed: ${e.message.split('\n')[0]}`]);
        }
    } finally {
        if (!process.argv.includes('--keep')) rmSync(work, { recursive: true, force: true });
    }
    const width = Math.max(...rows.map((r) => r[0].length));
    console.log(`| ${'measure'.padEnd(width)} | value`);
    console.log(`|${'-'.repeat(width + 2)}|${'-'.repeat(40)}`);
    for (const [k, v] of rows) console.log(`| ${k.padEnd(width)} | ${v}`);
}

await main();
