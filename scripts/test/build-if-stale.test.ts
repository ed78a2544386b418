// `npm start` builds only what changed (scripts/build-if-stale.mjs): on a small workspace in a
// temporary folder, with a stand-in build that "compiles" a package's src/ into dist/, every kind of
// input change rebuilds the package and what depends on it, and nothing else; a run with nothing
// changed builds nothing.
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterEach, beforeEach, describe, expect, it } from 'vitest';
// @ts-expect-error -- a plain .mjs script without type declarations
import { buildStale, NO_FILES, outsideInputs, readWorkspaces, staleness } from '../build-if-stale.mjs';

interface Workspace {
    name: string;
    dir: string;
    rel: string;
    build?: string;
    deps: string[];
    closure: string[];
}

interface BuildResult {
    ok: boolean;
    built: string[];
    skipped: string[];
    failed?: string;
}

let repo: string;

function put(rel: string, content: string): void {
    const file = path.join(repo, rel);
    mkdirSync(path.dirname(file), { recursive: true });
    writeFileSync(file, content);
}

function pkg(rel: string, json: Record<string, unknown>): void {
    put(`${rel}/package.json`, `${JSON.stringify(json, null, 2)}\n`);
}

/**
 * composer (no build) <- a <- b; c stands alone and declares a generator. b is listed before a, so
 * the order must come from the dependencies.
 */
function makeWorkspace(): void {
    repo = mkdtempSync(path.join(tmpdir(), 'maa-build-if-stale-'));
    pkg('.', { name: 'root', private: true, workspaces: ['packages/composer', 'packages/b', 'packages/a', 'packages/c'] });
    put('package-lock.json', '{"lockfileVersion": 3}\n');
    put('tsconfig.base.json', '{"compilerOptions": {"strict": true}}\n');
    pkg('packages/composer', { name: '@t/composer', bin: 'bin.mjs' });
    put('packages/composer/bin.mjs', 'compose v1\n');
    pkg('packages/a', { name: '@t/a', scripts: { build: 'compile' }, devDependencies: { '@t/composer': '*' } });
    put('packages/a/src/a.ts', 'export const a = 1;\n');
    put('packages/a/test/a.test.ts', 'test a\n');
    pkg('packages/b', { name: '@t/b', scripts: { build: 'compile' }, dependencies: { '@t/a': '*', leftpad: '1' } });
    put('packages/b/src/b.ts', 'export const b = 2;\n');
    pkg('packages/c', { name: '@t/c', scripts: { build: 'compile' }, maa: { generators: ['manifests/gen.json'] } });
    put('packages/c/src/c.ts', 'export const c = 3;\n');
    put('packages/c/manifests/gen.json', '{"name": "g"}\n');
    // c copies a template from the repository's examples/ and one of its own
    put('packages/c/templates/templates.json', JSON.stringify({ templates: [{ from: '../../examples/demo' }, { from: 'templates/own' }] }));
    put('packages/c/templates/own/App.arc', 'component Own {}\n');
    put('examples/demo/Demo.arc', 'component Demo {}\n');
    put('examples/other/Other.arc', 'component Other {}\n');
}

/** The stand-in build: dist/index.js is the concatenation of the package's src/ files; a package named in `failing` fails. */
function compile(failing: Set<string>, log: string[]) {
    return async (w: Workspace) => {
        log.push(w.name);
        if (failing.has(w.name)) return { code: 1, output: `${w.name}: error TS1005\n` };
        const src = path.join(w.dir, 'src');
        const text = readdirSync(src)
            .sort()
            .map((f) => readFileSync(path.join(src, f), 'utf8'))
            .join('');
        mkdirSync(path.join(w.dir, 'dist'), { recursive: true });
        writeFileSync(path.join(w.dir, 'dist', 'index.js'), text);
        writeFileSync(path.join(w.dir, 'tsconfig.tsbuildinfo'), String(Math.random()));
        return { code: 0, output: '' };
    };
}

async function build(options: { failing?: string[]; force?: boolean } = {}): Promise<BuildResult & { ran: string[]; lines: string }> {
    const ran: string[] = [];
    let lines = '';
    const result: BuildResult = await buildStale(repo, {
        force: options.force ?? false,
        runBuild: compile(new Set(options.failing ?? []), ran),
        write: (text: string) => {
            lines += text;
        },
    });
    return { ...result, ran, lines };
}

describe('build-if-stale', () => {
    beforeEach(async () => {
        makeWorkspace();
        const first = await build();
        expect(first.ran).toEqual(['@t/a', '@t/b', '@t/c']);
    });
    afterEach(() => rmSync(repo, { recursive: true, force: true }));

    it('orders the packages after their workspace dependencies and knows their closures', () => {
        const order: Workspace[] = readWorkspaces(repo);
        expect(order.map((w) => w.name)).toEqual(['@t/composer', '@t/a', '@t/b', '@t/c']);
        expect(order.find((w) => w.name === '@t/b')?.closure).toEqual(['@t/a', '@t/composer']);
        expect(order.find((w) => w.name === '@t/composer')?.build).toBeUndefined();
    });

    it('builds nothing when nothing changed, and says so per package', async () => {
        const again = await build();
        expect(again.ran).toEqual([]);
        expect(again.skipped).toEqual(['@t/a', '@t/b', '@t/c']);
        expect(again.lines).toMatch(/^\[1\/3\] @t\/a is up to date \(\d+\.\d s\)$/m);
    });

    it('rebuilds a package whose source changed and its dependents, not the others', async () => {
        put('packages/a/src/a.ts', 'export const a = 10;\n');
        const again = await build();
        expect(again.ran).toEqual(['@t/a', '@t/b']);
        expect(again.lines).toMatch(/^\[1\/3\] building @t\/a \(inputs changed\) \.\.\. \d+\.\d s$/m);
        expect((await build()).ran).toEqual([]);
    });

    it('rebuilds a package whose new source file appeared or whose source file vanished', async () => {
        put('packages/c/src/more.ts', 'export const more = 4;\n');
        expect((await build()).ran).toEqual(['@t/c']);
        rmSync(path.join(repo, 'packages/c/src/more.ts'));
        expect((await build()).ran).toEqual(['@t/c']);
    });

    it('stops at a dependency whose rebuild left its outputs as they were (a test changed)', async () => {
        put('packages/a/test/a.test.ts', 'test a, more\n');
        expect((await build()).ran).toEqual(['@t/a']);
    });

    it('rebuilds the dependents of a package without a build step when its files change', async () => {
        put('packages/composer/bin.mjs', 'compose v2\n');
        expect((await build()).ran).toEqual(['@t/a', '@t/b']);
    });

    it('rebuilds a package whose package.json changed (its build script, its dependencies)', async () => {
        pkg('packages/b', { name: '@t/b', scripts: { build: 'compile --strict' }, dependencies: { '@t/a': '*', leftpad: '1' } });
        expect((await build()).ran).toEqual(['@t/b']);
    });

    it('rebuilds everything when the root inputs change (compiler options, locked versions)', async () => {
        put('package-lock.json', '{"lockfileVersion": 3, "packages": {}}\n');
        expect((await build()).ran).toEqual(['@t/a', '@t/b', '@t/c']);
        put('tsconfig.base.json', '{"compilerOptions": {"strict": false}}\n');
        expect((await build()).ran).toEqual(['@t/a', '@t/b', '@t/c']);
    });

    it('rebuilds everything when a generator declaration changes (language-server reads them all)', async () => {
        put('packages/c/manifests/gen.json', '{"name": "g2"}\n');
        expect((await build()).ran).toEqual(['@t/a', '@t/b', '@t/c']);
    });

    it('rebuilds a package when a folder outside it that its build copies changes, not for other folders', async () => {
        expect(outsideInputs(repo, readWorkspaces(repo).find((w: Workspace) => w.name === '@t/c'))).toEqual(['examples/demo']);
        put('examples/demo/Demo.arc', 'component Demo { port in int i; }\n');
        expect((await build()).ran).toEqual(['@t/c']);
        put('examples/other/Other.arc', 'component Other { port in int i; }\n');
        expect((await build()).ran).toEqual([]);
    });

    it('rebuilds a package whose outputs were deleted or changed by someone else', async () => {
        rmSync(path.join(repo, 'packages/b/dist'), { recursive: true });
        const deleted = await build();
        expect(deleted.ran).toEqual(['@t/b']);
        expect(deleted.lines).toContain('building @t/b (outputs missing)');
        put('packages/c/dist/index.js', 'tampered\n');
        expect((await build()).ran).toEqual(['@t/c']);
    });

    it('ignores contents that did not change (a rewrite, a new build-info file) and tool folders', async () => {
        put('packages/a/src/a.ts', 'export const a = 1;\n');
        put('packages/a/tsconfig.tsbuildinfo', 'other');
        put('packages/a/node_modules/x/index.js', 'x\n');
        put('packages/a/.venv/bin/python', 'py\n');
        expect((await build()).ran).toEqual([]);
    });

    it('stops at a failed build, records nothing for it, and retries it next time', async () => {
        put('packages/a/src/a.ts', 'export const a = ;\n');
        const failed = await build({ failing: ['@t/a'] });
        expect(failed.ok).toBe(false);
        expect(failed.failed).toBe('@t/a');
        expect(failed.ran).toEqual(['@t/a']);
        expect(failed.lines).toMatch(/building @t\/a \(inputs changed\) \.\.\. failed \(exit 1\) after \d+\.\d s/);
        expect((await build()).ran).toEqual(['@t/a', '@t/b']);
    });

    it('says in a dry run what would be built and why, and builds nothing', async () => {
        put('packages/a/test/a.test.ts', 'test a, more\n');
        const ran: string[] = [];
        let lines = '';
        const dry: BuildResult = await buildStale(repo, {
            dryRun: true,
            runBuild: compile(new Set(), ran),
            write: (text: string) => {
                lines += text;
            },
        });
        expect(ran).toEqual([]);
        expect(dry.built).toEqual(['@t/a']);
        expect(lines).toContain('[1/3] @t/a: would be built (inputs changed)');
        expect(lines).toContain('[2/3] @t/b: up to date, unless the build of @t/a changes what it depends on');
        expect(lines).toContain('[3/3] @t/c: up to date\n');
        expect((await build()).ran).toEqual(['@t/a']);
    });

    it('builds everything with force', async () => {
        expect((await build({ force: true })).ran).toEqual(['@t/a', '@t/b', '@t/c']);
    });
});

describe('staleness', () => {
    const record = { key: 'k1', outputs: 'o1' };
    it('is stale without a record of a build', () => {
        expect(staleness(undefined, 'k1', 'o1')).toEqual({ stale: true, reason: 'no build recorded' });
    });
    it('is stale when the key changed', () => {
        expect(staleness(record, 'k2', 'o1')).toEqual({ stale: true, reason: 'inputs changed' });
    });
    it('is stale when the outputs are gone or changed', () => {
        expect(staleness(record, 'k1', NO_FILES)).toEqual({ stale: true, reason: 'outputs missing' });
        expect(staleness(record, 'k1', 'o2')).toEqual({ stale: true, reason: 'outputs changed since its build' });
    });
    it('is up to date when key and outputs are those of the last build', () => {
        expect(staleness(record, 'k1', 'o1')).toEqual({ stale: false, reason: 'up to date' });
    });
});
