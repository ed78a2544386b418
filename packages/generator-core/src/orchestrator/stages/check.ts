import { AstUtils, type AstNode } from 'langium';
import type { AppFinding } from '../../app/app-checks.js';
import type { ApplicationVariant } from '../../app/app-variant.js';
import { AppCodes } from '../../app/codes.js';
import { isAppPlatform, type AppPlatform, type Application } from '../../generated/ast.js';
import type { ArchitectureModel } from '../../model/architecture.js';
import { findingDiagnostic, inside } from '../diagnostics.js';
import { failure, hasErrors, outcome, timed, type GenerationRun, type StageResult } from '../run.js';
import { GenerateInputError, type GenerationDiagnostic } from '../types.js';
import type { Loaded } from './load.js';

/** The checked application: the platforms to generate, its feature configuration and its architecture. */
export interface Checked {
    readonly platforms: readonly AppPlatform[];
    readonly variant: ApplicationVariant;
    /** Built once (by the application's analysis) and passed to every later stage. */
    readonly architecture: ArchitectureModel;
}

/**
 * Check: the diagnostics of the files generation reads (the configuration, except what concerns
 * other platforms, and the architecture's files), the feature configuration, then the `app/`
 * checks of the platforms to generate. The application is checked once: the `app/` findings
 * and the architecture come from the `.arcapp` language's analysis of it, which the document
 * validator computed while loading (or which is computed here, once, if it did not). Throws
 * GenerateInputError for a platform the configuration does not have.
 */
export function check(run: GenerationRun, loaded: Loaded): StageResult<Checked> {
    const platforms = selectPlatforms(loaded.app, run.options.platforms);
    return timed(run, 'check', () => {
        run.progress({ phase: 'check', message: 'checking the configuration and the architecture' });
        const { modelRoot, appFile } = run;
        const analysis = loaded.arcApp.generators.Applications.analyze(loaded.app);
        const { architecture, variant } = analysis;
        const diagnostics: GenerationDiagnostic[] = [];
        // The app/ checks of the editor's check are replaced by those below (per platform, on the model elements).
        const relevant = new Set<string>([appFile, ...(architecture ? architectureFiles(architecture) : [])]);
        const otherPlatforms = loaded.app.platforms.filter((p) => !platforms.includes(p));
        for (const d of loaded.found) {
            if (!relevant.has(d.file)) continue;
            if (d.file === appFile && d.code.startsWith('app/') && d.code !== 'app/unknown-component' && d.code !== 'app/unknown-generator')
                continue;
            if (d.file === appFile && otherPlatforms.some((p) => inside(d, p))) continue;
            diagnostics.push(d);
        }
        // The feature configuration concerns every platform.
        for (const f of variant.findings) diagnostics.push(findingDiagnostic(modelRoot, f));
        if (!architecture || hasErrors(diagnostics)) return failure(diagnostics);
        const selected = new Set<AstNode>(platforms);
        for (const f of analysis.findings) {
            if (variant.findings.includes(f) || !concernsPlatforms(f, selected)) continue;
            diagnostics.push(findingDiagnostic(modelRoot, f));
        }
        return outcome({ platforms, variant, architecture }, diagnostics);
    });
}

/** A finding about one of the selected platforms, or a duplicate platform (which concerns all). */
function concernsPlatforms(f: AppFinding, selected: ReadonlySet<AstNode>): boolean {
    if (f.code === AppCodes.DuplicatePlatform) return true;
    const platform = AstUtils.getContainerOfType(f.node, isAppPlatform);
    return platform === undefined || selected.has(platform);
}

/** The platforms to generate: the named ones (in that order), or every platform once. */
export function selectPlatforms(app: Application, names: readonly string[] | undefined): AppPlatform[] {
    if (!names || names.length === 0) {
        if (app.platforms.length === 0) throw new GenerateInputError(`application '${app.name}' configures no platform`);
        const seen = new Set<string>();
        return app.platforms.filter((p) => {
            if (seen.has(p.name)) return false;
            seen.add(p.name);
            return true;
        });
    }
    return names.map((n) => {
        const p = app.platforms.find((q) => q.name === n);
        if (!p) {
            throw new GenerateInputError(
                `application '${app.name}' has no platform '${n}' (platforms: ${app.platforms.map((q) => q.name).join(', ') || 'none'})`,
            );
        }
        return p;
    });
}

function architectureFiles(a: ArchitectureModel): string[] {
    const nodes: AstNode[] = [...a.components.map((c) => c.node), ...a.dataTypes.map((t) => t.node)];
    return [
        ...new Set(
            nodes
                .map((n) => AstUtils.getDocument(n).uri)
                .filter((u) => u.scheme === 'file')
                .map((u) => u.fsPath),
        ),
    ];
}
