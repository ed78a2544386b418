#!/usr/bin/env node
// Benchmark of model checking (`npm run bench` at the repository root; not a test: it asserts
// nothing about times). Generates synthetic model roots (generate-models.mjs; 250, 1,000 and
// 4,000 components) in a temporary folder and prints ONE table with every figure of issue 18's
// goals 1 and 2 and the goal beside it (met / not met):
//   - parse only: the family's parser over the 1,000-component model's files, MB/s (1 MB = 10^6 bytes);
//   - cold `maa-gen check` through the CLI (median of --cli-runs) and its peak RSS;
//   - in-process checkModelRoots (1st and 2nd call) against the parse-only time, and the import
//     of the checking path the CLI loads (the one-module bundle, dist/check-bundle.js, when the
//     build wrote it; the unbundled @maa/language-server beside it);
//   - linear scaling: the in-process check at each size, time per component;
//   - the language services' initial build and the re-validation after a one-line change.
// Every measurement runs in a fresh Node process of its own, so memory figures do not mix; the
// runs of the CLI and the imports are interleaved, and the table gives medians.
//
// Options: --components N (1000)  --sizes 250,1000,4000  --cli-runs N (3)  --changes N (5)
//          --import-runs N (3)  --keep (keep the models)  --json (the raw figures after the table)
//          --profile (also: where the time of parse-only and of an in-process check goes, from a CPU
//          profile of each, by stage: garbage collection, parsing, linking, validation ...)
import { execFile } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { performance } from 'node:perf_hooks';
import { EDITABLE_LINE, generateModels } from './generate-models.mjs';
import { profileStages } from './profile-summary.mjs';
import { printTable } from './table.mjs';

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

const CHECK_LOADER = new URL('../dist/check-loader.js', import.meta.url);
const BUNDLE = new URL('../dist/check-bundle.js', import.meta.url);

/** The checking path as `maa-gen check` loads it (the bundle when it is current), timed. */
async function phaseCheck(root) {
    const { loadChecker, bundleIsCurrent } = await import(CHECK_LOADER.href);
    const via = bundleIsCurrent() ? 'bundle' : 'package';
    const t0 = performance.now();
    const { checkModelRoots } = await loadChecker();
    const importMs = performance.now() - t0;
    const t1 = performance.now();
    const diagnostics = await checkModelRoots([{ root }]);
    const firstMs = performance.now() - t1;
    const rssAfterFirst = maxRssKb();
    const t2 = performance.now();
    await checkModelRoots([{ root }]);
    const secondMs = performance.now() - t2;
    emit({
        via,
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

/** A cold import of the checking path: `bundle` (dist/check-bundle.js) or `package` (@maa/language-server). */
async function phaseImport(which) {
    const t0 = performance.now();
    if (which === 'bundle') await import(BUNDLE.href);
    else await import('@maa/language-server');
    emit({ which, ms: performance.now() - t0 });
}

/**
 * Parse only, as helper PARSE of issue 18 measures it: the family's parser (the LangiumParser of
 * each file's language, `services.parser.LangiumParser.parse(text)`: lexing, parsing and the CST,
 * exactly what creating a document does) over every model file, texts read beforehand; the
 * parsers' construction timed apart, one warm-up pass, then `passes` passes.
 */
async function phaseParse(root, passes) {
    const { createMaaServices } = await import('@maa/language-server');
    const { URI } = await import('langium');
    const { NodeFileSystem } = await import('langium/node');
    const { shared } = createMaaServices(NodeFileSystem);
    const extensions = shared.ServiceRegistry.all.flatMap((l) => l.LanguageMetaData.fileExtensions);
    const t0 = performance.now();
    const files = listFiles(root, extensions).map((file) => ({
        parser: shared.ServiceRegistry.getServices(URI.file(file)).parser.LangiumParser,
        text: readFileSync(file, 'utf8'),
    }));
    const constructionMs = performance.now() - t0;
    const bytes = files.reduce((n, f) => n + Buffer.byteLength(f.text), 0);
    const pass = () => {
        let errors = 0;
        const t = performance.now();
        for (const { parser, text } of files) {
            const r = parser.parse(text);
            errors += r.lexerErrors.length + r.parserErrors.length;
        }
        return { ms: performance.now() - t, errors };
    };
    const warmUp = pass();
    const passMs = [];
    for (let i = 0; i < passes; i++) passMs.push(pass().ms);
    emit({ files: files.length, bytes, constructionMs, warmUpMs: warmUp.ms, passMs, errors: warmUp.errors });
}

/** The model files below a folder (sorted). */
function listFiles(dir, extensions) {
    return readdirSync(dir, { withFileTypes: true })
        .sort((a, b) => a.name.localeCompare(b.name))
        .flatMap((e) => {
            const p = path.join(dir, e.name);
            if (e.isDirectory()) return listFiles(p, extensions);
            return extensions.some((x) => e.name.endsWith(x)) ? [p] : [];
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

const s = (ms) => `${(ms / 1000).toFixed(2)} s`;
const msf = (ms) => `${ms.toFixed(0)} ms`;
const mb = (kb) => `${(kb / 1024).toFixed(0)} MB`;
const verdict = (ok) => (ok ? 'met' : 'not met');

/** Runs the phases of one benchmark: the CLI and imports interleaved, then parse, check per size, incremental. */
async function measure(work, roots, primary, counts) {
    const probe = path.join(work, 'rss-probe.mjs');
    writeFileSync(
        probe,
        `import { writeSync } from 'node:fs';\nprocess.on('exit', () => writeSync(2, '\\n${RSS_PREFIX}' + process.resourceUsage().maxRSS + '\\n'));\n`,
    );
    const root = roots.get(primary).root;
    const cli = [];
    const imports = { bundle: [], package: [] };
    const hasBundle = existsSync(fileURLToPath(BUNDLE));
    for (let i = 0; i < Math.max(counts.cliRuns, counts.importRuns); i++) {
        if (i < counts.cliRuns) {
            process.stderr.write(`cli run ${i + 1}/${counts.cliRuns}...\n`);
            const r = await run(['--import', pathToFileURL(probe).href, CLI, 'check', '--format', 'json', root], { cwd: work });
            if (r.code !== 0 && r.code !== 1) throw new Error(`maa-gen check failed (exit ${r.code}):\n${r.stderr.trim()}`);
            const rss = /MAA_BENCH_MAXRSS_KB=(\d+)/.exec(r.stderr);
            cli.push({ ms: r.ms, code: r.code, maxRssKb: rss ? Number(rss[1]) : NaN, summary: JSON.parse(r.stdout).summary });
        }
        if (i < counts.importRuns) {
            for (const which of hasBundle ? ['bundle', 'package'] : ['package']) {
                imports[which].push(phaseResult(`import ${which}`, await run([SELF, '--phase', 'import', which], { cwd: work })).ms);
            }
        }
    }
    process.stderr.write('parse only...\n');
    const parse = phaseResult('parse', await run([SELF, '--phase', 'parse', root, '3'], { cwd: work }));
    const checks = new Map();
    for (const [n, r] of roots) {
        process.stderr.write(`in-process check, ${n} components...\n`);
        checks.set(n, phaseResult('check', await run([SELF, '--phase', 'check', r.root], { cwd: work })));
    }
    process.stderr.write('language services, one-line changes...\n');
    const gen = roots.get(primary).gen;
    const editable = gen.editable[Math.floor(gen.editable.length / 2)];
    const incr = phaseResult(
        'incremental',
        await run([SELF, '--phase', 'incremental', root, editable, String(counts.changes)], { cwd: work }),
    );
    return { cli, imports, parse, checks, incr };
}

/** The table rows [measure, value, goal, verdict] of issue 18's goals 1 and 2. */
function tableRows(m, primary) {
    const { cli, imports, parse, checks, incr } = m;
    const inproc = checks.get(primary);
    const parseMedian = median(parse.passMs);
    const mbps = parse.bytes / 1e6 / (parseMedian / 1000);
    const cliMedian = median(cli.map((c) => c.ms));
    const ratio = inproc.firstMs / parseMedian;
    const usedImport = inproc.via === 'bundle' ? median(imports.bundle) : median(imports.package);
    const rows = [
        [
            `parse only (${parse.files} files, ${(parse.bytes / 1e3).toFixed(0)} kB; median of ${parse.passMs.length} passes after a warm-up)`,
            `${mbps.toFixed(2)} MB/s = ${msf(parseMedian)}  (passes: ${parse.passMs.map(msf).join(', ')}; warm-up ${msf(parse.warmUpMs)}; parser construction ${msf(parse.constructionMs)}${parse.errors ? `; ${parse.errors} syntax errors!` : ''})`,
            '≥ 1 MB/s',
            verdict(mbps >= 1),
        ],
        [
            `cold check, CLI (maa-gen check, median of ${cli.length})`,
            `${s(cliMedian)}  (runs: ${cli.map((c) => s(c.ms)).join(', ')})`,
            '≤ 2 s',
            verdict(cliMedian <= 2000),
        ],
        ['peak RSS, CLI process', mb(Math.max(...cli.map((c) => c.maxRssKb))), 'reported', '—'],
        [
            `import of the checking path the CLI loads (${inproc.via === 'bundle' ? 'dist/check-bundle.js' : '@maa/language-server'}, median)`,
            `${msf(usedImport)}  (runs: ${(inproc.via === 'bundle' ? imports.bundle : imports.package).map(msf).join(', ')})`,
            '≤ 300 ms',
            verdict(usedImport <= 300),
        ],
        [
            'import of @maa/language-server unbundled (median)',
            `${msf(median(imports.package))}  (runs: ${imports.package.map(msf).join(', ')})`,
            'for comparison',
            '—',
        ],
        [
            'cold check, in-process (checkModelRoots, 1st call)',
            `${s(inproc.firstMs)} = ${ratio.toFixed(1)}× the parse-only time (${msf(parseMedian)})`,
            '≤ 2× parse only',
            verdict(ratio <= 2),
        ],
        ['repeated check, in-process (2nd call)', s(inproc.secondMs), '—', '—'],
        ['peak RSS, in-process after 1st check', mb(inproc.maxRssKb), 'reported', '—'],
    ];
    const base = inproc.firstMs / primary;
    for (const [n, c] of checks) {
        const per = c.firstMs / n;
        const dev = (per / base - 1) * 100;
        rows.push([
            `scaling: in-process check, ${n} components (peak RSS ${mb(c.maxRssKb)})`,
            `${s(c.firstMs)} = ${(per).toFixed(2)} ms per component (${dev >= 0 ? '+' : ''}${dev.toFixed(0)} % vs ${primary})`,
            `±20 % of ${primary}`,
            verdict(Math.abs(dev) <= 20),
        ]);
    }
    rows.push(
        ['language services: load + full build with validation', `${s(incr.initialMs)}  (${incr.documents} documents)`, '—', '—'],
        ['peak RSS, language services after build', mb(incr.maxRssKbAfterBuild), 'reported', '—'],
        [
            `re-validate after a one-line change (median of ${incr.changeMs.length})`,
            `${msf(median(incr.changeMs))}  (${incr.changeMs.map(msf).join(', ')}; via ${incr.via})`,
            '—',
            '—',
        ],
    );
    return rows;
}

/** With --profile: one more parse-only and in-process check run each under `--cpu-prof`, by stage. */
async function printProfiles(work, root) {
    for (const [title, args] of [
        ['parse only (a warm-up and 3 passes)', ['--phase', 'parse', root, '3']],
        ['cold check, in-process (import, 1st and 2nd call)', ['--phase', 'check', root]],
    ]) {
        const dir = mkdtempSync(path.join(work, 'profile-'));
        process.stderr.write(`profiling ${title}...\n`);
        phaseResult(title, await run(['--cpu-prof', '--cpu-prof-dir', dir, SELF, ...args], { cwd: work }));
        const [file] = readdirSync(dir).filter((f) => f.endsWith('.cpuprofile'));
        if (!file) throw new Error(`no CPU profile was written for ${title}`);
        console.log(`\nWhere the time goes: ${title} (CPU profile, ${path.join(dir, file)})`);
        console.log('| stage | ms | share |\n|---|---|---|');
        for (const [stage, ms, share] of profileStages(path.join(dir, file))) {
            console.log(`| ${stage} | ${ms.toFixed(0)} | ${(share * 100).toFixed(1)} % |`);
        }
    }
}

async function driver() {
    const primary = Number(option('components', '1000'));
    const sizes = [...new Set([primary, ...option('sizes', '250,1000,4000').split(',').map(Number)])].sort((a, b) => a - b);
    const counts = {
        cliRuns: Number(option('cli-runs', '3')),
        importRuns: Number(option('import-runs', '3')),
        changes: Number(option('changes', '5')),
    };
    const work = mkdtempSync(path.join(tmpdir(), 'maa-bench-'));
    try {
        const roots = new Map();
        for (const n of sizes) {
            const root = path.join(work, `models-${n}`);
            roots.set(n, { root, gen: generateModels(root, n) });
        }
        const gen = roots.get(primary).gen;
        console.log(
            `maa-gen check benchmark: ${gen.atomic + gen.composed} components (${gen.atomic} atomic, ${gen.composed} composed, 10 ports each) + 1 class diagram,`,
        );
        console.log(`${gen.files.length} files, ${gen.lines} lines; scaling at ${sizes.join(', ')} components; in ${work}`);
        console.log(`Node ${process.version}, ${process.platform}/${process.arch}\n`);
        const m = await measure(work, roots, primary, counts);
        printTable(tableRows(m, primary));
        const summary = m.cli[0].summary;
        const inproc = m.checks.get(primary);
        console.log(
            `\nDiagnostics of the generated models: CLI ${summary.errors} errors, ${summary.warnings} warnings in ${summary.files} files; ` +
                `language services ${m.incr.totals.errors} errors, ${m.incr.totals.warnings} warnings.`,
        );
        console.log(
            `Changed file: ${m.incr.changedFile}; its errors after each change: ${m.incr.errorsAfterEachChange.join(', ')} (odd changes break the line, even ones repair it).`,
        );
        if (inproc.sample.length > 0) console.log(`First diagnostics:\n  ${inproc.sample.join('\n  ')}`);
        if (flag('profile')) await printProfiles(work, roots.get(primary).root);
        if (flag('json')) {
            const raw = { ...m, checks: Object.fromEntries(m.checks), generated: { ...gen, files: gen.files.length, editable: undefined } };
            console.log(JSON.stringify(raw, null, 2));
        }
    } finally {
        if (flag('keep')) console.log(`\nmodels kept in ${work}`);
        else rmSync(work, { recursive: true, force: true });
    }
}

const phase = option('phase', undefined);
try {
    const args = process.argv.slice(process.argv.indexOf('--phase') + 2);
    if (phase === 'check') await phaseCheck(args[0]);
    else if (phase === 'import') await phaseImport(args[0]);
    else if (phase === 'parse') await phaseParse(args[0], Number(args[1]));
    else if (phase === 'incremental') {
        const [root, file, changes] = process.argv.slice(process.argv.indexOf('--phase') + 2);
        await phaseIncremental(root, file, Number(changes));
    } else await driver();
    process.exit(0);
} catch (e) {
    console.error(`bench: ${e instanceof Error ? e.message : String(e)}`);
    process.exit(1);
}
