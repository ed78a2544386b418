// An exercise's grading folder (`<exercise>/grading/`, docs/lab.md "Grading"): grading.json, checked
// against the GradingSpec contract (format maa-grading/1), and the hidden .stream files its `tests`
// criteria name. Read at release and update only; stored beside the exercise and never served to
// students (the starter never includes this folder).
import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import { gradingSpecIssues } from './grading-spec.js';
import { ExerciseError } from './errors.js';

export const GRADING_FOLDER = 'grading';
export const GRADING_FILE = 'grading.json';

/** A grading folder, read and valid: grading.json and the hidden files it names (path → content). */
export interface LoadedGrading {
    spec: Record<string, unknown>;
    files: Record<string, string>;
}

/** A hidden file's name: relative, `/`-separated, no `.` or `..` segment, a `.stream` file. */
const HIDDEN_FILE = /^(?!.*(?:^|\/)\.\.?(?:\/|$))[A-Za-z0-9_.-]+(?:\/[A-Za-z0-9_.-]+)*\.stream$/;

async function isFolder(dir: string): Promise<boolean> {
    return (await stat(dir).catch(() => undefined))?.isDirectory() === true;
}

/** The hidden files the spec's `tests` criteria name, with their JSON pointers. */
function namedFiles(spec: Record<string, unknown>): Array<{ file: string; pointer: string }> {
    const criteria = Array.isArray(spec['criteria']) ? (spec['criteria'] as unknown[]) : [];
    return criteria.flatMap((c, i) => {
        const criterion = c as { kind?: unknown; files?: unknown };
        if (criterion.kind !== 'tests' || !Array.isArray(criterion.files)) return [];
        return criterion.files.map((file, j) => ({ file: String(file), pointer: `/criteria/${i}/files/${j}` }));
    });
}

/**
 * Reads `<folder>/grading/` when the exercise has one (undefined otherwise). An
 * {@link ExerciseError} lists every problem by file and JSON pointer: grading.json missing, not
 * JSON, not a GradingSpec, or naming a hidden file that is not there or leaves the folder.
 */
export async function loadGrading(folder: string): Promise<LoadedGrading | undefined> {
    const dir = path.join(folder, GRADING_FOLDER);
    if (!(await isFolder(dir))) return undefined;
    const where = path.join(dir, GRADING_FILE);
    let json: unknown;
    try {
        json = JSON.parse(await readFile(where, 'utf8')) as unknown;
    } catch (e) {
        const code = (e as NodeJS.ErrnoException).code;
        throw new ExerciseError(
            `${where}: ${code === 'ENOENT' ? 'not found (a grading folder holds grading.json)' : `not JSON: ${(e as Error).message}`}`,
        );
    }
    const problems = gradingSpecIssues(json).map((i) => `${where}: ${i.pointer || '/'}: ${i.message}`);
    const spec = (problems.length === 0 ? json : {}) as Record<string, unknown>;
    const files: Record<string, string> = {};
    for (const { file, pointer } of namedFiles(spec)) {
        if (!HIDDEN_FILE.test(file)) {
            problems.push(`${where}: ${pointer}: ${JSON.stringify(file)} is no .stream file inside the grading folder`);
            continue;
        }
        try {
            files[file] = await readFile(path.join(dir, ...file.split('/')), 'utf8');
        } catch {
            problems.push(`${where}: ${pointer}: ${GRADING_FOLDER}/${file} does not exist`);
        }
    }
    if (problems.length > 0) throw new ExerciseError(problems.join('\n'), problems);
    return { spec, files };
}
