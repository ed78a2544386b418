import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { Command, Option } from 'commander';
import { ExitCode } from '../errors.js';
import type { CliIo } from '../io.js';

export interface GeneratorsCommandOptions {
    format: 'text' | 'json';
    from?: string;
}

interface Row {
    name: string;
    kind: string;
    language: string;
    gpl: string;
    rte: string;
    checks: string;
    package: string;
}

/**
 * `maa-gen generators [--from DIR] [--format text|json]`: lists the generators of the installed
 * packages (found from DIR upwards, default the current folder, and next to maa-gen itself).
 * Exit 1 when a package declares an invalid manifest (each problem names package and field).
 */
export async function runGenerators(options: GeneratorsCommandOptions, io: CliIo): Promise<ExitCode> {
    const { discoverGenerators } = await import('@maa/generator-core');
    const { NodeFileSystemProvider } = await import('langium/node');
    const { URI } = await import('langium');
    const from = path.resolve(io.cwd, options.from ?? '.');
    const installation = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
    const registry = discoverGenerators(new NodeFileSystemProvider(), URI.file(from), { extraRoots: [URI.file(installation)] });
    const all = registry.all();
    const rows: Row[] = all.map(({ manifest: m, source }) => ({
        name: m.name,
        kind: m.kind,
        language: m.kind === 'behavior' ? m.language : m.kind === 'component' && m.supports.length > 0 ? `(${m.supports.join(', ')})` : '-',
        gpl: m.output.gpl,
        rte: m.output.rte ?? '-',
        checks: m.checks.length > 0 ? m.checks.join(', ') : '-',
        package: `${source.packageName}@${source.packageVersion}`,
    }));
    if (options.format === 'json') {
        io.out(
            `${JSON.stringify(
                {
                    generators: all.map(({ manifest, source }) => ({
                        ...manifest,
                        package: source.packageName,
                        version: source.packageVersion,
                        packageDir: source.packageDir,
                        manifestFile: source.file,
                    })),
                    problems: registry.problems.map((p) => ({ package: p.packageName, file: p.file, field: p.field, message: p.problem })),
                },
                null,
                2,
            )}\n`,
        );
    } else {
        if (rows.length > 0) {
            const header: Row = {
                name: 'NAME',
                kind: 'KIND',
                language: 'LANGUAGE',
                gpl: 'GPL',
                rte: 'RTE',
                checks: 'CHECKS',
                package: 'PACKAGE',
            };
            const keys = Object.keys(header) as Array<keyof Row>;
            const widths = keys.map((k) => Math.max(...[header, ...rows].map((r) => r[k].length)));
            for (const r of [header, ...rows]) {
                io.out(`${keys.map((k, i) => (i === keys.length - 1 ? r[k] : r[k].padEnd(widths[i]!))).join('  ')}\n`);
            }
        }
        for (const p of registry.problems) io.err(`error: ${p.message}\n`);
        const packages = new Set(all.map((g) => g.source.packageName)).size;
        io.err(
            `${rows.length} generator${rows.length === 1 ? '' : 's'} from ${packages} package${packages === 1 ? '' : 's'}` +
                (registry.problems.length > 0
                    ? `, ${registry.problems.length} invalid manifest declaration${registry.problems.length === 1 ? '' : 's'}`
                    : '') +
                '\n',
        );
    }
    return registry.problems.length > 0 ? ExitCode.errors : ExitCode.ok;
}

export function generatorsCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('generators')
        .description('list the generators of the installed packages (name, kind, language, GPL, RTE, checks)')
        .option('--from <dir>', 'look for installed packages from this folder upwards (default: the current folder)')
        .addOption(new Option('-f, --format <format>', 'output format').choices(['text', 'json']).default('text'))
        .addHelpText(
            'after',
            `
A package provides generators by listing manifests in its package.json:
  "maa": { "generators": [ { "name": "ros2.Components", "kind": "component", ... } ] }
(see docs/generating.md). Packages are found in every node_modules folder from --from upwards
and next to maa-gen itself.

Exit codes:
  0  every manifest is valid
  1  at least one invalid manifest (each problem names the package and the field)
  3  internal error`,
        )
        .action(async (options: GeneratorsCommandOptions) => {
            setExitCode(await runGenerators(options, io));
        });
}
