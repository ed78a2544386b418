// The files of a grading run on disk: the grading folder (grading.json + hidden files) and each
// submission's model root (its files at the submitted revisions, the exercise's read-only files
// from its newest starter over them), and the recordings copied into the data directory.
import { copyFile, mkdir, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { isReadOnly, type ReleasedExercise } from '@maa/protocol/exercise';
import type { GradingRecording, LabStore, OwnedSubmission } from '../storage/index.js';
import type { GradingSpec } from '../exercises/grading-spec.js';

/** Writes `rel` below `root`, refusing a path that would leave it. */
async function writeConfined(root: string, rel: string, content: string): Promise<void> {
    const target = path.resolve(root, ...rel.split('/'));
    if (!target.startsWith(root + path.sep)) throw new Error(`the path ${JSON.stringify(rel)} leaves ${root}`);
    await mkdir(path.dirname(target), { recursive: true });
    await writeFile(target, content);
}

/** The grading folder: grading.json and the hidden files. */
export async function writeGradingDir(dir: string, spec: GradingSpec, files: Record<string, string>): Promise<void> {
    await mkdir(dir, { recursive: true });
    await writeFile(path.join(dir, 'grading.json'), JSON.stringify(spec, null, 2));
    for (const [rel, content] of Object.entries(files)) await writeConfined(dir, rel, content);
}

/**
 * A submission's model root: every file of the submission at its submitted revision, then the
 * exercise's read-only files from the newest starter (a student cannot change them; a read-only
 * file they never had is the exercise's too).
 */
export async function writeSubmissionRoot(
    store: LabStore,
    submission: OwnedSubmission,
    spec: ReleasedExercise,
    starter: Record<string, string>,
    root: string,
): Promise<void> {
    await mkdir(root, { recursive: true });
    for (const [rel, revision] of Object.entries(submission.files)) {
        if (isReadOnly(spec, rel)) continue;
        const file = await store.readFile(submission.workspaceId, rel, revision);
        if (file?.content != null) await writeConfined(root, rel, file.content);
    }
    for (const [rel, content] of Object.entries(starter)) if (isReadOnly(spec, rel)) await writeConfined(root, rel, content);
}

/** A scenario's file name: its id when it is a plain name, else a safe form of it. */
export function recordingName(scenario: string): string {
    const safe = scenario.replace(/[^A-Za-z0-9_-]/g, '_').slice(0, 100);
    return `${safe || 'scenario'}.mcap`;
}

/**
 * Copies a result's recordings from the engine's work folder into
 * `<dataDir>/recordings/<run>/<result>/<scenario>.mcap`; a file outside the work folder or missing
 * is skipped. Returns the stored entries (paths relative to the data directory).
 */
export async function keepRecordings(
    dataDir: string,
    workDir: string,
    runId: number,
    resultId: number,
    recordings: ReadonlyArray<{ scenario: string; file: string }>,
): Promise<GradingRecording[]> {
    const kept: GradingRecording[] = [];
    const work = path.resolve(workDir);
    for (const { scenario, file } of recordings) {
        const source = path.resolve(file);
        if (!source.startsWith(work + path.sep)) continue;
        if (!(await stat(source).catch(() => undefined))?.isFile()) continue;
        const rel = ['recordings', String(runId), String(resultId), recordingName(scenario)];
        const target = path.join(dataDir, ...rel);
        await mkdir(path.dirname(target), { recursive: true, mode: 0o700 });
        await copyFile(source, target);
        kept.push({ scenario, path: rel.join('/') });
    }
    return kept;
}

/** The absolute file of a stored recording, or undefined when its path would leave `<dataDir>/recordings`. */
export function recordingFile(dataDir: string, recording: GradingRecording): string | undefined {
    const root = path.resolve(dataDir, 'recordings');
    const file = path.resolve(dataDir, ...recording.path.split('/'));
    return file.startsWith(root + path.sep) && file.endsWith('.mcap') ? file : undefined;
}
