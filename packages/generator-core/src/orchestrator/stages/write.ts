import path from 'node:path';
import { AstUtils, type AstNode } from 'langium';
import type { HostLanguageServices } from '@maa/language-adl';
import type { Trace, TraceElement, TraceFile } from '@maa/protocol';
import { TRACE_FORMAT_VERSION } from '@maa/protocol/formats';
import type { PlatformSelection } from '../../app/app-checks.js';
import type { PlatformInfo } from '../../generators/types.js';
import type { FinishedFile } from '../../output/file-builder.js';
import { OutputWriteError } from '../../output/layout.js';
import { OutputTransaction } from '../../output/transaction.js';
import { planOutput, sha256, TRACE_FILE, type WritePlan } from '../../output/writer.js';
import { at } from '../diagnostics.js';
import { GenCodes } from '../gen-codes.js';
import {
    failure,
    hasErrors,
    outcome,
    timed,
    type GeneratorInstance,
    type GenerationRun,
    type PlatformOutput,
    type StageResult,
} from '../run.js';
import type { GenerationDiagnostic, PlatformResult } from '../types.js';
import type { Checked } from './check.js';
import type { Configured } from './configure.js';
import { platformInfo, type Generated } from './generate.js';
import type { Loaded } from './load.js';
import type { Selected } from './select.js';

/**
 * Write: the trace file of every platform, then one transaction over all output folders
 * (output/transaction.ts: staged beside the current output, then each platform folder switched
 * in one rename; a run killed at any point leaves the old output whole). The output root is
 * locked and cleaned up after killed runs before anything of it is read. Nothing is written
 * when a regenerated file would drop user content of a protected region.
 */
export function write(
    run: GenerationRun,
    loaded: Loaded,
    checked: Checked,
    selected: Selected,
    configured: Configured,
    generated: Generated,
): StageResult<PlatformResult[]> {
    let tx: OutputTransaction;
    try {
        tx = timed(run, 'write', () => OutputTransaction.open(run.outRoot));
    } catch (e) {
        return writeFailed(run, [], e);
    }
    try {
        const planned = planPlatforms(run, loaded, checked, selected, configured, generated);
        const diagnostics = planned.flatMap((p) => planDiagnostics(run, p));
        if (hasErrors(diagnostics)) return failure(diagnostics);
        try {
            commitPlans(run, tx, planned);
        } catch (e) {
            return writeFailed(run, diagnostics, e);
        }
        return outcome(
            planned.map(({ plan, output }) => platformResult(plan, output)),
            diagnostics,
        );
    } finally {
        tx.close();
    }
}

/** A platform's generated files and what writing them would change. */
interface PlannedOutput {
    readonly plan: WritePlan;
    readonly output: PlatformOutput;
}

/** The trace file of each platform, then the write plan of its folder (protected regions merged). */
function planPlatforms(
    run: GenerationRun,
    loaded: Loaded,
    checked: Checked,
    selected: Selected,
    configured: Configured,
    generated: Generated,
): PlannedOutput[] {
    return generated.outputs.map((output) => {
        const trace = timed(run, 'trace', () =>
            traceFile(
                run.options.services,
                run.modelRoot,
                output.outDir,
                platformInfo(loaded, checked, output.platform),
                output.files,
                selected.selections.get(output.platform)!,
                configured.instances,
            ),
        );
        return { plan: timed(run, 'write', () => planOutput(output.outDir, output.files, trace)), output };
    });
}

/** What a plan would lose (user content of a dropped protected region: an error) or keep (a stale file with user content). */
function planDiagnostics(run: GenerationRun, { plan, output }: PlannedOutput): GenerationDiagnostic[] {
    const { modelRoot, appFile, shown } = run;
    const platform = output.platform;
    const dropped = plan.droppedRegions.map((d) =>
        at(
            modelRoot,
            appFile,
            platform.$cstNode?.range,
            'error',
            GenCodes.ProtectedRegionDropped,
            `Platform '${platform.name}': ${shown(path.join(output.outDir, d.path))} has user content in protected region${d.regions.length > 1 ? 's' : ''} ${d.regions.map((r) => `'${r}'`).join(', ')}, which the regenerated file no longer has; move that content and run again (nothing was written).`,
        ),
    );
    const kept = plan.keptStale.map((stale) =>
        at(
            modelRoot,
            appFile,
            platform.$cstNode?.range,
            'warning',
            GenCodes.StaleFileKept,
            `Platform '${platform.name}': ${shown(path.join(output.outDir, stale))} is no longer generated but holds user content in protected regions; it was kept (delete it when done).`,
        ),
    );
    return [...dropped, ...kept];
}

/** Stages every platform's plan in the transaction and switches them in. */
function commitPlans(run: GenerationRun, tx: OutputTransaction, planned: readonly PlannedOutput[]): void {
    timed(run, 'write', () => {
        run.progress({ phase: 'write', message: `writing ${planned.reduce((n, p) => n + p.plan.write.length, 0)} files` });
        for (const p of planned) tx.stage(p.plan);
        tx.commit();
    });
}

/** The output could not be written: the diagnostics so far and an error saying nothing was changed. */
function writeFailed(run: GenerationRun, diagnostics: readonly GenerationDiagnostic[], e: unknown): StageResult<never> {
    const problem = e instanceof OutputWriteError ? `${run.shown(e.path)}: ${e.reason}` : (e as Error).message;
    return failure([
        ...diagnostics,
        at(
            run.modelRoot,
            run.appFile,
            undefined,
            'error',
            GenCodes.WriteFailed,
            `Cannot write the output: ${problem}. Nothing was changed.`,
        ),
    ]);
}

function platformResult(plan: WritePlan, output: PlatformOutput): PlatformResult {
    return {
        platform: output.platform.name,
        outDir: output.outDir,
        files: output.files.map((f) => f.path),
        generators: output.generators,
        // The trace file is written with every generation; the lists name the generated files.
        written: plan.write.map((f) => f.path).filter((p) => p !== TRACE_FILE),
        unchanged: plan.unchanged.filter((p) => p !== TRACE_FILE),
        kept: plan.kept,
        removed: plan.remove,
        preservedRegions: plan.preservedRegions,
        keptStale: plan.keptStale,
    };
}

/**
 * The trace file (`@maa/protocol`'s TraceFile, format version 2): generated lines -> model
 * elements (file relative to the model root, range, AST path). Positions follow the protocol's
 * one convention, LSP's: lines and characters 0-based, a range's end exclusive (Langium's CST
 * range as it is), generated line spans 0-based with both ends inclusive.
 */
export function traceFile(
    services: HostLanguageServices,
    modelRoot: string,
    outDir: string,
    platform: PlatformInfo,
    files: readonly FinishedFile[],
    selection: PlatformSelection,
    instances: ReadonlyMap<string, GeneratorInstance>,
): string {
    const locator = services.Arc.workspace.AstNodeLocator;
    const relRoot = path.relative(outDir, modelRoot).split(path.sep).join('/') || '.';
    // Per model file (the root node of its document) its name in the trace file, computed once:
    // a large model has thousands of traced elements in a few hundred files.
    const modelFiles = new Map<AstNode, string>();
    const fileOf = (node: AstNode): string => {
        const root = AstUtils.findRootNode(node);
        let file = modelFiles.get(root);
        if (file === undefined) {
            const uri = AstUtils.getDocument(node).uri;
            file = uri.scheme === 'file' ? path.relative(modelRoot, uri.fsPath).split(path.sep).join('/') : uri.toString();
            modelFiles.set(root, file);
        }
        return file;
    };
    const element = (node: AstNode): TraceElement => {
        const r = node.$cstNode?.range;
        const name = (node as { name?: unknown }).name;
        return {
            file: fileOf(node),
            range: r
                ? { start: { line: r.start.line, character: r.start.character }, end: { line: r.end.line, character: r.end.character } }
                : null,
            path: locator.getAstNodePath(node),
            type: node.$type,
            ...(typeof name === 'string' ? { name } : {}),
        };
    };
    const generators: TraceFile['generators'] = selection.references
        .filter((r, i, all) => all.findIndex((q) => q.generator === r.generator) === i && instances.has(r.generator.manifest.name))
        .map((r) => ({
            name: r.generator.manifest.name,
            kind: r.generator.manifest.kind,
            package: r.generator.source.packageName,
            version: r.generator.source.packageVersion,
        }));
    const trace: TraceFile = {
        version: TRACE_FORMAT_VERSION,
        application: platform.application,
        platform: platform.platform,
        rootComponent: platform.rootComponent,
        modelRoot: relRoot,
        generators,
        files: files.map((f) => ({
            path: f.path,
            generator: f.generator,
            userFile: f.userFile,
            sha256: sha256(f.content),
            lines: lineCount(f.content),
            // FileBuilder counts lines from 1.
            traces: f.traces.map(
                (t): Trace => ({
                    lines: { first: t.startLine - 1, last: t.endLine - 1 },
                    generator: t.generator,
                    element: element(t.element),
                }),
            ),
        })),
    };
    return `${JSON.stringify(trace, null, 1)}\n`;
}

/** The number of lines of a text (a last line without a line break counts; an empty text has none). */
function lineCount(text: string): number {
    let breaks = 0;
    for (let i = text.indexOf('\n'); i !== -1; i = text.indexOf('\n', i + 1)) breaks++;
    return text.length === 0 ? 0 : breaks + (text.endsWith('\n') ? 0 : 1);
}
