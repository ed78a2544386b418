import { constants, copyFileSync, existsSync, lstatSync, mkdirSync, readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { Command } from 'commander';
import { CliError, ExitCode } from '../errors.js';
import { displayPath } from '../format/text.js';
import type { CliIo } from '../io.js';

export interface NewCommandOptions {
    list?: boolean;
}

/** One project template, as the build step lists it in dist/templates/templates.json. */
export interface ProjectTemplate {
    name: string;
    description: string;
    /** The application configuration of the template, for the next steps. */
    app: string;
}

/** dist/templates: filled by scripts/copy-templates.mjs when the package is built. */
export function templatesDir(): string {
    return path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', 'templates');
}

/** The templates of this installation, in the order of templates/templates.json. */
export function listTemplates(dir = templatesDir()): ProjectTemplate[] {
    const manifest = path.join(dir, 'templates.json');
    if (!existsSync(manifest)) {
        throw new CliError(
            `the project templates are missing (${manifest}): rebuild @maa/cli (npm run build -w @maa/cli)`,
            ExitCode.internal,
        );
    }
    return (JSON.parse(readFileSync(manifest, 'utf8')) as { templates: ProjectTemplate[] }).templates;
}

function formatTemplateList(templates: readonly ProjectTemplate[]): string {
    const width = Math.max(...templates.map((t) => t.name.length));
    return templates.map((t) => `  ${t.name.padEnd(width)}  ${t.description}\n`).join('');
}

/** Every file of a template folder, relative and `/`-separated, sorted. */
function filesOf(dir: string): string[] {
    const out: string[] = [];
    const visit = (rel: string): void => {
        const entries = readdirSync(path.join(dir, rel), { withFileTypes: true }).sort((a, b) => (a.name < b.name ? -1 : 1));
        for (const entry of entries) {
            const child = rel ? `${rel}/${entry.name}` : entry.name;
            if (entry.isDirectory()) visit(child);
            else if (entry.isFile()) out.push(child);
        }
    };
    visit('');
    return out;
}

/**
 * The files of the new project that would replace something: an existing file (or folder) at a
 * target path, or an existing non-folder where a target needs a folder.
 */
function collisions(target: string, files: readonly string[]): string[] {
    const found = new Set<string>();
    for (const rel of files) {
        const parts = rel.split('/');
        for (let i = 1; i <= parts.length; i++) {
            const p = path.join(target, ...parts.slice(0, i));
            let stats: ReturnType<typeof lstatSync> | undefined;
            try {
                stats = lstatSync(p);
            } catch {
                break; // nothing there: nothing below it exists either
            }
            if (i === parts.length || !stats.isDirectory()) {
                found.add(p);
                break;
            }
        }
    }
    return [...found];
}

function copyInto(source: string, target: string, files: readonly string[], io: CliIo): void {
    for (const rel of files) {
        const to = path.join(target, ...rel.split('/'));
        try {
            mkdirSync(path.dirname(to), { recursive: true });
            // COPYFILE_EXCL: never replace a file that appeared since the collision check.
            copyFileSync(path.join(source, ...rel.split('/')), to, constants.COPYFILE_EXCL);
        } catch (e) {
            const code = (e as NodeJS.ErrnoException).code;
            const why = code === 'EEXIST' ? 'it exists' : code === 'EACCES' || code === 'EPERM' ? 'permission denied' : (code ?? String(e));
            throw new CliError(`cannot write ${displayPath(to, io.cwd)} (${why})`);
        }
    }
}

function nextSteps(template: ProjectTemplate, target: string, io: CliIo): string {
    const rel = path.relative(io.cwd, target);
    const steps: Array<[string, string]> = [
        ...(rel === '' ? [] : [[`cd ${/\s/.test(rel) ? JSON.stringify(rel) : rel}`, ''] as [string, string]]),
        ['npx maa-gen check .', 'diagnostics of every model'],
        [`npx maa-gen test ${template.app}`, 'the stream tests on the timesync build (Python 3.11)'],
        [`npx maa-gen generate ${template.app} --platform timesync`, 'Python code into generated/timesync'],
        ['npx maa-gen lsp --stdio', 'the language server, for an editor'],
    ];
    const width = Math.max(...steps.map(([command]) => command.length));
    const lines = steps.map(([command, what]) => (what ? `  ${command.padEnd(width)}  # ${what}\n` : `  ${command}\n`));
    return `\nNext steps:\n${lines.join('')}`;
}

/** The refusal to overwrite: the first few existing files by name, then how many more. */
function overwriteRefusal(existing: readonly string[], template: ProjectTemplate, io: CliIo): CliError {
    const shown = 5;
    const lines = existing.slice(0, shown).map((p) => `refusing to overwrite ${displayPath(p, io.cwd)}`);
    if (existing.length > shown) lines.push(`... and ${existing.length - shown} more files of the template that exist`);
    lines.push(`nothing was written; choose another folder (maa-gen new ${template.name} DIR)`);
    return new CliError(lines.join('\n'));
}

/**
 * `maa-gen new <template> [dir]`: copies a project template into DIR (default: a new folder named
 * after the template). Writes nothing when any file of the template already exists there.
 */
export async function runNew(
    name: string | undefined,
    dirArg: string | undefined,
    options: NewCommandOptions,
    io: CliIo,
): Promise<ExitCode> {
    const templates = listTemplates();
    if (options.list) {
        io.out(formatTemplateList(templates));
        return ExitCode.ok;
    }
    const template = templates.find((t) => t.name === name);
    if (!template) {
        io.err(
            `maa-gen: error: ${name === undefined ? 'no template given' : `unknown template: ${name}`}\n` +
                `templates (maa-gen new <template> [dir]):\n${formatTemplateList(templates)}`,
        );
        return ExitCode.usage;
    }
    const source = path.join(templatesDir(), template.name);
    const target = path.resolve(io.cwd, dirArg ?? template.name);
    const files = filesOf(source);
    const existing = collisions(target, files);
    if (existing.length > 0) throw overwriteRefusal(existing, template, io);
    copyInto(source, target, files, io);
    io.out(
        `Created ${target === path.resolve(io.cwd) ? '.' : displayPath(target, io.cwd)} from the template ${template.name} (${files.length} files).\n`,
    );
    io.out(nextSteps(template, target, io));
    return ExitCode.ok;
}

export function newCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('new')
        .description('create a project from a template (maa-gen new --list shows them)')
        .argument('[template]', 'the template: minimal, toast-service (see --list)')
        .argument('[dir]', 'the folder to create the project in (default: ./<template>); may exist, but no file of the template may')
        .option('-l, --list', 'list the templates with a one-line description')
        .addHelpText(
            'after',
            `
Exit codes:
  0  the project was created (or --list)
  2  unknown template, or a file of the template exists in DIR (nothing is written), or DIR
     cannot be written

Examples:
  maa-gen new --list
  maa-gen new toast-service demo
  maa-gen new minimal .`,
        )
        .action(async (template: string | undefined, dir: string | undefined, options: NewCommandOptions) => {
            setExitCode(await runNew(template, dir, options, io));
        });
}
