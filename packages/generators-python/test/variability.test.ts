import { cpSync, mkdtempSync, readFileSync, readdirSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { maaGenInProcess, type StreamResult } from './maa-gen.js';
import { ensureVenv, repoDir, venvPython } from './python-env.js';

const fixture = path.join(repoDir, 'packages', 'generators-python', 'test', 'fixtures', 'variability');
const work = mkdtempSync(path.join(tmpdir(), 'maa-variability-'));
afterAll(() => rmSync(work, { recursive: true, force: true }));

/** A copy of the fixture whose application binds `dim` as given. */
function configured(dim: boolean): string {
    const dir = path.join(work, `dim-${dim}`);
    cpSync(fixture, dir, { recursive: true });
    const app = path.join(dir, 'Variability.arcapp');
    writeFileSync(app, readFileSync(app, 'utf8').replace('lamp.Room(dim = true)', `lamp.Room(dim = ${dim})`));
    return app;
}

function allText(dir: string): string {
    let text = '';
    for (const name of readdirSync(dir)) {
        const p = path.join(dir, name);
        if (statSync(p).isDirectory()) text += allText(p);
        else if (name.endsWith('.py')) text += readFileSync(p, 'utf8');
    }
    return text;
}

// Variable architectures on python-timesync, end to end: the application's feature binding
// selects the configuration (lamp.Room's `dim`, and through its constraint the lamp's
// `dimmable`); each build runs the stream tests written for its configuration and refuses those
// of the other one.
describe('feature configurations on python-timesync (maa-gen test)', () => {
    for (const dim of [true, false]) {
        it(`dim = ${dim}: the tests of that configuration pass, those of the other are refused`, async () => {
            await ensureVenv();
            const r = await maaGenInProcess(['test', configured(dim), '--format', 'json', '--python', venvPython], repoDir);
            const out = JSON.parse(r.stdout) as { results: StreamResult[] };
            const own = out.results.filter((x) => x.file.endsWith(dim ? 'RoomDimmed.stream' : 'RoomPlain.stream'));
            const other = out.results.filter((x) => x.file.endsWith(dim ? 'RoomPlain.stream' : 'RoomDimmed.stream'));
            expect(own.length).toBe(1);
            expect(own.filter((x) => !x.passed)).toEqual([]);
            expect(other.length).toBe(1);
            expect(other[0]!.passed).toBe(false);
            expect(other[0]!.problems.join(' ')).toContain('another feature configuration');
        }, 180_000);
    }
});

// Instances of one component type in different configurations (hall.Hall: a dimmable and a plain
// lamp, wings whose lamps differ): each configuration is generated as a variant of the type, and
// the stream test sees every lamp behave as its own instance is configured.
const instancesApp = path.join(repoDir, 'packages', 'generators-python', 'test', 'fixtures', 'variability-instances', 'Instances.arcapp');

describe('instances of one type in different configurations (maa-gen test)', () => {
    it("python-timesync: each lamp behaves per its instance's configuration; a stream test of the type finds the variant of its features", async () => {
        await ensureVenv();
        const r = await maaGenInProcess(['test', instancesApp, '--format', 'json', '--python', venvPython], repoDir);
        const out = JSON.parse(r.stdout) as { results: StreamResult[] };
        // LampPlain.stream names hall.Lamp with dimmable = false: it runs against the variant Lamp__no_dimmable.
        expect(out.results.map((x) => x.file.split(/[\\/]/).pop()).sort()).toEqual([
            'Hall.stream',
            'LampDimmable.stream',
            'LampPlain.stream',
        ]);
        expect(out.results.filter((x) => !x.passed)).toEqual([]);
        expect(r.status, r.stdout + r.stderr).toBe(0);
    }, 180_000);

    it('both platforms generate one variant per configuration, named after its features', async () => {
        for (const platform of ['timesync', 'rospython']) {
            const dir = path.join(work, `instances-${platform}`);
            const r = await maaGenInProcess(['generate', instancesApp, '--platform', platform, '--out', dir], repoDir);
            expect(r.status, r.stdout + r.stderr).toBe(0);
            const text = allText(dir);
            for (const cls of ['class LampBehavior', 'class Lamp__no_dimmableBehavior']) expect(text).toContain(cls);
            expect(text).not.toContain('class Lamp__dimmable');
        }
    }, 180_000);
});

// The generated ROS 2 nodes of these configurations run with real rclpy in test/ros2/test_ros2_variability.py.
describe('feature configurations on ROS 2', () => {
    it('generate each configuration: the dimmed room has its doubler node, the plain one none', async () => {
        const texts: Record<string, string> = {};
        for (const dim of [true, false]) {
            const out = path.join(work, `ros2-${dim}`);
            const r = await maaGenInProcess(['generate', configured(dim), '--platform', 'rospython', '--out', out], repoDir);
            expect(r.status, r.stdout + r.stderr).toBe(0);
            texts[String(dim)] = allText(out);
        }
        expect(texts['true']).toContain('doubler');
        expect(texts['false']).not.toContain('doubler');
    }, 180_000);

    it('a binding of an unknown feature is refused (app/unknown-feature)', async () => {
        const app = configured(true);
        writeFileSync(app, readFileSync(app, 'utf8').replace('lamp.Room(dim = true)', 'lamp.Room(dimmed = true)'));
        const r = await maaGenInProcess(['generate', app, '--platform', 'timesync', '--out', path.join(work, 'unknown')], repoDir);
        expect(r.stdout + r.stderr).toContain('app/unknown-feature');
        expect(r.status).toBe(1);
    }, 180_000);
});
