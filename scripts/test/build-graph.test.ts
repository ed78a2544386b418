// `npm test` builds the workspaces two at a time in the order of their dependencies
// (scripts/build-graph.mjs): no build starts before those it depends on have ended, at most
// `jobs` run at once, a failure stops new builds, a cycle is refused, and a build that only
// type-checks holds back no other.
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
// @ts-expect-error -- a plain .mjs script without type declarations
import { runGraph, workspaceGraph } from '../build-graph.mjs';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');

interface Node {
    dir: string;
    build: boolean;
    checkOnly?: boolean;
    deps: string[];
}

/** Runs the graph with builds that end when the test says so; records starts and ends. */
function simulate(graph: Node[], jobs: number, fail: string[] = [], seconds?: Record<string, number>, first?: string[]) {
    const events: string[] = [];
    let running = 0;
    let most = 0;
    const status = runGraph(graph, {
        jobs,
        seconds,
        first,
        run: async (dir: string) => {
            running += 1;
            most = Math.max(most, running);
            events.push(`start ${dir}`);
            await new Promise((resolve) => setImmediate(resolve));
            running -= 1;
            events.push(`end ${dir}`);
            return fail.includes(dir) ? 3 : 0;
        },
    }) as Promise<number>;
    return { status, events, most: () => most };
}

describe('the build graph', () => {
    it("of this repository: every dependency is a workspace, and each build starts after its dependencies' builds ended", async () => {
        const graph = workspaceGraph(repo) as Node[];
        expect(graph.map((n) => n.dir)).toEqual(expect.arrayContaining(['packages/language-server', 'packages/cli', 'packages/ide-web']));
        const { status, events, most } = simulate(graph, 2);
        expect(await status).toBe(0);
        expect(most()).toBe(2);
        const built = graph.filter((n) => n.build);
        expect(events.filter((e) => e.startsWith('start')).sort()).toEqual(built.map((n) => `start ${n.dir}`).sort());
        const byDir = new Map(graph.map((n) => [n.dir, n]));
        /** The workspaces with a build that writes something that `dir` depends on, through those without one. */
        const builtDeps = (dir: string): string[] =>
            byDir.get(dir)!.deps.flatMap((d) => (byDir.get(d)!.build && !byDir.get(d)!.checkOnly ? [d] : builtDeps(d)));
        for (const n of built) {
            for (const dep of builtDeps(n.dir)) {
                expect(events.indexOf(`end ${dep}`), `${n.dir} after ${dep}`).toBeLessThan(events.indexOf(`start ${n.dir}`));
            }
        }
    });

    it("of this repository: the type-check-only builds and the IDE server's run-time dependency on the web app hold back no build", () => {
        const graph = workspaceGraph(repo) as Node[];
        const byDir = new Map(graph.map((n) => [n.dir, n]));
        expect(graph.filter((n) => n.checkOnly).map((n) => n.dir)).toEqual(['packages/diagram-view', 'packages/simulate-view']);
        expect(byDir.get('packages/ide-server')!.deps).not.toContain('packages/ide-web');
        expect(byDir.get('packages/ide-server')!.deps).toContain('packages/language-server');
        expect(byDir.get('packages/ide-web')!.deps).toContain('packages/diagram-view');
        // without the exception the edge is there (it comes from ide-server's package.json)
        const plain = workspaceGraph(repo, {}) as Node[];
        expect(plain.find((n) => n.dir === 'packages/ide-server')!.deps).toContain('packages/ide-web');
    });

    it('starts the dependents of a check-only build beside it, once what it depends on is built', async () => {
        const graph: Node[] = [
            { dir: 'lib', build: true, deps: [] },
            { dir: 'check', build: true, checkOnly: true, deps: ['lib'] },
            { dir: 'app', build: true, deps: ['check'] },
        ];
        const { status, events, most } = simulate(graph, 2);
        expect(await status).toBe(0);
        expect(most()).toBe(2);
        expect(events.slice(0, 4)).toEqual(['start lib', 'end lib', 'start check', 'start app']);
        expect(events.filter((e) => e.startsWith('end')).sort()).toEqual(['end app', 'end check', 'end lib']);
        // a failed check still fails the build
        const failing = simulate(graph, 2, ['check']);
        expect(await failing.status).toBe(3);
    });

    it('runs one at a time with one job, skips workspaces without a build script but waits for what they depend on', async () => {
        const graph: Node[] = [
            { dir: 'c', build: true, deps: ['b'] },
            { dir: 'b', build: false, deps: ['a'] },
            { dir: 'a', build: true, deps: [] },
        ];
        const { status, events, most } = simulate(graph, 1);
        expect(await status).toBe(0);
        expect(most()).toBe(1);
        expect(events).toEqual(['start a', 'end a', 'start c', 'end c']);
    });

    it('starts the ready build with the longest chain behind it first', async () => {
        const graph: Node[] = [
            { dir: 'short', build: true, deps: [] },
            { dir: 'long', build: true, deps: [] },
            { dir: 'after-long', build: true, deps: ['long'] },
        ];
        const { status, events } = simulate(graph, 1, [], { short: 5, long: 10, 'after-long': 10 });
        expect(await status).toBe(0);
        expect(events.filter((e) => e.startsWith('start'))).toEqual(['start long', 'start after-long', 'start short']);
    });

    it('starts a ready build named first before those with longer chains', async () => {
        const graph: Node[] = [
            { dir: 'long', build: true, deps: [] },
            { dir: 'awaited', build: true, deps: [] },
            { dir: 'after-long', build: true, deps: ['long'] },
        ];
        const { status, events } = simulate(graph, 1, [], { long: 10, awaited: 5, 'after-long': 10 }, ['awaited']);
        expect(await status).toBe(0);
        expect(events.filter((e) => e.startsWith('start'))).toEqual(['start awaited', 'start long', 'start after-long']);
    });

    it('after a failed build starts no other and resolves to its exit status', async () => {
        const graph: Node[] = [
            { dir: 'a', build: true, deps: [] },
            { dir: 'b', build: true, deps: ['a'] },
            { dir: 'c', build: true, deps: ['b'] },
        ];
        const { status, events } = simulate(graph, 2, ['a']);
        expect(await status).toBe(3);
        expect(events).toEqual(['start a', 'end a']);
    });

    it('refuses a cycle and a dependency that is not a workspace', async () => {
        const cycle: Node[] = [
            { dir: 'a', build: true, deps: ['b'] },
            { dir: 'b', build: true, deps: ['a'] },
        ];
        await expect(simulate(cycle, 2).status).rejects.toThrow(/cycle/);
        await expect(simulate([{ dir: 'a', build: true, deps: ['nowhere'] }], 2).status).rejects.toThrow(/nowhere, which is not a workspace/);
    });
});
