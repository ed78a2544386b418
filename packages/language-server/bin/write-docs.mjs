#!/usr/bin/env node
// Writes docs/diagnostics.md from the languages' diagnostic catalogs (run after `npm run build`).
import { writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { renderDiagnosticsMarkdown } from '../dist/index.js';

const target = resolve(dirname(fileURLToPath(import.meta.url)), '../../../docs/diagnostics.md');
writeFileSync(target, renderDiagnosticsMarkdown());
console.log(`wrote ${target}`);
