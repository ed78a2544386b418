// Writes the artifacts emitted from the contracts (emit-lib.mjs) where they differ.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { artifacts, repoDir } from './emit-lib.mjs';

for (const [rel, content] of artifacts()) {
    const abs = path.join(repoDir, rel);
    let old;
    try {
        old = readFileSync(abs, 'utf8');
    } catch {
        old = undefined;
    }
    if (old === content) continue;
    mkdirSync(path.dirname(abs), { recursive: true });
    writeFileSync(abs, content);
    console.log(`protocol: wrote ${rel}`);
}
