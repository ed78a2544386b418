// The build of `npm test` (scripts/test-all.mjs) on two cores: each workspace's `npm run build`
// runs as soon as the workspaces it depends on are built, two at a time, instead of one after the
// other in the order of the root package.json (what `npm run build` does). The order comes from
// the workspaces' own package.json dependencies, so a new dependency orders the build by itself.
import { readFileSync } from 'node:fs';
import path from 'node:path';

/**
 * CPU seconds of each workspace's build on a fresh clone (2026-11-24, 2-core machine): they only
 * decide which ready build starts first (the one with the longest chain of builds behind it); a
 * workspace missing here counts as 10 s.
 */
export const BUILD_SECONDS = {
    'packages/language-cd': 9,
    'packages/language-adl': 19,
    'packages/language-automata': 14,
    'packages/language-robotarm': 15,
    'packages/protocol': 7,
    'packages/generator-core': 23,
    'packages/generators-python': 8,
    'packages/language-server': 18,
    'packages/cli': 8,
    'packages/grading': 7,
    'packages/ide-server': 8,
    'packages/diagram-view': 5,
    'packages/simulate-view': 7,
    'packages/ide-web': 99,
    'packages/lab-server': 23,
    'packages/vscode-extension': 12,
};

/**
 * Dependencies that a workspace's build does not read, though the workspace needs them at run
 * time: its build need not wait for theirs.
 */
export const RUN_TIME_ONLY = {
    // maa-ide serves @maa/ide-web's dist/; its build (tsc -b) compiles nothing of the web app, so
    // it (and the lab server and the VS Code extension after it) build beside the web app's build
    'packages/ide-server': ['packages/ide-web'],
};

/** A build script that only type-checks (writes nothing another build could read). */
const CHECK_ONLY = /^tsc --noEmit -p \.$/;

/**
 * The workspaces of the repository in the root package.json's order, each with whether it has a
 * build script, whether that build only type-checks (`checkOnly`), and the workspaces it depends
 * on (dependencies, devDependencies, peerDependencies; without those of RUN_TIME_ONLY).
 */
export function workspaceGraph(repo, runTimeOnly = RUN_TIME_ONLY) {
    const root = JSON.parse(readFileSync(path.join(repo, 'package.json'), 'utf8'));
    const manifests = root.workspaces.map((dir) => ({ dir, pkg: JSON.parse(readFileSync(path.join(repo, dir, 'package.json'), 'utf8')) }));
    const dirOf = new Map(manifests.map(({ dir, pkg }) => [pkg.name, dir]));
    return manifests.map(({ dir, pkg }) => ({
        dir,
        build: typeof pkg.scripts?.build === 'string',
        checkOnly: CHECK_ONLY.test(pkg.scripts?.build ?? ''),
        deps: Object.keys({ ...pkg.dependencies, ...pkg.devDependencies, ...pkg.peerDependencies })
            .filter((name) => dirOf.has(name) && dirOf.get(name) !== dir)
            .map((name) => dirOf.get(name))
            .filter((dep) => !(runTimeOnly[dir] ?? []).includes(dep)),
    }));
}

/**
 * Runs `run(dir)` for each workspace with a build script once every workspace it depends on
 * (directly or through workspaces without one) is built, at most `jobs` at a time; among ready
 * builds the one with the longest chain of builds behind it goes first. A build that only
 * type-checks (`checkOnly`) holds back no other: its dependents wait only for what it waits for.
 * A ready build named in `first` (one that work outside the graph waits for) goes before the
 * others. After a failure no new build starts. Resolves to the first failing exit status, or 0.
 * @param {Array<{ dir: string, build: boolean, checkOnly?: boolean, deps: string[] }>} graph
 * @param {{ jobs: number, run: (dir: string) => Promise<number>, seconds?: Record<string, number>, first?: string[] }} options
 */
export async function runGraph(graph, { jobs, run, seconds = BUILD_SECONDS, first = [] }) {
    const byDir = new Map(graph.map((node) => [node.dir, node]));
    for (const node of graph) {
        for (const dep of node.deps) if (!byDir.has(dep)) throw new Error(`${node.dir} depends on ${dep}, which is not a workspace`);
    }
    const dependents = new Map(graph.map((node) => [node.dir, []]));
    for (const node of graph) for (const dep of node.deps) dependents.get(dep).push(node.dir);
    const cost = (dir) => (byDir.get(dir).build ? (seconds[dir] ?? 10) : 0);
    const holdsBack = (dir) => byDir.get(dir).build && !byDir.get(dir).checkOnly;
    // the longest chain of build seconds from a workspace to the end of the graph (it included;
    // a check-only build runs beside its dependents)
    const chain = new Map();
    const visiting = new Set();
    const chainOf = (dir) => {
        if (chain.has(dir)) return chain.get(dir);
        if (visiting.has(dir)) throw new Error(`the workspaces depend on each other in a cycle through ${dir}`);
        visiting.add(dir);
        const after = Math.max(0, ...dependents.get(dir).map(chainOf));
        const longest = holdsBack(dir) ? cost(dir) + after : Math.max(cost(dir), after);
        visiting.delete(dir);
        chain.set(dir, longest);
        return longest;
    };
    for (const node of graph) chainOf(node.dir);

    const waitingOn = new Map(graph.map((node) => [node.dir, new Set(node.deps)]));
    const ready = [];
    let running = 0;
    let failed = 0;
    let finishAll;
    const allDone = new Promise((resolve) => {
        finishAll = resolve;
    });
    let left = graph.length;
    /** Its dependents no longer wait for `dir`. */
    const release = (dir) => {
        for (const next of dependents.get(dir)) {
            const waiting = waitingOn.get(next);
            waiting.delete(dir);
            if (waiting.size === 0) becameReady(next);
        }
    };
    /** `dir` waits for nothing more: without a build it is done, a check-only build releases its dependents at once. */
    const becameReady = (dir) => {
        if (!byDir.get(dir).build) {
            left -= 1;
            release(dir);
            return;
        }
        ready.push(dir);
        if (!holdsBack(dir)) release(dir);
    };
    const pump = () => {
        while (failed === 0 && running < jobs && ready.length > 0) {
            ready.sort((a, b) => Number(first.includes(b)) - Number(first.includes(a)) || chain.get(b) - chain.get(a));
            const dir = ready.shift();
            running += 1;
            run(dir).then(
                (status) => finished(dir, status),
                () => finished(dir, 1),
            );
        }
        // (a workspace left unbuilt with nothing running cannot happen: a cycle throws above)
        if (running === 0 && (failed !== 0 || left === 0 || ready.length === 0)) finishAll(left === 0 ? 0 : failed || 1);
    };
    const finished = (dir, status) => {
        running -= 1;
        if (status !== 0) {
            if (failed === 0) failed = status;
        } else {
            left -= 1;
            if (holdsBack(dir)) release(dir);
        }
        pump();
    };
    for (const node of graph) if (node.deps.length === 0) becameReady(node.dir);
    pump();
    return allDone;
}
