import { readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, test } from 'vitest';
import { Codes } from '@maa/language-adl';
import { familyDiagnostics, renderDiagnosticsMarkdown } from '../src/index.js';

const doc = resolve(dirname(fileURLToPath(import.meta.url)), '../../../docs/diagnostics.md');

test('docs/diagnostics.md is generated from the current catalogs (run `npm run docs -w @maa/language-server`)', () => {
    expect(readFileSync(doc, 'utf8')).toBe(renderDiagnosticsMarkdown());
});

test('every host code is documented', () => {
    const documented = new Set(familyDiagnostics().flatMap((c) => c.entries.map((e) => e.code)));
    const undocumented = Object.values(Codes).filter((c) => !documented.has(c) && c !== Codes.InternalError && c !== Codes.LinkUnresolved);
    expect(undocumented).toEqual([]);
});
