// The public packages as published (docs/releasing.md): what a user installs must be complete
// without the repository. The pack-and-install test (scripts/pack-install.mjs) uses them; these
// checks name the package.json field that is wrong, quickly, on the built tree.
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { builtinModules } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
// @ts-expect-error -- a plain .mjs script without type declarations
import { DEPENDENCY_FIELDS, publicPackages, readWorkspace } from '../release/packages.mjs';

interface Workspace {
    dir: string;
    json: {
        name: string;
        version: string;
        private?: boolean;
        files?: string[];
        publishConfig?: { access?: string };
        dependencies?: Record<string, string>;
        peerDependencies?: Record<string, string>;
        [field: string]: unknown;
    };
}

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const workspace: Workspace[] = readWorkspace(repo);
const published: Workspace[] = publicPackages(workspace);
const versions = new Map(workspace.map((w) => [w.json.name, w.json.version]));

/** The packages a bare import names in a module's text (`import ... from 'x'`, `import('x')`), Node's built-ins left out. */
function importedPackages(text: string): Set<string> {
    const names = new Set<string>();
    for (const m of text.matchAll(/(?:\bfrom\s*|\bimport\s*\(\s*|\bimport\s+)['"]([^'"./][^'"]*)['"]/g)) {
        const specifier = m[1]!;
        // words like `from 'x'` in string lists (Python's keywords) are no imports: package names only
        if (!/^(@[a-z0-9][\w.-]*\/)?[a-z0-9][\w.-]*(\/[\w./-]*)?$/i.test(specifier)) continue;
        if (specifier.startsWith('node:') || builtinModules.includes(specifier.split('/')[0]!)) continue;
        names.add(specifier.startsWith('@') ? specifier.split('/').slice(0, 2).join('/') : specifier.split('/')[0]!);
    }
    return names;
}

/** The JavaScript files a package ships (its `files` entries that are folders or .js/.mjs files). */
function shippedModules(w: Workspace): string[] {
    const out: string[] = [];
    const visit = (file: string): void => {
        if (!existsSync(file)) return;
        if (/\.m?js$/.test(file)) out.push(file);
        else if (!path.extname(file)) {
            for (const e of readdirSync(file, { withFileTypes: true })) {
                if (e.name !== 'node_modules' && e.name !== '__pycache__') visit(path.join(file, e.name));
            }
        }
    };
    for (const entry of w.json.files ?? []) if (!entry.startsWith('!')) visit(path.join(repo, w.dir, entry));
    return out;
}

describe('the public packages', () => {
    it('include the CLI, the IDE and everything they run on; build tools stay private', () => {
        const names = published.map((w) => w.json.name).sort();
        expect(names).toEqual(
            expect.arrayContaining([
                '@maa/cli',
                '@maa/generator-core',
                '@maa/generators-python',
                '@maa/ide-server',
                '@maa/ide-web',
                '@maa/language-adl',
                '@maa/language-automata',
                '@maa/language-cd',
                '@maa/language-robotarm',
                '@maa/language-server',
                '@maa/protocol',
                '@maa/sim-server',
            ]),
        );
        expect(names).not.toContain('@maa/grammar-composer');
    });

    it('share one version, are scoped, published publicly, and list their files and a README', () => {
        for (const w of published) {
            expect(w.json.name, w.dir).toMatch(/^@maa\/[a-z-]+$/);
            expect(w.json.version, w.json.name).toBe(versions.get('@maa/cli'));
            expect(w.json.publishConfig?.access, w.json.name).toBe('public');
            expect(w.json.files?.length, `${w.json.name} has no "files"`).toBeGreaterThan(0);
            expect(existsSync(path.join(repo, w.dir, 'README.md')), `${w.json.name} has no README.md`).toBe(true);
            expect(w.json['engines'], w.json.name).toEqual({ node: '>=20.10' });
        }
    });

    it("carry the repository's license: the field, and a prepack that puts LICENSE into the tarball", () => {
        const license = readFileSync(path.join(repo, 'LICENSE'), 'utf8');
        expect(license.split('\n')[0]).toBe('MIT License');
        for (const w of published) {
            expect(w.json['license'], w.json.name).toBe('MIT');
            const prepack = (w.json['scripts'] as Record<string, string> | undefined)?.['prepack'];
            expect(prepack, `${w.json.name} has no prepack`).toBe(`node ${path.relative(path.join(repo, w.dir), path.join(repo, 'scripts/release/copy-license.mjs'))}`);
        }
    });

    it('depend on workspace packages that are public, at exactly their version', () => {
        for (const w of published) {
            for (const [dep, range] of Object.entries(w.json.dependencies ?? {})) {
                const version = versions.get(dep);
                if (version === undefined) continue;
                expect(published.some((p) => p.json.name === dep), `${w.json.name} depends on the private ${dep}`).toBe(true);
                expect(range, `${w.json.name} -> ${dep}`).toBe(version);
            }
        }
    });

    it('declare every package their shipped modules import as a dependency (or an optional peer)', () => {
        // a package without exports, main or bin (ide-web: a browser bundle maa-ide serves) is never loaded by Node
        for (const w of published.filter((p) => p.json['exports'] || p.json['main'] || p.json['bin'])) {
            const declared = new Set([...Object.keys(w.json.dependencies ?? {}), ...Object.keys(w.json.peerDependencies ?? {}), w.json.name]);
            const missing = new Set<string>();
            for (const file of shippedModules(w)) {
                for (const name of importedPackages(readFileSync(file, 'utf8'))) if (!declared.has(name)) missing.add(`${name} (${path.relative(repo, file)})`);
            }
            expect([...missing], `${w.json.name} imports packages it does not depend on`).toEqual([]);
        }
    });

    it('the CLI depends on the default generator families and the simulator', () => {
        const cli = published.find((w) => w.json.name === '@maa/cli')!;
        expect(Object.keys(cli.json.dependencies ?? {})).toEqual(expect.arrayContaining(['@maa/generators-python', '@maa/sim-server']));
    });

    it('every dependency field is an object of ranges', () => {
        for (const w of workspace) {
            for (const field of DEPENDENCY_FIELDS as string[]) {
                const deps = w.json[field];
                if (deps === undefined) continue;
                for (const range of Object.values(deps as Record<string, unknown>)) expect(typeof range, `${w.json.name} ${field}`).toBe('string');
            }
        }
    });
});
