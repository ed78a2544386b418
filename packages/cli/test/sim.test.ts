import { execFile } from 'node:child_process';
import { cpSync, existsSync, mkdtempSync, rmSync, utimesSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { simulatorFinishedContract } from '@maa/protocol';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { requireBuiltCli, runCli, runCliInProcess } from './helpers.js';

const repo = fileURLToPath(new URL('../../..', import.meta.url));
const EXAMPLE = path.join(repo, 'examples', 'toast-service');
/** The clone's simulator (bash sim-server/scripts/setup_env.sh); maa-gen sim finds it itself. */
const MAA_SIM = path.join(repo, 'sim-server', '.venv', 'bin', 'maa-sim');
const haveSim = existsSync(MAA_SIM);

/** The simulator's own topics and the scene state, recorded in every run. */
const SIM_TOPICS = [
    '/clock',
    '/joint_states',
    '/sensors/distance',
    '/sensors/color',
    '/arm/joint_command',
    '/arm/gripper_command',
    '/toaster/command',
    '/sim/scene',
];

interface InspectedChannel {
    topic: string;
    message_encoding: string;
    schema: string;
    schema_encoding: string;
    messages: number;
}

/** `maa-sim inspect`: the MCAP file read back with the `mcap` reader, every message decoded with mcap-ros2-support. */
function inspect(file: string): Promise<{ profile: string; messages: number; complete: boolean; channels: InspectedChannel[] }> {
    return new Promise((resolve, reject) => {
        execFile(MAA_SIM, ['inspect', file], { maxBuffer: 16 * 1024 * 1024 }, (error, stdout, stderr) => {
            if (error) reject(new Error(`maa-sim inspect failed: ${stderr}`));
            else resolve(JSON.parse(stdout));
        });
    });
}

describe('maa-gen sim: usage', () => {
    let dir: string;
    beforeAll(() => {
        requireBuiltCli();
        dir = mkdtempSync(path.join(tmpdir(), 'maa-sim-usage-'));
        cpSync(EXAMPLE, dir, { recursive: true });
    });
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('needs --platform when the application has several', async () => {
        const r = await runCliInProcess(['sim', 'TR.arcapp', '--until-goal'], dir);
        expect(r.code).toBe(2);
        expect(r.stderr).toContain('TR.arcapp has 2 platforms (rospython, timesync): choose one with --platform');
        expect(existsSync(path.join(dir, 'generated'))).toBe(false);
    });

    it('refuses an unknown platform, a missing file, --headless with --viewer and a bad --duration', async () => {
        const unknown = await runCliInProcess(['sim', 'TR.arcapp', '--platform', 'nope'], dir);
        expect(unknown.code).toBe(2);
        expect(unknown.stderr).toContain('TR.arcapp has no platform nope (its platforms: rospython, timesync)');
        const missing = await runCliInProcess(['sim', 'missing.arcapp', '--platform', 'timesync'], dir);
        expect(missing.code).toBe(2);
        expect(missing.stderr).toContain('path not found: missing.arcapp');
        const both = await runCliInProcess(['sim', 'TR.arcapp', '--platform', 'timesync', '--headless', '--viewer'], dir);
        expect(both.code).toBe(2);
        expect(both.stderr).toContain('--headless and --viewer exclude each other');
        const duration = await runCliInProcess(['sim', 'TR.arcapp', '--platform', 'timesync', '--duration', '-1'], dir);
        expect(duration.code).toBe(2);
        expect(duration.stderr).toContain('expected a number > 0');
    });
});

// The first run goes through the bin (its exit code and output as a user sees them); the later ones,
// the ROS 2 run too, run maa-gen in the test's warm worker thread (runCliInProcess), which saves
// loading the language services for each (the simulator is a process of its own either way).
describe.skipIf(!haveSim)('maa-gen sim: the toast service on the timesync platform (lock-step)', () => {
    let dir: string;
    beforeAll(() => {
        requireBuiltCli();
        dir = mkdtempSync(path.join(tmpdir(), 'maa-sim-run-'));
        cpSync(EXAMPLE, dir, { recursive: true });
    });
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('generates, runs until the goal, records every port topic, and exits 0', async () => {
        const r = await runCli(['sim', 'TR.arcapp', '--platform', 'timesync', '--until-goal', '--record', 'run.mcap'], dir);
        expect(r.stderr).toContain('maa-gen: generating timesync (its output is missing or older than the models)');
        expect(r.code, r.stderr).toBe(0);
        expect(r.stdout).toMatch(/^timesync \(lockstep mode\): goal reached\n/);
        expect(r.stdout).toMatch(/^ {2}goal {14}reached$/m);
        expect(r.stdout).toMatch(/^ {2}simulated time {4}1\d\.\d\d s$/m);
        const recording = /^ {2}recording {9}run\.mcap: (\d+) messages on (\d+) topics$/m.exec(r.stdout);
        expect(recording).not.toBeNull();

        const info = await inspect(path.join(dir, 'run.mcap'));
        expect(info.profile).toBe('ros2');
        expect(info.complete).toBe(true);
        expect(info.messages).toBe(Number(recording![1]));
        expect(info.channels.length).toBe(Number(recording![2]));
        const topics = info.channels.map((c) => c.topic);
        expect(topics).toEqual(expect.arrayContaining([...SIM_TOPICS, '/maa/automaton_states']));
        // the port topics of the generated build: its instances' out ports
        const ports = topics.filter((t) => t.startsWith('/toast_service_robot/'));
        expect(ports).toEqual(expect.arrayContaining(['/toast_service_robot/ctrl/arm', '/toast_service_robot/toaster_ctrl/lever_down']));
        for (const c of info.channels) {
            expect(c.messages, c.topic).toBeGreaterThan(0);
            expect([c.message_encoding, c.schema_encoding], c.topic).toEqual(['cdr', 'ros2msg']);
        }
        expect(info.channels.find((c) => c.topic === '/sim/scene')?.schema).toBe('maa_sim/msg/SceneState');
        expect(existsSync(path.join(dir, 'run.mcap.part'))).toBe(false);
    });

    it('stops at --duration: exit 1 with --until-goal (not reached), 0 without; reuses the generated output', async () => {
        const untilGoal = await runCliInProcess(
            ['sim', 'TR.arcapp', '--platform', 'timesync', '--until-goal', '--duration', '0.5', '--format', 'json'],
            dir,
        );
        expect(untilGoal.code, untilGoal.stderr).toBe(1);
        expect(untilGoal.stderr).not.toContain('generating'); // nothing changed since the first test
        const summary: unknown = JSON.parse(untilGoal.stdout);
        expect(summary).toMatchObject({
            platform: 'timesync',
            mode: 'lockstep',
            reason: 'time limit reached',
            goal_reached: false,
            record: null,
        });
        expect(simulatorFinishedContract.check({ event: 'finished', ...(summary as object) })).toBe(true);

        // paced at real time, so the run lasts more than a second and shows its progress (stderr is a pipe: plain lines)
        const completed = await runCliInProcess(['sim', 'TR.arcapp', '--platform', 'timesync', '--duration', '1.5', '--speed', '1'], dir);
        expect(completed.code, completed.stderr).toBe(0);
        expect(completed.stdout).toContain('timesync (lockstep mode): time limit reached');
        expect(completed.stdout).toMatch(/^ {2}goal {14}not reached \(not waited for\)$/m);
        expect(completed.stderr).toMatch(/^sim: \d+\.\d\d s simulated, [\d.]+x real time, goal not reached$/m);
    });

    it('generates again when a model file is newer than the output', async () => {
        const model = path.join(dir, 'toast', 'Controller.arc');
        expect(existsSync(model)).toBe(true);
        const now = new Date();
        utimesSync(model, now, now); // saved without a change
        const r = await runCliInProcess(['sim', 'TR.arcapp', '--platform', 'timesync', '--duration', '0.1'], dir);
        expect(r.code, r.stderr).toBe(0);
        expect(r.stderr).toContain('maa-gen: generating timesync');
        expect(r.stderr).toMatch(/\(0 written, \d+ unchanged\)/);
        // the output counts as checked against the models now
        const again = await runCliInProcess(['sim', 'TR.arcapp', '--platform', 'timesync', '--duration', '0.1'], dir);
        expect(again.code, again.stderr).toBe(0);
        expect(again.stderr).not.toContain('generating');
    });
});

const ROS2_VENV = path.join(repo, 'packages', 'generators-python', '.venv-ros2');
const haveRos2 = existsSync(path.join(ROS2_VENV, 'bin', 'maa-sim')) && process.env['MAA_TEST_ROS2'] !== '0';

describe.skipIf(!haveSim || !haveRos2)('maa-gen sim: the toast service on the rospython platform (ROS 2 nodes)', () => {
    let dir: string;
    beforeAll(() => {
        requireBuiltCli();
        dir = mkdtempSync(path.join(tmpdir(), 'maa-sim-ros2-'));
        cpSync(EXAMPLE, dir, { recursive: true });
    });
    afterAll(() => rmSync(dir, { recursive: true, force: true }));

    it('installs the interface package into the ROS 2 environment, runs the nodes until the goal and records their port topics', async () => {
        const args = ['sim', 'TR.arcapp', '--platform', 'rospython', '--until-goal', '--duration', '90', '--record', 'ros2.mcap'];
        // in the warm worker thread: the bin's exit code and output are the first timesync run's test
        const r = await runCliInProcess(args, dir);
        expect(r.code, r.stderr).toBe(0);
        expect(r.stderr).toContain('maa-gen: installing the interface package toast_service_robot_interfaces');
        expect(r.stdout).toMatch(/^rospython \(ros2 mode\): goal reached\n/);
        const info = await inspect(path.join(dir, 'ros2.mcap'));
        const channels = new Map(info.channels.map((c) => [c.topic, c]));
        for (const topic of [...SIM_TOPICS, '/toast_service_robot/ctrl/arm'])
            expect(channels.get(topic)?.messages, topic).toBeGreaterThan(0);
        // a port topic in a generated message type: its schema comes from the installed interface package
        const custom = info.channels.filter((c) => c.schema.startsWith('toast_service_robot_interfaces/msg/'));
        expect(custom.length).toBeGreaterThan(0);
        for (const c of custom) expect(c.messages, c.topic).toBeGreaterThan(0);
    }, 400_000);
});
