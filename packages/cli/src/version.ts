import { readFileSync } from 'node:fs';

/** The version of @maa/cli, read from its package.json (dist/ and src/ sit next to it). */
export function cliVersion(): string {
    const pkg = JSON.parse(readFileSync(new URL('../package.json', import.meta.url), 'utf8')) as { version?: string };
    return pkg.version ?? '0.0.0';
}
