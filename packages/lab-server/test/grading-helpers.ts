// Shared by grading-examples.test.ts and grading-malicious.test.ts: why a grading test cannot run
// here (no sim-server venv, no bubblewrap), a submission written out as a model root, and the
// words of a criterion's feedback.
import { accessSync, constants, cpSync, existsSync, mkdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import type { SubmissionGrade } from '@maa/protocol/grading';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
export const simPython = path.join(repo, 'sim-server/.venv/bin/python');

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
