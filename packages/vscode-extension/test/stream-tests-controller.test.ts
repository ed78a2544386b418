// The stream test controller (src/testing/controller.ts) with a stand-in for the `vscode` module
// (test/support/fake-vscode.ts) and the real CLI runner: the tree of a copy of the toast
// example, and what runs of a file, one case and an unassociated file report to the Testing API.
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { CliStreamTestRunner } from '../src/testing/cli-runner.js';
import { outlineStreamFile } from '../src/testing/stream-file.js';
import * as fake from './support/fake-vscode.js';

vi.mock('vscode', () => import('./support/fake-vscode.js'));
const { registerStreamTests } = await import('../src/testing/controller.js');

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const maaGen = path.join(repo, 'packages', 'cli', 'bin', 'maa-gen.js');
const python = path.join(repo, 'packages', 'generators-python', '.venv', 'bin', 'python');

const never: fake.CancellationToken = { isCancellationRequested: false, onCancellationRequested: () => ({ dispose() {} }) };

/** Waits until the controller's tree holds `n` files (discovery is asynchronous). */
async function filesInTree(controller: fake.TestController, n: number): Promise<void> {
    while (controller.items.size < n) await new Promise((r) => setImmediate(r));
}

describe('the maa.streamTests controller (fake vscode, real maa-gen)', () => {
    const root = mkdtempSync(path.join(tmpdir(), 'maa-vscode-controller-'));
    const controllerFile = path.join(root, 'toast-service', 'toast', 'Controller.stream');
    let controller: fake.TestController;
    beforeAll(async () => {
        cpSync(path.join(repo, 'examples', 'toast-service'), path.join(root, 'toast-service'), { recursive: true });
        // A stream file no application runs (no .arcapp above it).
        mkdirSync(path.join(root, 'loose'));
        writeFileSync(path.join(root, 'loose', 'L.stream'), 'component a.B;\ntest "alone" {\n  o == 1;\n}\n');
        // The second case of Controller.stream expects LOAD_BREAD one slice late.
        const text = readFileSync(controllerFile, 'utf8');
        writeFileSync(controllerFile, text.replace('arm      == NONE Tk Tk LOAD_BREAD Tk;', 'arm      == NONE Tk Tk Tk LOAD_BREAD Tk;'));
        fake.state.root = root;
        registerStreamTests(
            new CliStreamTestRunner(
                () => maaGen,
                () => python,
            ),
        );
        controller = fake.controllers.at(-1)!;
        await filesInTree(controller, 4);
    });
    afterAll(() => rmSync(root, { recursive: true, force: true }));

    const fileItem = (rel: string): fake.TestItem => controller.items.get(fake.Uri.file(path.join(root, rel)).toString())!;
    const run = async (include: fake.TestItem[]): Promise<fake.TestRun> => {
        await controller.profiles[0]!.handler({ include }, never);
        return controller.runs.at(-1)!;
    };
    const final = (r: fake.TestRun) => r.events.filter((e) => !['enqueued', 'started'].includes(e.kind));

    it('shows every .stream file with its cases at their ranges', () => {
        expect(controller.id).toBe('maa.streamTests');
        expect(controller.profiles.map((p) => [p.label, p.kind, p.isDefault])).toEqual([['Run', fake.TestRunProfileKind.Run, true]]);
        const file = fileItem('toast-service/toast/Controller.stream');
        expect(file.description).toBe('toast.Controller');
        const cases = [...file.children].map(([, c]) => c);
        expect(cases.map((c) => c.label)).toHaveLength(5);
        expect(cases[1]!.label).toBe('a plate starts loading the bread');
        expect(cases[1]!.range?.start.line).toBe(14);
        expect(cases.every((c) => c.parent === file)).toBe(true);
    });

    it('a file run: failed with a diff at the port statement, the rest passed', async () => {
        const file = fileItem('toast-service/toast/Controller.stream');
        const r = await run([file]);
        expect(r.ended).toBe(true);
        const events = final(r);
        expect(events.map((e) => [e.item.label, e.kind])).toEqual([
            ['nothing happens while no plate is in front of the robot', 'passed'],
            ['a plate starts loading the bread', 'failed'],
            ['a whole service: load, toast until golden, deliver', 'passed'],
            ['a burnt toast is not served', 'passed'],
            ['the states of a whole service, slice by slice', 'passed'],
        ]);
        const [message] = events[1]!.messages;
        expect(message).toMatchObject({ expectedOutput: 'NONE Tk Tk Tk LOAD_BREAD Tk', actualOutput: 'NONE Tk Tk LOAD_BREAD Tk' });
        const arm = outlineStreamFile(readFileSync(controllerFile, 'utf8')).cases[1]!.expected['arm']!;
        expect(message!.location?.range.start).toEqual({ line: arm.line, character: arm.character });
        expect(events.every((e) => e.duration === undefined)).toBe(true);
    }, 300_000);

    it('one case runs alone (with its time); a case and its file selected together run once', async () => {
        const file = fileItem('toast-service/toast/Controller.stream');
        const burnt = [...file.children].map(([, c]) => c)[3]!;
        const r = await run([burnt]);
        const events = final(r);
        expect(events.map((e) => [e.item.label, e.kind])).toEqual([['a burnt toast is not served', 'passed']]);
        expect(events[0]!.duration).toBeGreaterThan(0);
        const both = final(await run([file, burnt]));
        expect(both).toHaveLength(5);
    }, 300_000);

    it('a file no application runs is errored with the reason; an untrusted workspace runs nothing', async () => {
        const loose = fileItem('loose/L.stream');
        const events = final(await run([loose]));
        expect(events.map((e) => [e.item.label, e.kind])).toEqual([['alone', 'errored']]);
        expect(events[0]!.messages[0]!.message).toMatch(/No application configuration/);
        fake.state.trusted = false;
        try {
            const untrusted = final(await run([fileItem('toast-service/toast/ArmController.stream')]));
            expect(untrusted.every((e) => e.kind === 'errored' && /trusted workspaces/.test(e.messages[0]!.message))).toBe(true);
        } finally {
            fake.state.trusted = true;
        }
    }, 300_000);
});
