/** Test helpers: an exercise of examples/lab materialized as a submission (base + starter + an overlay), and the model files of small models. */
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');
export const fixtures = path.join(path.dirname(fileURLToPath(import.meta.url)), 'fixtures');

export function tempDir(prefix: string): { dir: string; remove: () => void } {
    const dir = mkdtempSync(path.join(tmpdir(), `maa-grading-${prefix}-`));
    return { dir, remove: () => rmSync(dir, { recursive: true, force: true }) };
}

/**
 * The toast-controller exercise as a student's model root in `dir`: its base (examples/toast-service)
 * without the omitted files, the starter over it, then the reference solution (or not), then `overlay`.
 */
export function toastController(dir: string, options: { solution: boolean; overlay?: Record<string, string> }): string {
    const exercise = path.join(repoDir, 'examples', 'lab', 'toast-controller');
    const manifest = JSON.parse(readFileSync(path.join(exercise, 'exercise.json'), 'utf8')) as { base: string; omit: string[] };
    cpSync(path.resolve(exercise, manifest.base), dir, { recursive: true });
    for (const f of manifest.omit) rmSync(path.join(dir, f), { recursive: true, force: true });
    cpSync(path.join(exercise, 'starter'), dir, { recursive: true });
    if (options.solution) cpSync(path.join(exercise, 'solution'), dir, { recursive: true });
    writeFiles(dir, options.overlay ?? {});
    return dir;
}

export function writeFiles(dir: string, files: Record<string, string>): void {
    for (const [rel, text] of Object.entries(files)) {
        mkdirSync(path.dirname(path.join(dir, rel)), { recursive: true });
        writeFileSync(path.join(dir, rel), text);
    }
}
