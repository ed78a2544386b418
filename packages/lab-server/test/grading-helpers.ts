// Shared by grading-examples.test.ts and grading-malicious.test.ts: why a grading test cannot run
// here (no sim-server venv, no bubblewrap), @maa/grading's gradeSubmissions loaded by name (the
// lab loads it so too: src/grading/engine.ts), and a submission written out as a model root.
import { accessSync, constants, cpSync, existsSync, mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import type { GradingSpec, SubmissionGrade } from '@maa/protocol/grading';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
export const simPython = path.join(repo, 'sim-server/.venv/bin/python');

/** The options of @maa/grading's gradeSubmissions that these tests use. */
export interface GradeCall {
    spec?: GradingSpec;
    gradingDir: string;
    submissions: { id: string; root: string; appFile: string }[];
    workDir: string;
    python?: string;
    onProgress?: (event: unknown) => void;
}
export type GradeSubmissions = (options: GradeCall) => Promise<SubmissionGrade[]>;

function onPath(name: string): string | undefined {
    for (const dir of (process.env['PATH'] ?? '').split(path.delimiter).concat(['/usr/bin', '/bin'])) {
        const file = path.join(dir, name);
        try {
            accessSync(file, constants.X_OK);
            return file;
        } catch {
            // not in this folder
        }
    }
    return undefined;
}

/** Why grading cannot run on this machine, or undefined when it can. */
export function gradingUnavailable(): string | undefined {
    if (!existsSync(simPython)) return `the sim-server venv is missing (${simPython}; bash sim-server/scripts/setup_env.sh creates it)`;
    if (onPath('bwrap') === undefined) return 'bubblewrap (bwrap) is not installed (node scripts/ensure-bubblewrap.mjs installs it)';
    return undefined;
}

/**
 * @maa/grading's gradeSubmissions, from the workspace's built package (lab-server does not depend
 * on it: the lab loads it by name on first use, src/grading/engine.ts).
 */
export async function loadGradeSubmissions(): Promise<GradeSubmissions> {
    const engine = (await import(pathToFileURL(path.join(repo, 'packages/grading/dist/index.js')).href)) as {
        gradeSubmissions?: GradeSubmissions;
    };
    if (typeof engine.gradeSubmissions !== 'function') throw new Error('@maa/grading exports no gradeSubmissions');
    return engine.gradeSubmissions;
}

/** Writes `files` (relative path → content) into `dir`, then copies each overlay folder over it. */
export function materialize(dir: string, files: Record<string, string>, overlays: string[] = []): string {
    for (const [rel, content] of Object.entries(files)) {
        const file = path.join(dir, ...rel.split('/'));
        mkdirSync(path.dirname(file), { recursive: true });
        writeFileSync(file, content);
    }
    for (const overlay of overlays) cpSync(overlay, dir, { recursive: true });
    return dir;
}

/** Everything a student could read in a grade: its feedback's words, scenarios, states and element links. */
export function feedbackText(criterion: SubmissionGrade['criteria'][number]): string {
    return criterion.feedback
        .map((f) => [f.text, f.scenario, f.state, f.element?.qualifiedName, f.element?.file].filter((x) => x !== undefined).join(' '))
        .join('\n');
}
