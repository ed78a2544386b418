#!/usr/bin/env node
// Generates the python-timesync builds of a montiarc-io conformance suite
// (../shared/conformance/montiarc-io, or the folder given as first argument, e.g. montiarc-io-extended):
// one build per component under test and feature configuration (a case's `features`), into
// <out>/builds/<variant>/timesync (default out: .cache/montiarc-io next to this package's test
// folder), and writes <out>/generation.json: `builds` (per variant whether generation succeeded,
// its folder and messages) and `cases` (case id -> variant).
// Usage: node scripts/generate-io-cases.mjs [SUITE_DIR] [OUT_DIR]
import { cpSync, existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const pkg = path.resolve(here, '..');
const suite = path.resolve(process.argv[2] ?? path.join(pkg, '..', '..', '..', 'shared', 'conformance', 'montiarc-io'));
const out = path.resolve(process.argv[3] ?? path.join(pkg, '.cache', 'montiarc-io'));
if (!existsSync(path.join(suite, 'io_cases.json'))) {
    console.error(`generate-io-cases: no suite at ${suite}`);
    process.exit(2);
}
const { createMaaServices } = await import('@maa/language-server');
const { generate } = await import('@maa/generator-core/node');
const { NodeFileSystem } = await import('langium/node');

const cases = JSON.parse(readFileSync(path.join(suite, 'io_cases.json'), 'utf8')).cases;

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
const variants = new Map();
const caseVariant = {};
for (const c of cases) {
    const v = variantOf(c);
    caseVariant[c.id] = v;
    if (!variants.has(v)) variants.set(v, { component: c.component, features: featuresOf(c) });
}
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
const root = path.join(out, 'models');
cpSync(path.join(suite, 'models'), root, { recursive: true });
const appFile = path.join(root, 'IoCase.arcapp');
const report = {};
for (const [variant, { component, features }] of [...variants].sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))) {
    const header = `application IoCase for ${component}${bindingOf(features)} {`;
    writeFileSync(
        appFile,
        [
            header,
            '  platform timesync {',
            '    timesync.Components;',
            '    timesync.AutomataBehavior;',
            '    timesync.RobotArmBehavior;',
            '    timesync.DataTypes;',
            '  }',
            '}',
            '',
        ].join('\n'),
    );
    const dir = path.join(out, 'builds', variant);
    try {
        const result = await generate({
            services: createMaaServices(NodeFileSystem),
            appFile,
            modelRoot: root,
            outDir: dir,
            discoveryRoots: [pkg],
        });
        const errors = result.diagnostics
            .filter((d) => d.severity === 'error' || d.severity === 1)
            .map((d) => `${d.file ?? ''}:${d.range?.start?.line ?? ''} ${d.code ?? ''} ${d.message}`);
        report[variant] = { ok: result.ok, dir: path.join(dir, 'timesync'), errors };
    } catch (e) {
        // Name the application header: with features, the binding is where a generator may differ.
        report[variant] = {
            ok: false,
            dir: path.join(dir, 'timesync'),
            errors: [`${String(e?.message ?? e)} (application: ${header})`, String(e?.stack ?? e)],
        };
    }
}
rmSync(appFile);
writeFileSync(path.join(out, 'generation.json'), `${JSON.stringify({ builds: report, cases: caseVariant }, null, 2)}\n`);
const failed = Object.entries(report).filter(([, r]) => !r.ok);
console.log(
    `generate-io-cases: ${variants.size - failed.length}/${variants.size} builds (component and feature configuration) generated into ${out}`,
);
for (const [c, r] of failed) console.log(`  ${c}: ${r.errors.join('; ').slice(0, 300)}`);
