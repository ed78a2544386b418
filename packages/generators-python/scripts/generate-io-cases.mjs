#!/usr/bin/env node
// Generates the python-timesync builds of montiarc-io conformance suites
// (../shared/conformance/montiarc-io, or the folders given, e.g. montiarc-io-extended): per suite
// one build per component under test and feature configuration (a case's `features`), into
// <out>/builds/<variant>/timesync (default out: .cache/montiarc-io next to this package's test
// folder), and writes <out>/generation.json: `builds` (per variant whether generation succeeded,
// its folder and messages) and `cases` (case id -> variant).
// Usage: node scripts/generate-io-cases.mjs [SUITE_DIR [OUT_DIR]] [SUITE_DIR OUT_DIR ...]
// Several suites in one run share the loading of the language services (a second or more of CPU
// per process); each suite gets services of its own, and its builds share them: only the
// application file changes from build to build, and generate() reloads the model root each time.
import { cpSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const pkg = path.resolve(here, '..');
const args = process.argv.slice(2);
const jobs = [];
if (args.length <= 2) {
    jobs.push({
        suite: path.resolve(args[0] ?? path.join(pkg, '..', '..', '..', 'shared', 'conformance', 'montiarc-io')),
        out: path.resolve(args[1] ?? path.join(pkg, '.cache', 'montiarc-io')),
    });
} else if (args.length % 2 === 0) {
    for (let i = 0; i < args.length; i += 2) jobs.push({ suite: path.resolve(args[i]), out: path.resolve(args[i + 1]) });
} else {
    console.error('usage: generate-io-cases.mjs [SUITE_DIR [OUT_DIR]] [SUITE_DIR OUT_DIR ...]');
    process.exit(2);
}
for (const { suite } of jobs) {
    if (!existsSync(path.join(suite, 'io_cases.json'))) {
        console.error(`generate-io-cases: no suite at ${suite}`);
        process.exit(2);
    }
}
const { createMaaServices } = await import('@maa/language-server');
const { discoverGenerators, generate, installationRoot } = await import('@maa/generator-core/node');
const { checkRoots } = await import('@maa/language-adl');
const { URI } = await import('langium');
const { NodeFileSystem } = await import('langium/node');

/** The feature configuration of a case, sorted by name (`{}`: no variability). */
function featuresOf(c) {
    const f = c.features ?? {};
    return Object.fromEntries(
        Object.keys(f)
            .sort()
            .map((k) => [k, f[k]]),
    );
}
/** A build folder name: the component, then the selected/deselected features. */
function variantOf(c) {
    const f = Object.entries(featuresOf(c));
    return f.length === 0 ? c.component : `${c.component}@${f.map(([k, v]) => `${v ? '' : '!'}${k}`).join(',')}`;
}
/**
 * The feature binding of the component under test in the application configuration: MontiArc
 * binds features like configuration arguments, by name on the instantiation (`C(delayed = true)`).
 */
function bindingOf(features) {
    const f = Object.entries(features);
    return f.length === 0 ? '' : `(${f.map(([k, v]) => `${k} = ${v ? 'true' : 'false'}`).join(', ')})`;
}

/** The application configuration of one build. */
function appText(header) {
    return [
        header,
        '  platform timesync {',
        '    timesync.Components;',
        '    timesync.AutomataBehavior;',
        '    timesync.RobotArmBehavior;',
        '    timesync.DataTypes;',
        '  }',
        '}',
        '',
    ].join('\n');
}

/** Removes the documents of a model root from the services, so the next root is checked alone. */
async function forget(services, root) {
    const uris = services.shared.workspace.LangiumDocuments.all
        .filter((d) => d.uri.fsPath.startsWith(root + path.sep))
        .map((d) => d.uri)
        .toArray();
    await services.shared.workspace.DocumentBuilder.update([], uris);
}

/** One build: generate() of the application `header` in `modelRoot` into `dir`; what the report keeps of it. */
async function generateBuild(services, registry, modelRoot, header, dir) {
    const appFile = path.join(modelRoot, 'IoCase.arcapp');
    writeFileSync(appFile, appText(header));
    try {
        const result = await generate({ services, registry, appFile, modelRoot, outDir: dir, discoveryRoots: [pkg] });
        const errors = result.diagnostics
            .filter((d) => d.severity === 'error' || d.severity === 1)
            .map((d) => `${d.file ?? ''}:${d.range?.start?.line ?? ''} ${d.code ?? ''} ${d.message}`);
        return { ok: result.ok, dir: path.join(dir, 'timesync'), errors };
    } catch (e) {
        // Name the application header: with features, the binding is where a generator may differ.
        return {
            ok: false,
            dir: path.join(dir, 'timesync'),
            errors: [`${String(e?.message ?? e)} (application: ${header})`, String(e?.stack ?? e)],
        };
    } finally {
        rmSync(appFile);
        await forget(services, modelRoot);
    }
}

/**
 * Generates every build of one suite into `out`. A build is generated in a model root of its own
 * that holds the model files of its cases (`model_files`): checking the suite's whole model root
 * for each build cost most of the time (parsing, linking and validating every file again). So
 * that nothing is lost by that, the whole root is checked once first: only when it has no error
 * are the builds generated in their own roots (generation reads only the files of the
 * architecture, and these resolve as in the whole root), and a build that does not generate there
 * (a case that does not list every file it needs) is generated in the whole root, as before.
 */
async function generateSuite(suite, out) {
    const cases = JSON.parse(readFileSync(path.join(suite, 'io_cases.json'), 'utf8')).cases;
    const variants = new Map();
    const caseVariant = {};
    for (const c of cases) {
        const v = variantOf(c);
        caseVariant[c.id] = v;
        if (!variants.has(v)) variants.set(v, { component: c.component, features: featuresOf(c), files: new Set() });
        for (const f of c.model_files ?? []) variants.get(v).files.add(f);
    }
    rmSync(out, { recursive: true, force: true });
    mkdirSync(out, { recursive: true });
    const root = path.join(out, 'models');
    cpSync(path.join(suite, 'models'), root, { recursive: true });
    const services = createMaaServices(NodeFileSystem);
    // The generators installed for the model root, found once for the suite, as generate() would
    // find them for each build (above the model root and in this package; nothing installs any meanwhile).
    const registry = discoverGenerators(services.shared.workspace.FileSystemProvider, URI.file(root), {
        extraRoots: [installationRoot(), URI.file(pkg)].filter((r) => r !== undefined),
    });
    const rootClean = !(await checkRoots(services, [{ root }])).some((d) => d.severity === 'error');
    await forget(services, root);
    const report = {};
    for (const [variant, { component, features, files }] of [...variants].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))) {
        const header = `application IoCase for ${component}${bindingOf(features)} {`;
        const dir = path.join(out, 'builds', variant);
        if (rootClean && files.size > 0) {
            const own = path.join(out, 'roots', variant);
            for (const f of files) {
                mkdirSync(path.dirname(path.join(own, f)), { recursive: true });
                cpSync(path.join(root, f), path.join(own, f));
            }
            report[variant] = { ...(await generateBuild(services, registry, own, header, dir)), modelRoot: 'own' };
            if (report[variant].ok) continue;
        }
        report[variant] = { ...(await generateBuild(services, registry, root, header, dir)), modelRoot: 'suite' };
    }
    writeFileSync(path.join(out, 'generation.json'), `${JSON.stringify({ builds: report, cases: caseVariant }, null, 2)}\n`);
    const failed = Object.entries(report).filter(([, r]) => !r.ok);
    const own = Object.values(report).filter((r) => r.modelRoot === 'own').length;
    console.log(
        `generate-io-cases: ${variants.size - failed.length}/${variants.size} builds (component and feature configuration) generated into ${out} (${own} in a model root of their own; the suite's root ${rootClean ? 'has no errors' : 'has errors: every build generated in it'})`,
    );
    for (const [c, r] of failed) console.log(`  ${c}: ${r.errors.join('; ').slice(0, 300)}`);
}

for (const { suite, out } of jobs) await generateSuite(suite, out);
