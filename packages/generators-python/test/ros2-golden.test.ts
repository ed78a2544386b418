import { cpSync, mkdtempSync, readdirSync, readFileSync, rmSync, statSync, writeFileSync, mkdirSync, existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, describe, expect, it } from 'vitest';
import { NodeFileSystem } from 'langium/node';
import { generate, type GenerateResult } from '@maa/generator-core/node';
import { createMaaServices } from '@maa/language-server';

/**
 * Golden-file tests of the ros2.* generators on test/ros2/model (nesting, a root in and out port,
 * configuration arguments passed down, enum parameters, a handwritten component, an automaton,
 * class and generic ports). `MAA_UPDATE_GOLDEN=1 npx vitest run packages/generators-python/test/ros2-golden.test.ts`
 * rewrites test/golden-ros2 after an intended change; the diff shows what changed.
 */
const here = path.dirname(fileURLToPath(import.meta.url));
const packageDir = path.resolve(here, '..');
const modelRoot = path.join(here, 'ros2', 'model');
const goldenDir = path.join(here, 'golden-ros2');
const RTE = ['maa_behavior', 'maa_ros2'];
const temps: string[] = [];

function temp(): string {
    const d = mkdtempSync(path.join(tmpdir(), 'maa-ros2-golden-'));
    temps.push(d);
    return d;
}

afterAll(() => {
    for (const d of temps) rmSync(d, { recursive: true, force: true });
});

function listFiles(root: string, rel = ''): string[] {
    const out: string[] = [];
    for (const name of readdirSync(path.join(root, rel)).sort()) {
        const r = rel ? `${rel}/${name}` : name;
        if (statSync(path.join(root, r)).isDirectory()) out.push(...listFiles(root, r));
        else out.push(r);
    }
    return out;
}

async function run(appFile: string, outDir: string, root = modelRoot): Promise<GenerateResult> {
    return generate({ services: createMaaServices(NodeFileSystem), appFile, modelRoot: root, outDir });
}

const isRte = (f: string): boolean => RTE.some((r) => f.startsWith(`robot/${r}/`));

describe('ros2.* golden files', () => {
    it('generates the golden files (RTE copies equal rte/)', async () => {
        const out = temp();
        const result = await run(path.join(modelRoot, 'Golden.arcapp'), out);
        expect(result.diagnostics.filter((d) => d.severity === 'error')).toEqual([]);
        expect(result.ok).toBe(true);
        const platform = path.join(out, 'rospython');
        const files = listFiles(platform).filter((f) => f !== '.maa-trace.json');
        if (process.env.MAA_UPDATE_GOLDEN === '1') {
            rmSync(goldenDir, { recursive: true, force: true });
            for (const f of files.filter((x) => !isRte(x))) {
                mkdirSync(path.dirname(path.join(goldenDir, f)), { recursive: true });
                cpSync(path.join(platform, f), path.join(goldenDir, f));
            }
        }
        expect(existsSync(goldenDir)).toBe(true);
        expect(files.filter((f) => !isRte(f))).toEqual(listFiles(goldenDir));
        for (const f of files) {
            const actual = readFileSync(path.join(platform, f), 'utf8');
            if (isRte(f)) {
                expect(actual, f).toBe(readFileSync(path.join(packageDir, 'rte', f.slice('robot/'.length)), 'utf8'));
            } else {
                expect(actual, f).toBe(readFileSync(path.join(goldenDir, f), 'utf8'));
            }
        }
        const trace = JSON.parse(readFileSync(path.join(platform, '.maa-trace.json'), 'utf8')) as {
            generators: Array<{ name: string }>;
            files: Array<{ path: string; traces: unknown[] }>;
        };
        expect(trace.generators.map((g) => g.name)).toEqual(['ros2.Components', 'ros2.AutomataBehavior', 'ros2.DataTypes']);
        // nodes and messages are traced to the model
        expect(trace.files.find((f) => f.path === 'robot/robot/nodes/unit__ctrl.py')?.traces.length).toBeGreaterThan(0);
        expect(trace.files.find((f) => f.path === 'robot_interfaces/msg/Reading.msg')?.traces.length).toBe(1);
    });

    it('regenerates byte-identically and keeps user files', async () => {
        const a = temp();
        const b = temp();
        await run(path.join(modelRoot, 'Golden.arcapp'), a);
        await run(path.join(modelRoot, 'Golden.arcapp'), b);
        const files = listFiles(path.join(a, 'rospython'));
        expect(listFiles(path.join(b, 'rospython'))).toEqual(files);
        for (const f of files) expect(readFileSync(path.join(b, 'rospython', f)), f).toEqual(readFileSync(path.join(a, 'rospython', f)));
        // a second run into the same folder changes nothing; an edited user file stays
        const user = path.join(a, 'rospython', 'robot/robot/handwritten/sensor.py');
        writeFileSync(user, `${readFileSync(user, 'utf8')}# edited by the user\n`);
        const again = await run(path.join(modelRoot, 'Golden.arcapp'), a);
        expect(again.ok).toBe(true);
        expect(again.platforms[0]!.written).toEqual([]);
        expect(readFileSync(user, 'utf8')).toContain('# edited by the user');
    });

    it('reports a topic with two publishers (gen/generator-failed)', async () => {
        const root = temp();
        cpSync(modelRoot, root, { recursive: true });
        writeFileSync(
            path.join(root, 'robot', 'Sensor.ros2.py'),
            [
                '"""A platform component that publishes on a port topic of another node."""',
                '',
                'from typing import ClassVar',
                '',
                'from robot.handwritten.sensor_base import SensorBase',
                '',
                '',
                'class Sensor(SensorBase):',
                '    SUBSCRIBES: ClassVar[dict[str, str]] = {}',
                '    PUBLISHES: ClassVar[dict[str, str]] = {"/robot/unit/ctrl/reading": "robot_interfaces/msg/Reading"}',
                '',
            ].join('\n'),
        );
        const result = await run(path.join(root, 'Golden.arcapp'), temp(), root);
        expect(result.ok).toBe(false);
        const d = result.diagnostics.find((x) => x.code === 'gen/generator-failed');
        expect(d?.message).toContain('topic /robot/unit/ctrl/reading would have two publishers, /robot/sensor and /robot/unit/ctrl');
    });
});
