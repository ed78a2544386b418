#!/usr/bin/env node
// Benchmark of generation (`npm run bench:generate -w @maa/cli`, or `npm run bench` at the root;
// not a test: it asserts nothing about times). Takes the 1,000-component model of the check
// benchmark (generate-models.mjs), adds a top component `System` that instantiates every
// component type and an application configuration, installs a small template-based generator
// family (component + data type generator, Nunjucks templates with trace marks), and reports:
//   - raw template rendering: the same templates over the same component views, rendered
//     directly with the shared Nunjucks environment (no orchestration);
//   - the orchestrator's phases: manifest discovery, loading + language checks, configuration
//     checks and generator rules, instantiation, generation (rendering through FileBuilders),
//     tracing, and the transactional write; first run (empty output) and second run (unchanged);
//   - the orchestration overhead: everything but loading the models, minus raw rendering;
//   - cold `maa-gen generate` through the CLI against a cold `maa-gen check` of the same model
//     root, interleaved (medians of --cli-runs): issue 18's goal 3, generate ≤ check + 1 s.
// One table, with each goal beside its figure (met / not met). Each CLI run's CPU time (user +
// system, all threads, as the process reports it at exit) is given beside its wall time: on a
// loaded machine wall times vary with the load, CPU times much less.
// Options: --components N (1000)  --cli-runs N (3)  --keep (keep the folder)  --json (raw figures)
//   --cli-only (only the CLI runs)  --baseline PATH (also a cold `generate` of another build's
//   bin/maa-gen.js, interleaved with the others: before/after figures on the same load)
import { execFile } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { performance } from 'node:perf_hooks';
import { generateModels, PACKAGES, writeSystemComponent } from './generate-models.mjs';
import { printTable } from './table.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const CLI = path.resolve(here, '..', 'bin', 'maa-gen.js');

function option(name, fallback) {
    const i = process.argv.indexOf(`--${name}`);
    return i >= 0 && process.argv[i + 1] !== undefined ? process.argv[i + 1] : fallback;
}
const flag = (name) => process.argv.includes(`--${name}`);
const median = (xs) => {
    const sorted = [...xs].sort((a, b) => a - b);
    const mid = Math.floor(sorted.length / 2);
    return sorted.length % 2 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
};
const verdict = (ok) => (ok ? 'met' : 'not met');

const COMPONENT_TEMPLATE = `# Generated from {{ c.qualifiedName }}
{% for p in c.parameters %}
# parameter {{ p.name }}: {{ p.typeName }}
{% endfor %}


class {{ c.name | pascal_case }}:
    """Component {{ c.qualifiedName | py_str }}."""

{% for p in c.ports %}
{% trace p %}
    {{ p.name | snake_case | upper }}_{{ p.direction | upper }} = ({{ p.name | py_str }}, {{ p.qualifiedTypeName | py_str }}, {{ p.timing | py_str }})
{% endtrace %}
{% endfor %}

    def __init__(self):
{% for s in c.subcomponents %}
{% trace s %}
        self.{{ s.name | py_ident }} = {{ s.type | replace(".", "_") }}()
{% endtrace %}
{% endfor %}
{% for k in c.connectors %}
{% trace k %}
        self.connect({{ k.source.subcomponent | default("self") | py_str }}, {{ k.source.port | py_str }}, {{ k.targets | length }})
{% endtrace %}
{% endfor %}
        pass
`;

const TYPES_TEMPLATE = `# Data types
{% for t in types %}
{% trace t %}
class {{ t.name | pascal_case }}:
{% for c in t.constants %}
    {{ c | constant_case }} = {{ c | py_str }}
{% endfor %}
{% for a in t.attributes %}
    {{ a.name | snake_case }}: {{ a.typeName | py_str }}
{% endfor %}
    pass
{% endtrace %}
{% endfor %}
`;

function installGenerators(root) {
    const dir = path.join(root, 'node_modules', 'bench-gens');
    mkdirSync(path.join(dir, 'templates'), { recursive: true });
    writeFileSync(
        path.join(dir, 'package.json'),
        JSON.stringify(
            {
                name: 'bench-gens',
                version: '1.0.0',
                type: 'module',
                maa: {
                    generators: [
                        {
                            name: 'bench.Components',
                            kind: 'component',
                            supports: ['compute'],
                            output: { gpl: 'python', rte: 'bench-rte' },
                            entry: 'components.js',
                            templates: 'templates',
                            checks: ['components.BehaviorOrHandwritten', 'components.NoInheritance'],
                        },
                        {
                            name: 'bench.DataTypes',
                            kind: 'datatype',
                            output: { gpl: 'python' },
                            entry: 'datatypes.js',
                            templates: 'templates',
                            checks: ['datatypes.NoInheritance'],
                        },
                    ],
                },
            },
            null,
            2,
        ),
    );
    writeFileSync(path.join(dir, 'templates', 'component.py.njk'), COMPONENT_TEMPLATE);
    writeFileSync(path.join(dir, 'templates', 'types.py.njk'), TYPES_TEMPLATE);
    writeFileSync(
        path.join(dir, 'components.js'),
        `export default () => ({ kind: 'component', async generate(ctx) {
  for (const c of ctx.architecture.components) {
    const f = ctx.out.file(c.qualifiedName.replace(/\\./g, '/') + '.py');
    f.render('component.py.njk', { c }, c.node);
    await ctx.behavior(c);
  }
} });
`,
    );
    writeFileSync(
        path.join(dir, 'datatypes.js'),
        `export default () => ({ kind: 'datatype', generate(ctx) {
  ctx.out.file('types.py').render('types.py.njk', { types: ctx.dataTypes });
  return {};
} });
`,
    );
    return dir;
}

function writeSystem(root, gen) {
    const count = writeSystemComponent(root, gen);
    writeFileSync(
        path.join(root, 'Bench.arcapp'),
        'application Bench for robot.System {\n  platform python {\n    bench.Components;\n    bench.DataTypes;\n  }\n}\n',
    );
    return count;
}

/** Preloaded into each CLI run: reports the process's CPU time on stderr when it exits. */
const CPU_REPORT = `data:text/javascript,${encodeURIComponent(
    "import { writeSync } from 'node:fs'; process.on('exit', () => { const u = process.cpuUsage(); writeSync(2, '\\nmaa-bench-cpu ' + (u.user + u.system) / 1000 + '\\n'); });",
)}`;
const CPU_LINE = /\nmaa-bench-cpu ([\d.]+)\n$/;

/** Runs node with `args`; `ms` is the wall time, `cpuMs` the CPU time the process reported. */
function run(args, options = {}) {
    return new Promise((resolve, reject) => {
        const started = performance.now();
        execFile(
            process.execPath,
            ['--import', CPU_REPORT, ...args],
            { maxBuffer: 256 * 1024 * 1024, ...options },
            (error, stdout, stderr) => {
                const ms = performance.now() - started;
                const cpu = CPU_LINE.exec(stderr);
                if (error && typeof error.code !== 'number') reject(error);
                else resolve({ code: error ? error.code : 0, stdout, stderr, ms, cpuMs: cpu ? Number(cpu[1]) : Number.NaN });
            },
        );
    });
}

/**
 * Cold CLI runs, interleaved so that all see the same load: `maa-gen generate` of the
 * application, `maa-gen check` of its model root (the same files) and, with --baseline, the other
 * build's `maa-gen generate`. Wall and CPU times of each run.
 */
async function cliRuns(root, work, count, baseline) {
    const runs = { generate: [], check: [], baseline: [] };
    const generate = async (cli, out) => {
        const g = await run([cli, 'generate', path.join(root, 'Bench.arcapp'), '--out', path.join(work, out)], { cwd: work });
        if (g.code !== 0) throw new Error(`maa-gen generate (${cli}) failed (exit ${g.code}):\n${g.stderr}`);
        return { ms: g.ms, cpuMs: g.cpuMs };
    };
    for (let i = 0; i < count; i++) {
        process.stderr.write(`cold maa-gen generate and check (CLI), run ${i + 1}/${count}...\n`);
        runs.generate.push(await generate(CLI, `out-cli-${i}`));
        const c = await run([CLI, 'check', '--format', 'json', root], { cwd: work });
        if (c.code !== 0 && c.code !== 1) throw new Error(`maa-gen check failed (exit ${c.code}):\n${c.stderr}`);
        runs.check.push({ ms: c.ms, cpuMs: c.cpuMs });
        if (baseline) runs.baseline.push(await generate(baseline, `out-baseline-${i}`));
    }
    return runs;
}

/** Medians of wall and CPU time of some runs. */
function medians(runs) {
    return { ms: median(runs.map((r) => r.ms)), cpuMs: median(runs.map((r) => r.cpuMs)) };
}

/** The table rows of the CLI runs: issue 18's goal 3 on wall and on CPU time. */
function cliRows(runs) {
    const s = (x) => `${(x / 1000).toFixed(2)} s`;
    const list = (rs) => rs.map((r) => `${s(r.ms)}/${s(r.cpuMs)}`).join(', ');
    const g = medians(runs.generate);
    const c = medians(runs.check);
    const n = runs.generate.length;
    const rows = [
        [
            `cold maa-gen generate through the CLI, wall (median of ${n})`,
            `${s(g.ms)}  (runs, wall/CPU: ${list(runs.generate)})`,
            `≤ check + 1 s = ${s(c.ms + 1000)}`,
            verdict(g.ms <= c.ms + 1000),
        ],
        [
            `cold maa-gen generate through the CLI, CPU (median of ${n})`,
            `${s(g.cpuMs)}  (generate - check = ${s(g.cpuMs - c.cpuMs)})`,
            `≤ check + 1 s = ${s(c.cpuMs + 1000)}`,
            verdict(g.cpuMs <= c.cpuMs + 1000),
        ],
        [
            `cold maa-gen check of the same model root, wall (median of ${n})`,
            `${s(c.ms)}  (runs, wall/CPU: ${list(runs.check)}; generate - check = ${s(g.ms - c.ms)})`,
            '≤ 2 s',
            verdict(c.ms <= 2000),
        ],
        [`cold maa-gen check of the same model root, CPU (median of ${n})`, s(c.cpuMs), '—', '—'],
    ];
    if (runs.baseline.length > 0) {
        const b = medians(runs.baseline);
        rows.push([
            `baseline: cold maa-gen generate of --baseline, wall / CPU (median of ${n})`,
            `${s(b.ms)} / ${s(b.cpuMs)}  (runs, wall/CPU: ${list(runs.baseline)}; this build - baseline = ${s(g.ms - b.ms)} / ${s(g.cpuMs - b.cpuMs)})`,
            '—',
            '—',
        ]);
    }
    return rows;
}

async function main() {
    const components = Number(option('components', '1000'));
    const work = mkdtempSync(path.join(tmpdir(), 'maa-gen-bench-'));
    const root = path.join(work, 'models');
    try {
        const gen = generateModels(root, components);
        const componentTypes = writeSystem(root, gen);
        installGenerators(root);
        console.log(
            `maa-gen generate benchmark: ${gen.atomic + gen.composed} components of the check benchmark (${PACKAGES} packages) + a System component`,
        );
        console.log(
            `instantiating each (${componentTypes} component types), 1 class diagram; generator family: component + data type generator (Nunjucks)`,
        );
        console.log(`Node ${process.version}, ${process.platform}/${process.arch}\n`);
        const cliCount = Number(option('cli-runs', '3'));
        const baseline = option('baseline', undefined);
        if (flag('cli-only')) {
            const runs = await cliRuns(root, work, cliCount, baseline && path.resolve(baseline));
            printTable(cliRows(runs));
            if (flag('json')) console.log(JSON.stringify(runs, null, 2));
            return;
        }

        const { createMaaServices } = await import('@maa/language-server');
        const core = await import('@maa/generator-core/node');
        const { NodeFileSystem } = await import('langium/node');
        const out = path.join(work, 'out');

        process.stderr.write('orchestrated generation, first run...\n');
        const t0 = performance.now();
        const first = await core.generate({
            services: createMaaServices(NodeFileSystem),
            appFile: path.join(root, 'Bench.arcapp'),
            outDir: out,
        });
        const firstMs = performance.now() - t0;
        if (!first.ok)
            throw new Error(
                `generation failed:\n${first.diagnostics
                    .filter((d) => d.severity === 'error')
                    .slice(0, 10)
                    .map((d) => `${d.file}:${d.line} ${d.code} ${d.message}`)
                    .join('\n')}`,
            );
        process.stderr.write('orchestrated generation, second run (unchanged)...\n');
        const t1 = performance.now();
        const second = await core.generate({
            services: createMaaServices(NodeFileSystem),
            appFile: path.join(root, 'Bench.arcapp'),
            outDir: out,
        });
        const secondMs = performance.now() - t1;

        // Raw rendering: the same templates over the same views, no orchestration, no tracing.
        process.stderr.write('raw template rendering...\n');
        const services = createMaaServices(NodeFileSystem);
        core.configureGeneratorRegistry(services.shared, core.GeneratorRegistry.EMPTY);
        const { checkRoots } = await import('@maa/language-adl');
        await checkRoots(services, [{ root }]);
        const { URI } = await import('langium');
        const app = services.shared.workspace.LangiumDocuments.getDocument(URI.file(path.join(root, 'Bench.arcapp'))).parseResult.value
            .application;
        const tArch = performance.now();
        const architecture = core.applicationArchitecture(app);
        const archMs = performance.now() - tArch;
        const env = core.createTemplateEnvironment([path.join(root, 'node_modules', 'bench-gens', 'templates')]);
        const raw = [];
        for (let i = 0; i < 3; i++) {
            const t = performance.now();
            let bytes = 0;
            for (const c of architecture.components) bytes += env.render('component.py.njk', { c }).length;
            bytes += env.render('types.py.njk', { types: architecture.dataTypes }).length;
            raw.push({ ms: performance.now() - t, bytes });
        }
        const rawMs = Math.min(...raw.map((r) => r.ms));

        const runs = await cliRuns(root, work, cliCount, baseline && path.resolve(baseline));

        const f = first.timings;
        const overhead = f.discover + f.check + f.instantiate + f.generate + f.trace + f.write - raw[0].ms;
        const ms = (x) => `${x.toFixed(0)} ms`;
        const s = (x) => `${(x / 1000).toFixed(2)} s`;
        const files = first.platforms[0].files.length;
        const rows = [
            ...cliRows(runs),
            [
                'raw template rendering, cold (templates compiled on first use)',
                `${ms(raw[0].ms)}  (${files} outputs, ${(raw[0].bytes / 1024).toFixed(0)} KiB)`,
                '—',
                '—',
            ],
            ['raw template rendering, warm (best of 3)', ms(rawMs), '—', '—'],
            ['building the architecture view (once)', ms(archMs), '—', '—'],
            ['orchestrated, 1st run: discover manifests', ms(f.discover), '—', '—'],
            ['orchestrated, 1st run: load + language checks (all files)', s(f.load), '—', '—'],
            ['orchestrated, 1st run: configuration checks + generator rules', ms(f.check), '—', '—'],
            ['orchestrated, 1st run: instantiate generators', ms(f.instantiate), '—', '—'],
            ['orchestrated, 1st run: generate (render via FileBuilders, trace marks)', ms(f.generate), '—', '—'],
            ['orchestrated, 1st run: resolve traces + trace file', ms(f.trace), '—', '—'],
            [
                'orchestrated, 1st run: plan (protected regions) + stage + commit the write',
                `${ms(f.write)}  (${first.platforms[0].written.length} files written)`,
                '—',
                '—',
            ],
            [
                'orchestrated, 1st run: total (in-process)',
                `${s(firstMs)}  (all but load: ${s(firstMs - f.load)})`,
                'all but load ≤ 1 s',
                verdict(firstMs - f.load <= 1000),
            ],
            [
                'orchestration overhead (1st run: all but loading, minus cold raw rendering)',
                `${ms(overhead)}  (${(overhead / raw[0].ms).toFixed(1)} x cold raw rendering; ${((overhead / firstMs) * 100).toFixed(0)} % of the run)`,
                '—',
                '—',
            ],
            [
                'orchestrated, 2nd run (output unchanged): total',
                `${s(secondMs)}  (load ${s(second.timings.load)}, generate ${ms(second.timings.generate)}, trace ${ms(second.timings.trace)}, plan + write ${ms(second.timings.write)}, ${second.platforms[0].written.length} written)`,
                '—',
                '—',
            ],
        ];
        printTable(rows);
        console.log(
            `\n${files} generated files + trace file; ${first.diagnostics.filter((d) => d.severity === 'warning').length} model warnings (unconnected outputs of the System's subcomponents).`,
        );
        if (flag('json'))
            console.log(
                JSON.stringify(
                    {
                        rawMs,
                        raw,
                        archMs,
                        first: { ms: firstMs, timings: first.timings },
                        second: { ms: secondMs, timings: second.timings },
                        cli: runs,
                    },
                    null,
                    2,
                ),
            );
    } finally {
        if (flag('keep')) console.log(`\nkept in ${work}`);
        else rmSync(work, { recursive: true, force: true });
    }
}

try {
    await main();
    process.exit(0);
} catch (e) {
    console.error(`bench: ${e instanceof Error ? e.message : String(e)}`);
    process.exit(1);
}
