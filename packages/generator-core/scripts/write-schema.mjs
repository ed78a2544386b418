#!/usr/bin/env node
// Writes dist/generator-manifest.schema.json (published with the package, for editors) from the
// schema the registry validates with (run by `npm run build`, after tsc).
import { writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { GENERATOR_MANIFEST_SCHEMA } from '../dist/manifest/schema.js';

const target = join(dirname(fileURLToPath(import.meta.url)), '..', 'dist', 'generator-manifest.schema.json');
writeFileSync(target, `${JSON.stringify(GENERATOR_MANIFEST_SCHEMA, null, 2)}\n`);
