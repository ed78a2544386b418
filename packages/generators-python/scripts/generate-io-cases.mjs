#!/usr/bin/env node
// Generates the python-timesync build of every component of the montiarc-io conformance suite
// (../shared/conformance/montiarc-io, or the folder given as first argument) into
// <out>/<component>/timesync (default out: .cache/montiarc-io next to this package's test folder)
// and writes <out>/generation.json: per component whether generation succeeded, and its messages.
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
const components = [...new Set(cases.map((c) => c.component))].sort();
rmSync(out, { recursive: true, force: true });
mkdirSync(out, { recursive: true });
const root = path.join(out, 'models');
cpSync(path.join(suite, 'models'), root, { recursive: true });
const appFile = path.join(root, 'IoCase.arcapp');
const report = {};
for (const component of components) {
  writeFileSync(appFile, [
    `application IoCase for ${component} {`,
    '  platform timesync {',
    '    timesync.Components;',
    '    timesync.AutomataBehavior;',
    '    timesync.RobotArmBehavior;',
    '    timesync.DataTypes;',
    '  }',
    '}',
    ''
  ].join('\n'));
  const dir = path.join(out, 'builds', component);
  try {
    const result = await generate({ services: createMaaServices(NodeFileSystem), appFile, modelRoot: root, outDir: dir, discoveryRoots: [pkg] });
    const errors = result.diagnostics.filter((d) => d.severity === 'error' || d.severity === 1).map((d) => `${d.file ?? ''}:${d.range?.start?.line ?? ''} ${d.code ?? ''} ${d.message}`);
    report[component] = { ok: result.ok, dir: path.join(dir, 'timesync'), errors };
  } catch (e) {
    report[component] = { ok: false, dir: path.join(dir, 'timesync'), errors: [String(e?.stack ?? e)] };
  }
}
rmSync(appFile);
writeFileSync(path.join(out, 'generation.json'), `${JSON.stringify(report, null, 2)}\n`);
const failed = Object.entries(report).filter(([, r]) => !r.ok);
console.log(`generate-io-cases: ${components.length - failed.length}/${components.length} components generated into ${out}`);
for (const [c, r] of failed) console.log(`  ${c}: ${r.errors.join('; ').slice(0, 300)}`);
