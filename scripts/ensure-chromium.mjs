#!/usr/bin/env node
// Makes sure Debian's chromium is installed at /usr/bin/chromium for the e2e tests and the IDE
// benchmark (playwright-core drives it; no browser download). Installs it with apt-get when
// missing (needs root); prints the path. Usage: node scripts/ensure-chromium.mjs
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { aptInstall } from './apt-install.mjs';

export const CHROMIUM = process.env.MAA_CHROMIUM ?? '/usr/bin/chromium';

export function ensureChromium({ quiet = false } = {}) {
    if (existsSync(CHROMIUM)) return CHROMIUM;
    aptInstall('chromium', {
        tool: 'ensure-chromium',
        missing: `${CHROMIUM} is missing`,
        hint: "Install Debian's chromium yourself: sudo apt-get install -y chromium (or set MAA_CHROMIUM to a chromium binary).",
        quiet,
    });
    if (!existsSync(CHROMIUM)) throw new Error(`ensure-chromium: apt-get installed chromium, but ${CHROMIUM} is still missing`);
    return CHROMIUM;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
    try {
        console.log(ensureChromium());
    } catch (error) {
        console.error(error.message);
        process.exit(1);
    }
}
