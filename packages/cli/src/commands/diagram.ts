import { existsSync, statSync } from 'node:fs';
import path from 'node:path';
import { Command, Option } from 'commander';
import { CliError, ExitCode } from '../errors.js';
import type { CliIo } from '../io.js';
import { createProgress } from '../progress.js';
import { isModelFile, modelRootOfFile } from '../roots.js';
import { findComponent } from '../diagram/find-component.js';
import { type DiagramFormat, diagramSummary, rasterize, writeOutput } from '../diagram/output.js';

export interface DiagramCommandOptions {
    format?: DiagramFormat;
    out?: string;
    depth: string;
    automaton?: boolean;
    root?: string;
    scale: string;
}

type Language = typeof import('@maa/language-server');

/**
 * `maa-gen diagram COMPONENT [--automaton] [--depth N] [--format svg|png] [--out FILE]`: the
 * IDE's diagram of a component (its C&C view, or with --automaton the state machine of an
 * automaton or mode automaton) laid out by the same ELK layout and written as SVG (without a
 * browser: the diagram model rendered by @maa/language-server's SVG writer) or PNG (that SVG
 * rasterized by resvg). Exit 0 when written, 2 for usage and I/O problems, an unknown
 * component or a component without the asked-for view.
 */
export async function runDiagram(componentArg: string, options: DiagramCommandOptions, io: CliIo): Promise<ExitCode> {
    const depth = parseDepth(options.depth);
    const scale = parseScale(options.scale);
    const format = options.format ?? (options.out && path.extname(options.out).toLowerCase() === '.png' ? 'png' : 'svg');
    if (format === 'png' && options.out === '-') throw new CliError('--out - (standard output) takes SVG only; give a file for PNG');
    const file = modelFileArgument(componentArg, io.cwd);
    const root = modelRootFor(options.root, file, io.cwd);
    const progress = createProgress(io);
    try {
        progress?.update('loading the language services');
        // Loaded on demand, so that --help and usage errors stay fast.
        const language: Language = await import('@maa/language-server');
        const workspace = await language.loadDiagramWorkspace(root, (m) => progress?.update(m));
        const component = findComponent(
            language.workspaceComponents(workspace.family.shared.workspace.LangiumDocuments),
            componentArg,
            file,
        );
        progress?.update('laying out the diagram');
        const diagramType = options.automaton ? 'maa-automaton' : 'maa-cc';
        const expanded = options.automaton ? [] : language.expandedToDepth(component.node, depth);
        const graph = await language.standaloneDiagram(workspace.diagrams, { component: component.node, diagramType, expanded });
        if (graph.children.length === 0)
            throw new CliError(`${component.name} has no automaton and no mode automaton: there is no state machine to show`);
        const svg = language.renderDiagramSvg(graph);
        const out = options.out ?? `${component.name.split('.').pop()}${options.automaton ? '-automaton' : ''}.${format}`;
        const data = format === 'png' ? await rasterize(svg, scale) : svg;
        progress?.done();
        writeOutput(out, data, io);
        if (out !== '-') io.err(`${path.relative(io.cwd, path.resolve(io.cwd, out)) || out}: ${diagramSummary(graph, component.name)}\n`);
        const errors = workspace.diagnostics.filter((d) => d.severity === 'error').length;
        if (errors > 0)
            io.err(
                `note: the model root has ${errors} error${errors === 1 ? '' : 's'} (maa-gen check lists them); the diagram marks them\n`,
            );
    } finally {
        progress?.done();
    }
    return ExitCode.ok;
}

/** `--depth`: a level count from 1, or `all`. */
function parseDepth(text: string): number {
    if (text === 'all') return Number.POSITIVE_INFINITY;
    if (!/^[1-9]\d*$/.test(text)) throw new CliError(`--depth takes a number from 1 or "all", not "${text}"`);
    return Number(text);
}

function parseScale(text: string): number {
    const scale = Number(text);
    if (!Number.isFinite(scale) || scale <= 0 || scale > 20)
        throw new CliError(`--scale takes a number above 0 and at most 20, not "${text}"`);
    return scale;
}

/** The component argument as a model file (its component is shown), when it names one. */
function modelFileArgument(arg: string, cwd: string): string | undefined {
    const abs = path.resolve(cwd, arg);
    if (!isModelFile(abs)) return undefined;
    if (!existsSync(abs) || !statSync(abs).isFile()) throw new CliError(`model file not found: ${arg}`);
    return abs;
}

/** `--root`, else the model root of the named file, else that of the current folder (nearest maa.json above it, or itself). */
function modelRootFor(rootArg: string | undefined, file: string | undefined, cwd: string): string {
    if (rootArg !== undefined) {
        const root = path.resolve(cwd, rootArg);
        if (!existsSync(root) || !statSync(root).isDirectory()) throw new CliError(`model root not found: ${rootArg}`);
        return root;
    }
    // A file's root follows its package declaration; a name is looked up as from a file in the current folder.
    return file ? modelRootOfFile(file, undefined) : modelRootOfFile(path.join(cwd, 'component.arc'), undefined);
}

export function diagramCommand(io: CliIo, setExitCode: (code: ExitCode) => void): Command {
    return new Command('diagram')
        .description("draw a component's diagram as the IDE shows it (C&C view, or its state machine) as SVG or PNG")
        .argument('<component>', 'qualified name (toast.ToastServiceRobot), simple name if unique, or a model file (its component)')
        .option('--automaton', "the state-machine view: the component's automaton or mode automaton")
        .option(
            '-d, --depth <n>',
            'levels of subcomponents in the C&C view: 1 as the IDE opens it, 2 opens the composed ones, ... or "all"',
            '1',
        )
        .addOption(new Option('-f, --format <format>', 'output format (default: from --out, else svg)').choices(['svg', 'png']))
        .option('-o, --out <file>', 'output file, "-" for standard output (SVG) (default: COMPONENT.svg or COMPONENT-automaton.svg)')
        .option(
            '-r, --root <dir>',
            'model root to load (default: that of the model file, else the nearest folder with a maa.json above the current one, else the current folder)',
        )
        .option('--scale <factor>', 'PNG pixels per SVG unit', '2')
        .addHelpText(
            'after',
            `
What it does:
  loads and checks the model root, builds the diagram the IDE shows for the component (the
  same diagram model and ELK layout), and writes it: SVG with the IDE's classes, element ids
  and stylesheet (what the IDE's Export SVG gives, without live values), or PNG rendered from
  that SVG by resvg (no browser). Errors in the models are marked in the diagram as in the IDE.

Exit codes:
  0  written
  2  usage or I/O problem (unknown component, no automaton for --automaton, unwritable output)
  3  internal error (a bug; MAA_GEN_DEBUG=1 prints the stack trace)

Examples:
  maa-gen diagram toast.ToastServiceRobot --root examples/toast-service
  maa-gen diagram examples/toast-service/toast/Controller.arc --automaton --out controller.png
  maa-gen diagram Robot --depth all --out - > robot.svg`,
        )
        .action(async (component: string, options: DiagramCommandOptions) => {
            setExitCode(await runDiagram(component, options, io));
        });
}
