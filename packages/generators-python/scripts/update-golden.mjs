#!/usr/bin/env node
// Regenerates the golden files of the generator tests (test/golden/<case>/) from the current
// generators: `npm run golden:update -w @maa/generators-python`, then review the diff.
import { cpSync, mkdirSync, rmSync } from 'node:fs';
import path from 'node:path';
import { freshBase, generateCase, goldenCases, goldenDir, listFiles } from './golden-lib.mjs';

const base = freshBase();

for (const c of goldenCases()) {
    const { result, dir } = await generateCase(c, base);
    if (!result.ok) {
        console.error(`update-golden: ${c.name} does not generate:`);
        for (const d of result.diagnostics) console.error(`  ${d.file}:${d.line}: ${d.code} ${d.message}`);
        process.exit(1);
    }
    const target = path.join(goldenDir, c.name);
    rmSync(target, { recursive: true, force: true });
    for (const file of listFiles(dir)) {
        mkdirSync(path.dirname(path.join(target, file)), { recursive: true });
        cpSync(path.join(dir, file), path.join(target, file));
    }
    console.log(`update-golden: ${c.name}: ${listFiles(dir).length} files`);
}
rmSync(base, { recursive: true, force: true });
