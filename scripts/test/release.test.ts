import { describe, expect, it } from 'vitest';
// @ts-expect-error: plain JavaScript modules of the repository's scripts, without declarations
import { compareVersions, dependencyOrder, nextVersion, planBump, setDependencyRange, setTopLevelVersion, sharedVersion } from '../release/packages.mjs';
// @ts-expect-error: as above
import { missingPackedTargets, packedTargets } from '../release/packed-targets.mjs';

interface Pkg {
    dir: string;
    text: string;
    json: Record<string, unknown>;
}

/** A workspace package as readWorkspace gives it: the text (formatted as written) and its parse. */
function pkg(dir: string, text: string): Pkg {
    return { dir, text, json: JSON.parse(text) as Record<string, unknown> };
}

const core = pkg(
    'packages/core',
    `{
  "name": "@x/core",
  "version": "0.1.0",
  "description": "mentions \\"version\\": \\"0.1.0\\" in prose",
  "maa": { "generators": [{ "name": "g", "version": "0.1.0" }] },
  "dependencies": { "langium": "4.1.3" }
}
`,
);
const cli = pkg(
    'packages/cli',
    `{
  "name": "@x/cli",
  "version": "0.1.0",
  "dependencies": {
    "@x/core": "0.1.0",
    "commander": "^14.0.3"
  },
  "devDependencies": {"@x/tool": "0.1.0"}
}
`,
);
const tool = pkg('packages/tool', '{\n  "name": "@x/tool",\n  "version": "0.1.0",\n  "private": true,\n  "devDependencies": { "@x/core": "0.1.0" }\n}\n');

describe('nextVersion', () => {
    it('takes an explicit version after the current one', () => {
        expect(nextVersion('0.1.0', '0.2.0')).toBe('0.2.0');
        expect(nextVersion('0.1.0', '1.0.0-rc.1')).toBe('1.0.0-rc.1');
        expect(nextVersion('1.0.0-rc.1', '1.0.0-rc.2')).toBe('1.0.0-rc.2');
        expect(nextVersion('1.0.0-rc.1', '1.0.0')).toBe('1.0.0');
    });
    it('bumps major, minor and patch', () => {
        expect(nextVersion('0.1.9', 'patch')).toBe('0.1.10');
        expect(nextVersion('0.1.9', 'minor')).toBe('0.2.0');
        expect(nextVersion('0.1.9', 'major')).toBe('1.0.0');
        expect(nextVersion('1.0.0-rc.2', 'patch')).toBe('1.0.0');
    });
    it('refuses versions that do not come after the current one, and non-versions', () => {
        expect(() => nextVersion('0.2.0', '0.1.5')).toThrow('does not come after');
        expect(() => nextVersion('0.2.0', '0.2.0')).toThrow('does not come after');
        expect(() => nextVersion('1.0.0', '1.0.0-rc.1')).toThrow('does not come after');
        expect(() => nextVersion('0.1.0', 'v0.2')).toThrow('neither a version');
        expect(() => nextVersion('0.1.0', 'next')).toThrow('neither a version');
    });
});

describe('compareVersions', () => {
    it('orders by semantic-version precedence', () => {
        const sorted = ['1.0.0', '1.0.0-rc.10', '0.9.9', '1.0.0-alpha', '1.0.0-rc.2', '1.0.0-alpha.1', '0.10.0'].sort(compareVersions);
        expect(sorted).toEqual(['0.9.9', '0.10.0', '1.0.0-alpha', '1.0.0-alpha.1', '1.0.0-rc.2', '1.0.0-rc.10', '1.0.0']);
    });
});

describe('planBump', () => {
    it('sets the public packages’ versions and every workspace range on them, keeping the formatting', () => {
        const changes: { dir: string; text: string }[] = planBump([core, cli, tool], '0.2.0');
        const byDir = new Map(changes.map((c) => [c.dir, c.text]));
        expect(byDir.get('packages/core')).toBe(core.text.replace('"version": "0.1.0",\n  "description"', '"version": "0.2.0",\n  "description"'));
        expect(byDir.get('packages/cli')).toBe(
            cli.text.replace('"version": "0.1.0"', '"version": "0.2.0"').replace('"@x/core": "0.1.0"', '"@x/core": "0.2.0"'),
        );
        // the private package keeps its version; its range on a public one follows the release
        expect(byDir.get('packages/tool')).toBe(tool.text.replace('"@x/core": "0.1.0"', '"@x/core": "0.2.0"'));
    });
    it('leaves nested "version" members, prose and ranges on private or third-party packages alone', () => {
        const [coreChange] = planBump([core], '3.0.0');
        const json = JSON.parse(coreChange.text);
        expect(json.version).toBe('3.0.0');
        expect(json.description).toBe(JSON.parse(core.text).description);
        expect(json.maa.generators[0].version).toBe('0.1.0');
        const cliJson = JSON.parse(planBump([core, cli, tool], '3.0.0')[1].text);
        expect(cliJson.devDependencies['@x/tool']).toBe('0.1.0');
        expect(cliJson.dependencies.commander).toBe('^14.0.3');
    });
    it('changes nothing when no package is public', () => {
        expect(planBump([tool], '9.0.0')).toEqual([]);
    });
});

describe('package.json edits', () => {
    it('fail loudly when the member is missing', () => {
        expect(() => setTopLevelVersion('{ "name": "a" }', '1.0.0')).toThrow('no top-level "version"');
        expect(() => setDependencyRange('{ "dependencies": {} }', 'dependencies', 'b', '1.0.0')).toThrow('no "b" in "dependencies"');
        expect(() => setDependencyRange('{ "name": "a" }', 'dependencies', 'b', '1.0.0')).toThrow('no "b" in "dependencies"');
    });
});

describe('sharedVersion and dependencyOrder', () => {
    it('requires one version across the public packages', () => {
        expect(sharedVersion([core, cli, tool])).toBe('0.1.0');
        const other = pkg('packages/other', '{ "name": "@x/other", "version": "0.3.0" }');
        expect(() => sharedVersion([core, other])).toThrow('@x/core@0.1.0, @x/other@0.3.0');
    });
    it('puts every package after the workspace packages it depends on', () => {
        expect(dependencyOrder([cli, core]).map((p: Pkg) => p.json['name'])).toEqual(['@x/core', '@x/cli']);
        const a = pkg('a', '{ "name": "a", "version": "1.0.0", "dependencies": { "b": "1.0.0" } }');
        const b = pkg('b', '{ "name": "b", "version": "1.0.0", "dependencies": { "a": "1.0.0" } }');
        expect(() => dependencyOrder([a, b])).toThrow('dependency cycle: a -> b -> a');
    });
});

describe('packedTargets', () => {
    const manifest = {
        bin: { tool: './bin/tool.js' },
        exports: { '.': { types: './dist/index.d.ts', default: './dist/index.js' }, './data/*': './data/*.json', './package.json': './package.json' },
    };
    it('lists the files bin and exports name', () => {
        expect(packedTargets(manifest)).toEqual(['bin/tool.js', 'data/*.json', 'dist/index.d.ts', 'dist/index.js', 'package.json']);
    });
    it('names the targets missing from a tarball', () => {
        const files = ['bin/tool.js', 'dist/index.js', 'data/a.json', 'package.json'];
        expect(missingPackedTargets(manifest, files)).toEqual(['dist/index.d.ts']);
        expect(missingPackedTargets(manifest, ['bin/tool.js', 'dist/index.js', 'dist/index.d.ts', 'package.json'])).toEqual(['data/*.json']);
    });
});
