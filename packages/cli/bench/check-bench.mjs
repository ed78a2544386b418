#!/usr/bin/env node
// Benchmark of model checking (`npm run bench` at the repository root; not a test: it asserts
// nothing about times). Generates a synthetic model root (default 1,000 components, see
// generate-models.mjs) in a temporary folder and reports:
//   - cold `maa-gen check` time and peak RSS, through the CLI as a child process;
//   - in-process `checkModelRoots` time (first and second call) and peak RSS;
//   - the language services' initial build, and the time to re-validate after a one-line
//     change (median over several changes), through DocumentBuilder.update.
// Every measurement runs in a fresh Node process of its own, so memory figures do not mix.
//
// Options: --components N (1000)  --cli-runs N (3)  --changes N (5)  --keep (keep the models)
//          --json (print the raw figures as JSON after the table)
import { execFile } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { performance } from 'node:perf_hooks';
import { EDITABLE_LINE, generateModels } from './generate-models.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const CLI = path.resolve(here, '..', 'bin', 'maa-gen.js');
const SELF = fileURLToPath(import.meta.url);
const RESULT_PREFIX = 'MAA_BENCH_RESULT ';
const RSS_PREFIX = 'MAA_BENCH_MAXRSS_KB=';

function option(name, fallback) {
    const i = process.argv.indexOf(`--${name}`);
    return i >= 0 && process.argv[i + 1] !== undefined ? process.argv[i + 1] : fallback;
}
const flag = (name) => process.argv.includes(`--${name}`);

function run(args, options = {}) {
    return new Promise((resolve, reject) => {
        const started = performance.now();
        execFile(process.execPath, args, { maxBuffer: 256 * 1024 * 1024, ...options }, (error, stdout, stderr) => {
            const ms = performance.now() - started;
            if (error && typeof error.code !== 'number') reject(error);
            else resolve({ code: error ? error.code : 0, stdout, stderr, ms });
        });
    });
}

/** The result line a phase child printed, or a clear failure. */
function phaseResult(name, r) {
    const line = r.stdout.split('\n').find((l) => l.startsWith(RESULT_PREFIX));
    if (r.code !== 0 || !line) {
        throw new Error(`bench phase "${name}" failed (exit ${r.code}):\n${r.stderr.trim()}`);
    }
    return JSON.parse(line.slice(RESULT_PREFIX.length));
}

const median = (xs) => {
    const s = [...xs].sort((a, b) => a - b);
    return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};
const maxRssKb = () => process.resourceUsage().maxRSS;
const emit = (result) => console.log(RESULT_PREFIX + JSON.stringify(result));

// ---------------------------------------------------------------------------------------------
// Phases (each in its own process)

async function phaseCheck(root) {
    const t0 = performance.now();
    const { checkModelRoots } = await import('@maa/language-server');
    const importMs = performance.now() - t0;
    const t1 = performance.now();
    const diagnostics = await checkModelRoots([{ root }]);
    const firstMs = performance.now() - t1;
    const rssAfterFirst = maxRssKb();
    const t2 = performance.now();
    await checkModelRoots([{ root }]);
    const secondMs = performance.now() - t2;
    emit({
        importMs,
        firstMs,
        secondMs,
        maxRssKb: rssAfterFirst,
        heapUsedMb: process.memoryUsage().heapUsed / 2 ** 20,
        errors: diagnostics.filter((d) => d.severity === 'error').length,
        warnings: diagnostics.filter((d) => d.severity === 'warning').length,
        sample: diagnostics
            .slice(0, 5)
            .map((d) => `${path.relative(root, d.file)}:${d.line}:${d.column} ${d.severity} ${d.code} ${d.message}`),
    });
}

async function phaseIncremental(root, editableFile, changes) {
    const { createMaaServices } = await import('@maa/language-server');
    const { URI, TextDocument } = await import('langium');
    const { NodeFileSystem } = await import('langium/node');
    const { shared } = createMaaServices(NodeFileSystem);
    const documents = shared.workspace.LangiumDocuments;
    const builder = shared.workspace.DocumentBuilder;
    const textDocuments = shared.workspace.TextDocuments;

    // Load the model root the way the language server does: the workspace manager reads every
    // model file of the workspace folder and builds all of it with validation.
    const rootUri = URI.file(root);
    const manager = shared.workspace.WorkspaceManager;
    // The model root defines the scope and the packages (folders below it).
    shared.maa?.ModelRoots?.setRoots([rootUri]);
    manager.initialBuildOptions = { ...manager.initialBuildOptions, validation: true };
    const t0 = performance.now();
    await manager.initializeWorkspace([{ name: path.basename(root), uri: rootUri.toString() }]);
    const initialMs = performance.now() - t0;
    const all = documents.all.toArray();
    const count = (doc) => ({
        errors: (doc.diagnostics ?? []).filter((d) => d.severity === 1).length,
        warnings: (doc.diagnostics ?? []).filter((d) => d.severity === 2).length,
    });
    const totals = all
        .map(count)
        .reduce((a, b) => ({ errors: a.errors + b.errors, warnings: a.warnings + b.warnings }), { errors: 0, warnings: 0 });
    const rssAfterBuild = maxRssKb();

    // One-line changes to one component: alternately introduce a type error in the line and
    // repair it, so each change really has to be re-parsed, re-linked and re-validated.
    const uri = URI.file(editableFile);
    const original = readFileSync(editableFile, 'utf8');
    const broken = original.replace(EDITABLE_LINE, '    o1 = i2;');
    const languageId = documents.getDocument(uri)?.textDocument.languageId ?? 'arc';
    // The editor path needs the TextDocuments service (present when the services include the LSP
    // module); without it, the change is written to disk, as a file watcher would report it.
    const via = textDocuments && typeof textDocuments.set === 'function' ? 'editor buffer' : 'file on disk';
    const times = [];
    const diagnosticsAfter = [];
    for (let i = 1; i <= changes; i++) {
        const text = i % 2 === 1 ? broken : original;
        const t = performance.now();
        if (via === 'editor buffer') textDocuments.set(TextDocument.create(uri.toString(), languageId, i, text));
        else writeFileSync(editableFile, text);
        await builder.update([uri], []);
        times.push(performance.now() - t);
        const doc = documents.getDocument(uri);
        if (doc?.textDocument.getText() !== text) throw new Error('the changed text did not reach the document');
        diagnosticsAfter.push(count(doc).errors);
    }
    if (via === 'file on disk') writeFileSync(editableFile, original);
    emit({
        documents: all.length,
        initialMs,
        totals,
        maxRssKbAfterBuild: rssAfterBuild,
        changeMs: times,
        via,
        changedFile: path.relative(root, editableFile),
        errorsAfterEachChange: diagnosticsAfter,
    });
}

// ---------------------------------------------------------------------------------------------
// Driver

async function driver() {
    const components = Number(option('components', '1000'));
    const cliRuns = Number(option('cli-runs', '3'));
    const changes = Number(option('changes', '5'));
    const work = mkdtempSync(path.join(tmpdir(), 'maa-bench-'));
    const root = path.join(work, 'models');
    try {
        const gen = generateModels(root, components);
        console.log(
            `maa-gen check benchmark: ${gen.atomic + gen.composed} components (${gen.atomic} atomic, ${gen.composed} composed, 10 ports each) + 1 class diagram,`,
        );
        console.log(`${gen.files.length} files, ${gen.lines} lines, in ${root}`);
        console.log(`Node ${process.version}, ${process.platform}/${process.arch}\n`);

        // A preload that reports the CLI process's peak RSS on exit.
        const probe = path.join(work, 'rss-probe.mjs');
        writeFileSync(
            probe,
            `import { writeSync } from 'node:fs';\nprocess.on('exit', () => writeSync(2, '\\n${RSS_PREFIX}' + process.resourceUsage().maxRSS + '\\n'));\n`,
        );
        const cli = [];
        for (let i = 0; i < cliRuns; i++) {
            process.stderr.write(`cli run ${i + 1}/${cliRuns}...\n`);
            const r = await run(['--import', pathToFileURL(probe).href, CLI, 'check', '--format', 'json', root], { cwd: work });
            if (r.code !== 0 && r.code !== 1) throw new Error(`maa-gen check failed (exit ${r.code}):\n${r.stderr.trim()}`);
            const rss = /MAA_BENCH_MAXRSS_KB=(\d+)/.exec(r.stderr);
            cli.push({ ms: r.ms, code: r.code, maxRssKb: rss ? Number(rss[1]) : NaN, summary: JSON.parse(r.stdout).summary });
        }

        process.stderr.write('in-process check...\n');
        const inproc = phaseResult('check', await run([SELF, '--phase', 'check', root], { cwd: work }));

        process.stderr.write('language services, one-line changes...\n');
        const editable = gen.editable[Math.floor(gen.editable.length / 2)];
        const incr = phaseResult(
            'incremental',
            await run([SELF, '--phase', 'incremental', root, editable, String(changes)], { cwd: work }),
        );

        const s = (ms) => `${(ms / 1000).toFixed(2)} s`;
        const msf = (ms) => `${ms.toFixed(0)} ms`;
        const mb = (kb) => `${(kb / 1024).toFixed(0)} MB`;
        const summary = cli[0].summary;
        const rows = [
            [
                'cold check, CLI (maa-gen check, median)',
                `${s(median(cli.map((c) => c.ms)))}  (runs: ${cli.map((c) => s(c.ms)).join(', ')})`,
            ],
            ['peak RSS, CLI process', mb(Math.max(...cli.map((c) => c.maxRssKb)))],
            [
                'cold check, in-process (checkModelRoots, 1st call)',
                `${s(inproc.firstMs)}  (+ ${msf(inproc.importMs)} to import the language server)`,
            ],
            ['repeated check, in-process (2nd call)', s(inproc.secondMs)],
            ['peak RSS, in-process after 1st check', mb(inproc.maxRssKb)],
            ['language services: load + full build with validation', `${s(incr.initialMs)}  (${incr.documents} documents)`],
            ['peak RSS, language services after build', mb(incr.maxRssKbAfterBuild)],
            [
                `re-validate after a one-line change (median of ${incr.changeMs.length})`,
                `${msf(median(incr.changeMs))}  (${incr.changeMs.map(msf).join(', ')}; via ${incr.via})`,
            ],
        ];
        const width = Math.max(...rows.map((r) => r[0].length));
        console.log(`| ${'measure'.padEnd(width)} | value`);
        console.log(`|${'-'.repeat(width + 2)}|${'-'.repeat(40)}`);
        for (const [k, v] of rows) console.log(`| ${k.padEnd(width)} | ${v}`);
        console.log(
            `\nDiagnostics of the generated models: CLI ${summary.errors} errors, ${summary.warnings} warnings in ${summary.files} files; ` +
                `language services ${incr.totals.errors} errors, ${incr.totals.warnings} warnings.`,
        );
        console.log(
            `Changed file: ${incr.changedFile}; its errors after each change: ${incr.errorsAfterEachChange.join(', ')} (odd changes break the line, even ones repair it).`,
        );
        if (inproc.sample.length > 0) console.log(`First diagnostics:\n  ${inproc.sample.join('\n  ')}`);
        if (flag('json'))
            console.log(
                JSON.stringify({ generated: { ...gen, files: gen.files.length, editable: undefined }, cli, inproc, incr }, null, 2),
            );
    } finally {
        if (flag('keep')) console.log(`\nmodels kept in ${root}`);
        else rmSync(work, { recursive: true, force: true });
    }
}

const phase = option('phase', undefined);
try {
    if (phase === 'check') await phaseCheck(process.argv[process.argv.indexOf('--phase') + 2]);
    else if (phase === 'incremental') {
        const [root, file, changes] = process.argv.slice(process.argv.indexOf('--phase') + 2);
        await phaseIncremental(root, file, Number(changes));
    } else await driver();
    process.exit(0);
} catch (e) {
    console.error(`bench: ${e instanceof Error ? e.message : String(e)}`);
    process.exit(1);
}
