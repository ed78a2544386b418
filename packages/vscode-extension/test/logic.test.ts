// The extension's own logic, without an editor: the platform quick pick from .arcapp texts, the
// trace lookups in both directions, the settings as server start options and generate arguments,
// and the CLI's JSON report as diagnostics (the last one from a real `maa-gen generate` run).
import { execFile } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { TRACE_FORMAT_VERSION, type TraceFile } from '@maa/protocol';
import { afterAll, describe, expect, it } from 'vitest';
import { parseGenerateReport, summaryMessage } from '../src/generate-report.js';
import { platformItems, platformsOf } from '../src/platforms.js';
import { contributions } from '../src/contributions.js';
import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import {
    type ContributedLanguage,
    generateArgs,
    generateCommand,
    outDirOf,
    readSettings,
    serverStart,
    SETTINGS,
    watchedFiles,
} from '../src/settings.js';
import { generatedCodeAt, modelElementAt, modelFileOf, platformDirOf } from '../src/trace.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
const tmp = mkdtempSync(path.join(tmpdir(), 'maa-vscode-'));
afterAll(() => rmSync(tmp, { recursive: true, force: true }));

describe('platform quick pick', () => {
    it('lists the platforms of every application configuration, skipping comments and strings', () => {
        const tr = `// platform commented { }\napplication TR for toast.Robot {\n  platform rospython { ros2.Components; }\n  platform timesync {\n    timesync.Components; /* platform fake { */\n  }\n}`;
        expect(platformsOf(tr)).toEqual({ application: 'TR', platforms: ['rospython', 'timesync'] });
        const items = platformItems([
            {
                file: '/w/b/B.arcapp',
                displayPath: 'b/B.arcapp',
                text: 'application B for p.C { platform timesync { timesync.Components; } }',
            },
            { file: '/w/a/TR.arcapp', displayPath: 'a/TR.arcapp', text: tr },
            { file: '/w/broken.arcapp', displayPath: 'broken.arcapp', text: '/* no application here */' },
        ]);
        expect(items.map((i) => [i.label, i.description, i.appFile])).toEqual([
            ['rospython', 'TR — a/TR.arcapp', '/w/a/TR.arcapp'],
            ['timesync', 'TR — a/TR.arcapp', '/w/a/TR.arcapp'],
            ['timesync', 'B — b/B.arcapp', '/w/b/B.arcapp'],
        ]);
    });

    it('an application without platforms gives no items', () => {
        expect(platformsOf('application A for p.C { }')).toEqual({ application: 'A', platforms: [] });
        expect(platformItems([{ file: '/a', displayPath: 'a', text: 'application A for p.C { }' }])).toEqual([]);
    });
});

/** A trace of one generated file with a component (lines 0-20) and one of its ports (line 4). */
function trace(): TraceFile {
    const element = (path_: string, type: string, start: number, end: number, name: string) => ({
        file: 'demo/Lamp.arc',
        range: { start: { line: start, character: 0 }, end: { line: end, character: 1 } },
        path: path_,
        type,
        name,
    });
    return {
        version: TRACE_FORMAT_VERSION,
        application: 'App',
        platform: 'timesync',
        rootComponent: 'demo.Lamp',
        modelRoot: '../../models',
        generators: [],
        files: [
            {
                path: 'demo/lamp.py',
                generator: 'timesync.Components',
                userFile: false,
                sha256: '0'.repeat(64),
                lines: 30,
                traces: [
                    {
                        lines: { first: 0, last: 20 },
                        generator: 'timesync.Components',
                        element: element('/', 'ComponentType', 2, 12, 'Lamp'),
                    },
                    { lines: { first: 4, last: 4 }, generator: 'timesync.Components', element: element('/ports@0', 'Port', 3, 3, 'press') },
                ],
            },
        ],
    };
}

describe('trace lookups', () => {
    const platformDir = path.join('/p', 'gen', 'timesync');
    const model = path.join('/p', 'models', 'demo', 'Lamp.arc');

    it('model file paths resolve through the model root relative to the platform folder', () => {
        expect(modelFileOf(trace(), platformDir, 'demo/Lamp.arc')).toBe(model);
        expect(modelFileOf(trace(), platformDir, 'file:///x/y.arc')).toBe('file:///x/y.arc');
    });

    it('model → generated: the innermost element at the cursor', () => {
        expect(generatedCodeAt(trace(), platformDir, model, { line: 3, character: 0 })).toEqual([
            { file: path.join(platformDir, 'demo', 'lamp.py'), first: 4, last: 4, generator: 'timesync.Components' },
        ]);
        expect(generatedCodeAt(trace(), platformDir, model, { line: 8, character: 0 })[0]).toMatchObject({ first: 0, last: 20 });
        expect(generatedCodeAt(trace(), platformDir, model, { line: 13, character: 0 })).toEqual([]);
        expect(generatedCodeAt(trace(), platformDir, '/p/models/demo/Other.arc', { line: 3, character: 0 })).toEqual([]);
    });

    it('generated → model: the narrowest span around the line', () => {
        const file = path.join(platformDir, 'demo', 'lamp.py');
        expect(modelElementAt(trace(), platformDir, file, 4)).toMatchObject({ file: model, type: 'Port', name: 'press' });
        expect(modelElementAt(trace(), platformDir, file, 10)).toMatchObject({ file: model, type: 'ComponentType', name: 'Lamp' });
        expect(modelElementAt(trace(), platformDir, file, 25)).toBeUndefined();
        expect(modelElementAt(trace(), platformDir, path.join(platformDir, 'other.py'), 4)).toBeUndefined();
    });

    it('a generated file belongs to the nearest folder with a trace file', () => {
        const dirs = ['/p/gen', '/p/gen/timesync', '/p/gen/rospython'];
        expect(platformDirOf('/p/gen/timesync/demo/lamp.py', dirs)).toBe(path.resolve('/p/gen/timesync'));
        expect(platformDirOf('/p/genx/a.py', dirs)).toBeUndefined();
    });
});

describe('settings', () => {
    it("defaults are the manifest defaults and maa-gen's", () => {
        const s = readSettings(() => undefined);
        expect(s).toEqual({ outDir: 'generated', command: '', nodeArgs: [] });
        expect(SETTINGS['maa.generate.outDir'].default).toBe('generated');
        expect(outDirOf('/w/app/App.arcapp', s)).toBe(path.resolve('/w/app/generated'));
    });

    it('become the server start options (IPC module, Node options; debug adds an inspector)', () => {
        const s = readSettings((k) => ({ 'maa.server.nodeArgs': ['--max-old-space-size=4096', 3] })[k]);
        const start = serverStart('/ext/out/server/main.mjs', s);
        expect(start.run).toEqual({ module: '/ext/out/server/main.mjs', args: [], options: { execArgv: ['--max-old-space-size=4096'] } });
        expect(start.debug.options.execArgv).toEqual(['--max-old-space-size=4096', '--nolazy', '--inspect=6009']);
    });

    it('the server watches maa.json and the files of every contributed language', () => {
        const languages = contributions(LANGUAGE_FACTS).contributes['languages'] as ContributedLanguage[];
        const glob = watchedFiles(languages);
        expect(glob.startsWith('**/{maa.json,')).toBe(true);
        for (const ext of ['.arc', '.cd', '.arcapp', '.ra']) expect(glob).toContain(`*${ext},`.replace(/,$/, ''));
        expect(watchedFiles([{ id: 'x', extensions: ['.x', '.xx'] }])).toBe('**/{maa.json,*.x,*.xx}');
    });

    it('become the generate command and its arguments', () => {
        const s = readSettings((k) => ({ 'maa.generate.outDir': '/abs/out', 'maa.generate.command': ' ' })[k]);
        expect(generateArgs('/w/App.arcapp', 'timesync', s)).toEqual([
            'generate',
            '/w/App.arcapp',
            '--platform',
            'timesync',
            '--out',
            path.resolve('/abs/out'),
            '--format',
            'json',
        ]);
        const local = path.join('/w', 'node_modules', '.bin', 'maa-gen');
        expect(generateCommand(s, ['/v', '/w'], (f) => f === local)).toBe(local);
        expect(generateCommand(s, ['/w'], () => false)).toBe('maa-gen');
        expect(generateCommand({ ...s, command: '/opt/maa-gen' }, ['/w'], () => true)).toBe('/opt/maa-gen');
    });
});

/** Runs the workspace's built maa-gen with `args` (asynchronously) and resolves with its output. */
function runMaaGen(args: string[]): Promise<{ stdout: string; stderr: string }> {
    const bin = path.join(repo, 'packages', 'cli', 'bin', 'maa-gen.js');
    return new Promise((resolve) => {
        execFile(process.execPath, [bin, ...args], { cwd: tmp }, (_e, stdout, stderr) => resolve({ stdout, stderr }));
    });
}

describe('generate report', () => {
    it("maa-gen generate's JSON report of a broken model gives its errors per file", async () => {
        const root = path.join(tmp, 'proj');
        mkdirSync(path.join(root, 'demo'), { recursive: true });
        writeFileSync(path.join(root, 'maa.json'), '{}\n');
        const model = path.join(root, 'demo', 'Lamp.arc');
        writeFileSync(model, 'package demo;\n\ncomponent Lamp {\n  port in boolean press;\n  press -> nowhere;\n}\n');
        const app = path.join(root, 'App.arcapp');
        writeFileSync(app, 'application App for demo.Lamp {\n  platform timesync {\n    timesync.Components;\n  }\n}\n');
        const s = readSettings(() => undefined);
        const { stdout, stderr } = await runMaaGen(generateArgs(app, 'timesync', s));
        const report = parseGenerateReport(stdout, stderr);
        expect(report.ok).toBe(false);
        expect(report.errors).toBeGreaterThan(0);
        const errors = report.byFile.get(model) ?? [];
        expect(errors.some((d) => d.severity === 'error' && d.line === 5 && d.code.length > 0)).toBe(true);
        expect(summaryMessage('timesync', report)).toMatch(
            /^MontiArc: nothing generated for timesync \(\d+ errors?, \d+ warnings?; see Problems\)$/,
        );
        expect(existsSync(path.join(root, 'generated', 'timesync'))).toBe(false);
    }, 120_000);

    it('a successful report counts files and names the output folders', () => {
        const report = parseGenerateReport(
            JSON.stringify({
                diagnostics: [],
                platforms: [{ platform: 'timesync', outDir: '/o/timesync' }],
                summary: { ok: true, errors: 0, warnings: 1, files: 12, platforms: 1 },
            }),
        );
        expect(report).toMatchObject({ ok: true, files: 12, warnings: 1, outDirs: ['/o/timesync'] });
        expect(summaryMessage('timesync', report)).toBe('MontiArc: generated 12 files for timesync (0 errors, 1 warning)');
    });

    it('output that is no JSON report is an error naming what the CLI said', () => {
        expect(() => parseGenerateReport('', 'maa-gen: command not found')).toThrow(
            /did not print a JSON report: maa-gen: command not found/,
        );
        expect(() => parseGenerateReport('{"x":1}')).toThrow(/without diagnostics/);
    });
});

describe('trace lookups in a real generation', () => {
    it('every traced element of the minimal example leads to its generated lines and back', async () => {
        const project = path.join(tmp, 'minimal');
        cpSync(path.join(repo, 'packages', 'cli', 'templates', 'minimal'), project, { recursive: true });
        const app = path.join(project, 'App.arcapp');
        const s = readSettings(() => undefined);
        const { stdout, stderr } = await runMaaGen(generateArgs(app, 'timesync', s));
        expect(parseGenerateReport(stdout, stderr).ok, stderr).toBe(true);
        const platformDir = path.join(outDirOf(app, s), 'timesync');
        const trace = JSON.parse(readFileSync(path.join(platformDir, '.maa-trace.json'), 'utf8')) as TraceFile;
        const lamp = path.join(project, 'hello', 'Lamp.arc');
        let checked = 0;
        for (const file of trace.files) {
            for (const t of file.traces) {
                const range = t.element.range;
                if (!range) continue;
                const modelFile = modelFileOf(trace, platformDir, t.element.file);
                expect(existsSync(modelFile), modelFile).toBe(true);
                // model → generated: the element's start leads to generated code, and some of it is in this file.
                const generated = generatedCodeAt(trace, platformDir, modelFile, range.start);
                expect(generated.length, `${t.element.path} in ${t.element.file}`).toBeGreaterThan(0);
                // generated → model: the first line of this span leads to an element of the same file that contains it.
                const back = modelElementAt(trace, platformDir, path.join(platformDir, file.path), t.lines.first);
                expect(back?.file).toBe(modelFile);
                checked++;
            }
        }
        expect(checked).toBeGreaterThanOrEqual(2);
        const traced = new Set(trace.files.flatMap((f) => f.traces.map((t) => modelFileOf(trace, platformDir, t.element.file))));
        expect(traced).toContain(lamp);
        expect(traced).toContain(path.join(project, 'hello', 'Toggle.arc'));
    }, 120_000);
});
