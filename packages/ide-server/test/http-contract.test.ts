import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { answers, topicMapContract, traceFileContract, type Contract, type TSchema } from '@maa/protocol';
import { authFetch, startSite, type TestSite } from './helpers.js';

const APP = 'toast-service/TR.arcapp';

/**
 * The HTTP contract of @maa/protocol against the server's real answers: what ide-web validates
 * must be what ide-server sends (a drift on either side fails here), and malformed request
 * bodies are refused with the contract's message while the server keeps serving.
 */
describe('HTTP API contract (@maa/protocol) on a copy of examples/', () => {
    let site: TestSite;
    beforeAll(async () => {
        site = await startSite();
    });
    afterAll(() => site.dispose());

    const post = (route: string, body: string) =>
        authFetch(site.url(route), { method: 'POST', body, headers: { 'Content-Type': 'application/json' } });

    async function expectKeeps<T extends TSchema>(res: Response, contract: Contract<T>, status = 200): Promise<unknown> {
        expect(res.status).toBe(status);
        const body: unknown = await res.json();
        expect(contract.issues(body), `${contract.name}: ${JSON.stringify(body).slice(0, 300)}`).toEqual([]);
        return body;
    }

    it('GET /api/files, GET /api/apps and GET /api/sim/status answer what the client reads', async () => {
        await expectKeeps(await authFetch(site.url('/api/files')), answers.files);
        const apps = await expectKeeps(await authFetch(site.url('/api/apps')), answers.apps);
        expect(answers.apps.parse(apps).apps.map((a) => a.path)).toContain(APP);
        await expectKeeps(await authFetch(site.url('/api/sim/status')), answers.simStatus);
    });

    it('POST /api/generate answers a GenerateAnswer; PUT /api/file an OkAnswer; failures an ErrorAnswer', async () => {
        const generated = answers.generate.parse(
            await expectKeeps(await post('/api/generate', JSON.stringify({ app: APP, platform: 'timesync' })), answers.generate),
        );
        expect(generated.ok).toBe(true);
        // The trace file the generation wrote, as the generate panel reads it (0-based positions).
        const trace = traceFileContract.parse(
            await expectKeeps(
                await authFetch(site.url(`/api/generated/trace?app=${encodeURIComponent(APP)}&platform=timesync`)),
                traceFileContract,
            ),
        );
        expect(trace.files.map((f) => f.path).sort()).toEqual(generated.files.map((f) => f.path).sort());
        const traced = trace.files.flatMap((f) => f.traces);
        expect(traced.length).toBeGreaterThan(0);
        expect(traced.some((t) => t.lines.first === 0)).toBe(true);
        await expectKeeps(await authFetch(site.url('/api/file?path=notes.txt'), { method: 'PUT', body: 'x' }), answers.ok);
        await expectKeeps(await authFetch(site.url('/api/file?path=missing.txt')), answers.error, 404);
        await expectKeeps(await post('/api/generate', JSON.stringify({ app: APP, platform: 'nosuch' })), answers.error, 400);
    });

    it('GET /api/sim/topics: the port topics the generators wrote, the same names on both platforms', async () => {
        const topics = (platform: string) => authFetch(site.url(`/api/sim/topics?app=${encodeURIComponent(APP)}&platform=${platform}`));
        expect((await post('/api/generate', JSON.stringify({ app: APP, platform: 'timesync' }))).status).toBe(200);
        expect((await post('/api/generate', JSON.stringify({ app: APP, platform: 'rospython' }))).status).toBe(200);
        const lockstep = topicMapContract.parse(await expectKeeps(await topics('timesync'), topicMapContract));
        const ros2 = topicMapContract.parse(await expectKeeps(await topics('rospython'), topicMapContract));
        expect(lockstep.mode).toBe('lockstep');
        expect(ros2.mode).toBe('ros2');
        // toasterCtrl.leverDown: the port path keeps its spelling, the topic is snake case.
        expect(lockstep.ports).toContainEqual({
            portPath: 'toasterCtrl.leverDown',
            instancePath: 'toasterCtrl',
            port: 'leverDown',
            direction: 'out',
            topic: '/toast_service_robot/toaster_ctrl/lever_down',
            type: 'std_msgs/msg/Bool',
            external: false,
        });
        const outs = (m: typeof lockstep) =>
            m.ports
                .filter((p) => p.direction === 'out')
                .map((p) => `${p.portPath} ${p.topic}`)
                .sort();
        expect(outs(ros2)).toEqual(expect.arrayContaining(outs(lockstep)));
        expect(lockstep.nodes).toContainEqual({ instancePath: 'ctrl', node: '/toast_service_robot/ctrl' });
        expect(ros2.nodes.map((n) => n.node)).toEqual(expect.arrayContaining(lockstep.nodes.map((n) => n.node)));
        // the automata table: the same on both platforms, files relative to the workspace
        expect(ros2.automata).toEqual(lockstep.automata);
        const ctrl = lockstep.automata?.find((a) => a.instancePath === 'ctrl');
        expect(ctrl).toMatchObject({
            node: '/toast_service_robot/ctrl',
            component: 'toast.Controller',
            file: 'toast-service/toast/Controller.arc',
        });
        expect(ctrl?.states.map((s) => s.path)).toEqual(['Idle', 'Loading', 'Toasting', 'Serving']);
        expect(ctrl?.transitions[2]).toMatchObject({ index: 2, from: 'Toasting', to: 'Serving', line: 24, column: 5 });
        expect((await authFetch(site.url(`/api/file?path=${encodeURIComponent(ctrl!.file)}`))).status).toBe(200);
        await expectKeeps(await topics('nosuch'), answers.error, 400);
        await expectKeeps(await authFetch(site.url('/api/sim/topics?app=..%2Fx.arcapp&platform=timesync')), answers.error, 400);
    });

    it.each([
        ['not JSON', '{', 'not valid JSON'],
        ['an array', '[]', 'must be a JSON object'],
        ['no platform', JSON.stringify({ app: APP }), 'invalid POST /api/generate request: /platform: platform must be a non-empty string'],
        ['a number for app', JSON.stringify({ app: 7, platform: 'timesync' }), '/app: app must be a non-empty string'],
        ['an object for app', JSON.stringify({ app: { $gt: '' }, platform: 'timesync' }), '/app: app must be a non-empty string'],
        ['an empty platform', JSON.stringify({ app: APP, platform: '' }), '/platform: platform must be a non-empty string'],
        ['deep nesting', `{"app":${'['.repeat(5000)}${']'.repeat(5000)},"platform":"timesync"}`, '/app: app must be a non-empty string'],
    ])('POST /api/generate with %s: 400 with the validation message', async (_what, body, message) => {
        const res = await post('/api/generate', body);
        const answer = answers.error.parse(await expectKeeps(res, answers.error, 400));
        expect(answer.error).toContain(message);
    });

    it.each([
        ['an unknown mode', { app: APP, platform: 'timesync', mode: 'fast' }, '/mode: mode must be "lockstep" or "ros2"'],
        ['a negative speed', { app: APP, platform: 'timesync', speed: -1 }, '/speed: speed must be a number from 0'],
        ['a string speed', { app: APP, platform: 'timesync', speed: '2' }, '/speed: speed must be a number from 0'],
        ['a huge speed', { app: APP, platform: 'timesync', speed: 1e300 }, '/speed: speed must be a number from 0'],
        ['no app', { platform: 'timesync' }, '/app: app must be a non-empty string'],
    ])('POST /api/sim/start with %s: 400 with the validation message', async (_what, body, message) => {
        const res = await post('/api/sim/start', JSON.stringify(body));
        const answer = answers.error.parse(await expectKeeps(res, answers.error, 400));
        expect(answer.error).toContain(message);
    });

    it('keeps serving after a burst of malformed bodies', async () => {
        const bodies = ['{', 'null', '"x"', '[1]', '{"app":null}', JSON.stringify({ app: APP, platform: ['timesync'] })];
        const statuses = await Promise.all(
            bodies.flatMap((b) => [post('/api/generate', b), post('/api/sim/start', b)]).map(async (r) => (await r).status),
        );
        expect(
            statuses.every((s) => s === 400),
            statuses.join(','),
        ).toBe(true);
        await expectKeeps(await authFetch(site.url('/api/apps')), answers.apps);
        expect(answers.simStatus.parse(await (await authFetch(site.url('/api/sim/status'))).json()).running).toBe(false);
    });
});
