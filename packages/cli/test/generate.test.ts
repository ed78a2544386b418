import { execFile } from 'node:child_process';
import { chmodSync, existsSync, readdirSync, readFileSync, readlinkSync, statSync } from 'node:fs';
import path from 'node:path';
// The subpath: '@maa/generator-core/node' would have Vitest load all of generator-core and Langium into the test.
import { killWhenPaused } from '@maa/generator-core/pause';
import { afterEach, beforeAll, describe, expect, it } from 'vitest';
import { BIN, ModelDir, parseTextLines, requireBuiltCli, runCli, runCliInProcess } from './helpers.js';

// `maa-gen generate` and `maa-gen generators` against a generator package installed in the
// test folder's node_modules (small generators written here; the real ones are separate packages).
// maa-gen runs in a warm worker thread (runCliInProcess) except where the process itself is tested:
// a usage error and help through the bin, a generator failing by its environment, a run without
// write permission, and runs killed while writing.

const MODELS: Record<string, string> = {
    'models/robot/Robot.arc':
        'package robot;\n\nimport robot.types.*;\n\ncomponent Robot {\n  port out Mode mode;\n  Sensor sensor;\n  Ctrl ctrl;\n\n  sensor.value -> ctrl.distance;\n  ctrl.mode -> mode;\n}\n',
    'models/robot/Sensor.arc': 'package robot;\n\n<<handwritten>> component Sensor {\n  port out int value;\n}\n',
    'models/robot/Ctrl.arc': [
        'package robot;',
        '',
        'import robot.types.*;',
        '',
        'component Ctrl {',
        '  port in int distance;',
        '  port out Mode mode;',
        '',
        '  automaton {',
        '    initial { mode = Mode.IDLE; } state Idle;',
        '    state Busy;',
        '    Idle -> Busy [distance < 10] / { mode = Mode.BUSY; };',
        '  }',
        '}',
        '',
    ].join('\n'),
    'models/robot/types/Types.cd': 'package robot.types;\n\nclassdiagram Types {\n  enum Mode { IDLE, BUSY; }\n}\n',
    'models/App.arcapp': [
        'application Demo for robot.Robot {',
        '  platform alpha {',
        '    t.Components;',
        '    t.Automata;',
        '    t.DataTypes;',
        '  }',
        '  platform beta {',
        '    t.Components;',
        '    t.DataTypes;',
        '  }',
        '}',
        '',
    ].join('\n'),
};

const GENERATORS: Record<string, string> = {
    'node_modules/t-gens/package.json': JSON.stringify({
        name: 't-gens',
        version: '1.0.0',
        type: 'module',
        maa: {
            generators: [
                {
                    name: 't.Components',
                    kind: 'component',
                    supports: ['compute'],
                    output: { gpl: 'python', rte: 't-rte' },
                    entry: 'components.js',
                    templates: 'templates',
                    checks: ['components.BehaviorOrHandwritten'],
                },
                'automata.json',
                { name: 't.DataTypes', kind: 'datatype', output: { gpl: 'python' }, entry: 'datatypes.js' },
            ],
        },
    }),
    'node_modules/t-gens/automata.json': JSON.stringify({
        name: 't.Automata',
        kind: 'behavior',
        language: 'automaton',
        output: { gpl: 'python', rte: 't-rte' },
        entry: 'automata.js',
        requires: ['ports'],
    }),
    'node_modules/t-gens/components.js': [
        'export default function create() {',
        '  return { kind: "component", async generate(ctx) {',
        '    if (process.env.T_GENS_FAIL) throw new Error("components exploded");',
        '    for (const c of ctx.architecture.components) {',
        '      const f = ctx.out.file(`components/${c.name}.py`);',
        '      f.render("component.py.njk", { c }, c.node);',
        '      const d = await ctx.behavior(c);',
        '      if (d) f.line(`# behavior: ${d.handledBy} ${d.language}`);',
        '      if (c.handwritten) ctx.out.file(`user/${c.name}_impl.py`, { userFile: true }).line("# yours");',
        '    }',
        '  } };',
        '}',
        '',
    ].join('\n'),
    'node_modules/t-gens/automata.js':
        'export default { kind: "behavior", generate(b, ctx) { ctx.out.file(`behaviors/${b.component}.py`).line(`# ports ${ctx.ports.map((p) => p.name)}`, b.node); return {}; } };\n',
    'node_modules/t-gens/datatypes.js':
        'export default { kind: "datatype", generate(ctx) { const f = ctx.out.file("types.py"); for (const t of ctx.dataTypes) f.line(`class ${t.name}: pass`, t.node); } };\n',
    'node_modules/t-gens/templates/component.py.njk':
        'class {{ c.name | pascal_case }}:\n{% for p in c.ports %}\n{% trace p %}\n    {{ p.name | snake_case }} = None  # {{ p.direction }} {{ p.typeName }}\n{% endtrace %}\n{% endfor %}\n',
};

beforeAll(() => requireBuiltCli());

/** Every file below a folder (links followed) with its content. */
function tree(dir: string, rel = ''): Record<string, string> {
    const out: Record<string, string> = {};
    for (const name of readdirSync(path.join(dir, rel)).sort()) {
        const r = rel ? `${rel}/${name}` : name;
        if (statSync(path.join(dir, r)).isDirectory()) Object.assign(out, tree(dir, r));
        else out[r] = readFileSync(path.join(dir, r), 'utf8');
    }
    return out;
}

/** Runs maa-gen as a user whom file permissions bind (root is not bound: then as nobody). */
function runCliAs(args: string[], cwd: string): Promise<{ code: number | null; stdout: string; stderr: string }> {
    // Root ignores permissions: it runs maa-gen without capabilities (setpriv), still able to read a
    // clone only root may enter (mktemp -d), or else as nobody.
    const root = process.getuid?.() === 0;
    const setpriv = root && existsSync('/usr/bin/setpriv');
    const command = setpriv ? '/usr/bin/setpriv' : process.execPath;
    const commandArgs = setpriv ? ['--bounding-set=-all', '--inh-caps=-all', '--', process.execPath, BIN, ...args] : [BIN, ...args];
    const asUser = root && !setpriv ? { uid: 65534, gid: 65534 } : {};
    return new Promise((resolve, reject) => {
        execFile(command, commandArgs, { cwd, env: { ...process.env, NO_COLOR: '1' }, ...asUser }, (error, stdout, stderr) => {
            if (error && typeof error.code !== 'number') reject(error);
            else resolve({ code: error ? (error.code as number) : 0, stdout, stderr });
        });
    });
}

let dirs: ModelDir[] = [];
function workspace(extra: Record<string, string> = {}): ModelDir {
    const d = new ModelDir();
    dirs.push(d);
    for (const [rel, text] of Object.entries({ ...MODELS, ...GENERATORS, ...extra })) d.write(rel, text);
    return d;
}
afterEach(() => {
    for (const d of dirs) d.dispose();
    dirs = [];
});

describe('maa-gen generators', () => {
    it('lists the generators of installed packages', async () => {
        const w = workspace();
        const r = await runCliInProcess(['generators'], w.dir);
        expect(r.code).toBe(0);
        const lines = r.stdout.trim().split('\n');
        expect(lines[0]).toMatch(/^NAME\s+KIND\s+LANGUAGE\s+GPL\s+RTE\s+CHECKS\s+PACKAGE$/);
        // Generators installed next to maa-gen itself are listed too; these are the test folder's.
        expect(
            lines
                .slice(1)
                .map((l) => l.split(/\s{2,}/))
                .filter((cells) => cells[6] === 't-gens@1.0.0'),
        ).toEqual([
            ['t.Automata', 'behavior', 'automaton', 'python', 't-rte', '-', 't-gens@1.0.0'],
            ['t.Components', 'component', '(compute)', 'python', 't-rte', 'components.BehaviorOrHandwritten', 't-gens@1.0.0'],
            ['t.DataTypes', 'datatype', '-', 'python', '-', '-', 't-gens@1.0.0'],
        ]);
        expect(r.stderr.trim()).toMatch(/^\d+ generators from \d+ packages?$/);
    });

    it('reports invalid manifests naming the package and the field, and exits 1', async () => {
        const w = workspace({
            'node_modules/bad-gens/package.json': JSON.stringify({
                name: 'bad-gens',
                maa: { generators: [{ name: 'b.X', kind: 'behavior', output: { gpl: 'python', rte: 'r' }, entry: 'x.js' }] },
            }),
        });
        const r = await runCliInProcess(['generators', '--format', 'json'], w.dir);
        expect(r.code).toBe(1);
        const report = JSON.parse(r.stdout) as {
            generators: Array<{ name: string; package: string }>;
            problems: Array<{ package: string; field: string; message: string }>;
        };
        expect(report.generators.filter((g) => g.package === 't-gens').map((g) => g.name)).toEqual([
            't.Automata',
            't.Components',
            't.DataTypes',
        ]);
        expect(report.problems.filter((p) => p.package === 'bad-gens')).toEqual([
            {
                package: 'bad-gens',
                file: path.join(w.dir, 'node_modules/bad-gens/package.json'),
                field: 'maa.generators[0]',
                message: "missing required field 'language'",
            },
        ]);
        const text = await runCliInProcess(['generators'], w.dir);
        expect(text.code).toBe(1);
        expect(text.stderr).toContain(
            `error: generator package bad-gens (${path.join(w.dir, 'node_modules/bad-gens/package.json')}): maa.generators[0]: missing required field 'language'`,
        );
    });
});

describe('maa-gen generate', () => {
    it('generates a platform, reports each generator with its file count, and writes a trace', async () => {
        const w = workspace();
        const r = await runCliInProcess(['generate', 'models/App.arcapp', '--platform', 'alpha', '--out', 'out'], w.dir);
        expect(r.stdout).toBe('');
        expect(r.stderr.split('\n').filter(Boolean)).toEqual([
            'alpha: t.Components: 4 files',
            'alpha: t.Automata: 1 file',
            'alpha: t.DataTypes: 1 file',
            'alpha: 6 files in out/alpha (6 written, 0 unchanged)',
            '0 errors, 0 warnings; generated 6 files for 1 platform',
        ]);
        expect(r.code).toBe(0);
        expect(readFileSync(w.path('out/alpha/components/Ctrl.py'), 'utf8')).toBe(
            'class Ctrl:\n    distance = None  # in int\n    mode = None  # out Mode\n# behavior: behavior-generator automaton\n',
        );
        // The trace file's format is @maa/protocol's TraceFile: generated lines 0-based, both ends inclusive.
        const trace = JSON.parse(readFileSync(w.path('out/alpha/.maa-trace.json'), 'utf8')) as {
            files: Array<{
                path: string;
                traces: Array<{ lines: { first: number; last: number }; element: { file: string; type: string } }>;
            }>;
        };
        const ctrl = trace.files.find((f) => f.path === 'components/Ctrl.py')!;
        expect(ctrl.traces.map((t) => `${t.lines.first}-${t.lines.last} ${t.element.type} ${t.element.file}`)).toEqual([
            '0-2 ComponentType robot/Ctrl.arc',
            '1-1 Port robot/Ctrl.arc',
            '2-2 Port robot/Ctrl.arc',
        ]);
        // Again: nothing changes, the user file is kept.
        const again = await runCliInProcess(['generate', 'models/App.arcapp', '-p', 'alpha', '-o', 'out'], w.dir);
        expect(again.code).toBe(0);
        expect(again.stderr).toContain('alpha: 6 files in out/alpha (0 written, 5 unchanged, 1 user file kept)');
    });

    it('reports configuration errors of the platform with exit 1 and writes nothing', async () => {
        const w = workspace();
        const r = await runCliInProcess(['generate', 'models/App.arcapp', '--platform', 'beta', '--out', 'out'], w.dir);
        expect(r.code).toBe(1);
        const lines = parseTextLines(r.stdout);
        expect(lines.map((l) => `${l['file']}:${l['line']} ${l['code']}`)).toEqual(['models/App.arcapp:7 app/uncovered-behavior-language']);
        expect(r.stderr.trim().split('\n').pop()).toBe('1 error, 0 warnings; nothing was generated');
        expect(existsSync(w.path('out'))).toBe(false);
    });

    it('a failing generator writes nothing (text and JSON)', async () => {
        const w = workspace();
        const { execFile } = await import('node:child_process');
        const run = (args: string[]) =>
            new Promise<{ code: number; stdout: string }>((resolve) => {
                execFile(
                    process.execPath,
                    [BIN, ...args],
                    { cwd: w.dir, env: { ...process.env, NO_COLOR: '1', T_GENS_FAIL: '1' } },
                    (error, stdout) => resolve({ code: error ? (error.code as number) : 0, stdout }),
                );
            });
        const r = await run(['generate', 'models/App.arcapp', '-p', 'alpha', '-o', 'out', '--format', 'json']);
        expect(r.code).toBe(1);
        const report = JSON.parse(r.stdout) as {
            diagnostics: Array<{ code: string; message: string }>;
            summary: { ok: boolean; errors: number };
        };
        expect(report.summary).toMatchObject({ ok: false, errors: 1 });
        expect(report.diagnostics[0]!.code).toBe('gen/generator-failed');
        expect(report.diagnostics[0]!.message).toContain("Generator 't.Components' failed: components exploded");
        expect(existsSync(w.path('out'))).toBe(false);
    });

    it('usage problems exit 2', async () => {
        const w = workspace();
        // the first through the bin (its exit code and stderr), the others in the warm worker thread
        const missing = await runCli(['generate', 'nope.arcapp'], w.dir);
        expect(missing.code).toBe(2);
        expect(missing.stderr).toBe('maa-gen: error: path not found: nope.arcapp\n');
        const wrong = await runCliInProcess(['generate', 'models/robot/Ctrl.arc'], w.dir);
        expect(wrong.code).toBe(2);
        expect(wrong.stderr).toContain('not an application configuration (expected .arcapp)');
        const platform = await runCliInProcess(['generate', 'models/App.arcapp', '--platform', 'gamma'], w.dir);
        expect(platform.code).toBe(2);
        expect(platform.stderr).toBe("maa-gen: error: application 'Demo' has no platform 'gamma' (platforms: alpha, beta)\n");
    });

    it('the JSON report is one object on stdout, two-space indented, with the documented fields in order', async () => {
        const w = workspace();
        const r = await runCliInProcess(['generate', 'models/App.arcapp', '-p', 'alpha', '-o', 'out', '--format', 'json'], w.dir);
        expect(r.code).toBe(0);
        expect(r.stderr).toBe('');
        const report = JSON.parse(r.stdout) as {
            diagnostics: unknown[];
            platforms: Array<Record<string, unknown> & { files: string[]; written: string[] }>;
            summary: unknown;
        };
        expect(r.stdout).toBe(`${JSON.stringify(report, null, 2)}\n`);
        expect(Object.keys(report)).toEqual(['diagnostics', 'platforms', 'summary']);
        expect(report.diagnostics).toEqual([]);
        expect(report.platforms.map((p) => Object.keys(p))).toEqual([
            ['platform', 'outDir', 'generators', 'files', 'written', 'unchanged', 'kept', 'removed', 'keptStale'],
        ]);
        expect(report.platforms[0]!.platform).toBe('alpha');
        expect(report.platforms[0]!.files).toHaveLength(6);
        expect(report.platforms[0]!.written).toHaveLength(6);
        expect(JSON.stringify(report.summary)).toBe('{"ok":true,"errors":0,"warnings":0,"files":6,"platforms":1}');
    });

    it('a folder as the application or a missing --root folder is a usage problem (exit 2)', async () => {
        const w = workspace();
        const folder = await runCliInProcess(['generate', 'models'], w.dir);
        expect(folder.code).toBe(2);
        expect(folder.stderr).toBe('maa-gen: error: not a file: models\n');
        const root = await runCliInProcess(['generate', 'models/App.arcapp', '--root', 'nowhere'], w.dir);
        expect(root.code).toBe(2);
        expect(root.stderr).toBe('maa-gen: error: model root not found: nowhere\n');
        const fileRoot = await runCliInProcess(['generate', 'models/App.arcapp', '--root', 'models/App.arcapp'], w.dir);
        expect(fileRoot.code).toBe(2);
        expect(fileRoot.stderr).toBe('maa-gen: error: model root not found: models/App.arcapp\n');
        expect(existsSync(w.path('models/generated'))).toBe(false);
    });

    it('an output that cannot be written exits 2, names the folder and changes nothing', async () => {
        const w = workspace();
        expect((await runCliInProcess(['generate', 'models/App.arcapp', '-p', 'alpha', '-o', 'out'], w.dir)).code).toBe(0);
        const before = tree(w.path('out/alpha'));
        w.write(
            'models/robot/Sensor.arc',
            'package robot;\n\n<<handwritten>> component Sensor {\n  port out int value;\n  port out int extra;\n}\n',
        );
        // Read-only, as a full disk or a read-only mount would be (runCliAs: root runs maa-gen without capabilities).
        chmodSync(w.dir, 0o755);
        chmodSync(w.path('out'), 0o555);
        chmodSync(w.path('out/.maa-gen'), 0o555);
        try {
            const r = await runCliAs(['generate', 'models/App.arcapp', '-p', 'alpha', '-o', 'out'], w.dir);
            const errors = parseTextLines(r.stdout).filter((l) => l['severity'] === 'error');
            expect(errors.map((l) => `${l['code']} ${l['message']}`)).toEqual([
                'gen/write-failed Cannot write the output: out: permission denied. Nothing was changed.',
            ]);
            expect(r.stderr.trim().split('\n').pop()).toBe('1 error, 1 warning; nothing was generated');
            expect(r.code).toBe(2);
        } finally {
            chmodSync(w.path('out'), 0o755);
            chmodSync(w.path('out/.maa-gen'), 0o755);
        }
        expect(tree(w.path('out/alpha'))).toEqual(before);
    });

    it('a file where the platform folder belongs exits 2 naming it (JSON too)', async () => {
        const w = workspace();
        w.write('out/alpha', 'my notes\n');
        const r = await runCliInProcess(['generate', 'models/App.arcapp', '-p', 'alpha', '-o', 'out', '--format', 'json'], w.dir);
        expect(r.code).toBe(2);
        const report = JSON.parse(r.stdout) as { diagnostics: Array<{ code: string; message: string }>; summary: { ok: boolean } };
        expect(report.summary.ok).toBe(false);
        expect(report.diagnostics.map((d) => `${d.code} ${d.message}`)).toEqual([
            'gen/write-failed Cannot write the output: out/alpha: is a file where the platform folder is needed. Nothing was changed.',
        ]);
        expect(readFileSync(w.path('out/alpha'), 'utf8')).toBe('my notes\n');
    });

    it('killed at each phase of writing (MAA_GEN_PAUSE_AT), the platform folder is wholly old or new, and the next run succeeds', async () => {
        const w = workspace();
        const args = ['generate', 'models/App.arcapp', '-p', 'alpha', '-o', 'out'];
        expect((await runCliInProcess(args, w.dir)).code).toBe(0);
        const older = tree(w.path('out/alpha'));
        w.write(
            'models/robot/Sensor.arc',
            'package robot;\n\n<<handwritten>> component Sensor {\n  port out int value;\n  port out int extra;\n}\n',
        );
        expect((await runCliInProcess(args, w.dir)).code).toBe(0);
        const newer = tree(w.path('out/alpha'));
        expect(newer).not.toEqual(older);
        const sensor = (extra: boolean): string =>
            `package robot;\n\n<<handwritten>> component Sensor {\n  port out int value;\n${extra ? '  port out int extra;\n' : ''}}\n`;
        for (const phase of ['staging', 'commit', 'cleanup']) {
            // Each run switches between the two trees: the model goes back and forth.
            const fromNewer = JSON.stringify(tree(w.path('out/alpha'))) === JSON.stringify(newer);
            const [from, to] = fromNewer ? [newer, older] : [older, newer];
            w.write('models/robot/Sensor.arc', sensor(!fromNewer));
            const paused = await killWhenPaused(process.execPath, [BIN, ...args], `${phase}:2`, {
                cwd: w.dir,
                env: { ...process.env, NO_COLOR: '1' },
            });
            expect(paused).toMatch(new RegExp(`^${phase} \\d+$`));
            expect(tree(w.path('out/alpha')), `killed at ${paused}`).toEqual(phase === 'staging' ? from : to);
            const again = await runCliInProcess(args, w.dir);
            expect(again.code).toBe(0);
            expect(tree(w.path('out/alpha'))).toEqual(to);
            // Nothing of the killed run is left: the state folder holds the current version only.
            expect(readdirSync(w.path('out/.maa-gen'))).toEqual([path.basename(readlinkSync(w.path('out/alpha')))]);
        }
    });

    it('is listed in the help', async () => {
        const r = await runCli(['--help'], process.cwd());
        expect(r.stdout).toMatch(/generate \[options\] <app>/);
        expect(r.stdout).toMatch(/generators \[options\]/);
    });
});
