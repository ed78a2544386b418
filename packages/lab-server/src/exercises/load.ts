// Loads an exercise folder (examples/lab/<name>/): exercise.json checked against the format of
// @maa/protocol/exercise, its description and its starter files (its `base` folder's, without
// those it omits, with the starter folder's over them). Nothing else of the folder (a reference
// solution) is read, so nothing else can be released.
import { readdir, readFile, realpath, stat } from 'node:fs/promises';
import path from 'node:path';
import {
    EXERCISE_FILE_NAME,
    type ExerciseManifest,
    exerciseIssues,
    layerStarter,
    type ReleasedExercise,
    type StarterSource,
} from '@maa/protocol/exercise';
import { ExerciseError } from './errors.js';
import { type LoadedGrading, loadGrading } from './grading-folder.js';

/** An exercise folder, read and valid. */
export interface LoadedExercise {
    /** the folder's name: the exercise's name in a course */
    name: string;
    folder: string;
    manifest: ExerciseManifest;
    /** the description, Markdown */
    description: string;
    /** the starter: path (relative, `/`) → content */
    files: Record<string, string>;
    /** the grading folder (`grading/`: grading.json and its hidden files), when the exercise has one; never released to students */
    grading?: LoadedGrading;
}

const EXERCISE_NAME = /^[a-z0-9][a-z0-9-]*$/;

/** Names never part of a starter: generated output, caches, hidden files (as `maa-gen new` skips them). */
function skipped(name: string): boolean {
    return name.startsWith('.') || name === 'node_modules' || name === 'generated' || name === '__pycache__';
}

/** Every file below `dir` (relative, `/`-separated, sorted), without the skipped names. */
async function filesBelow(dir: string, rel = ''): Promise<string[]> {
    const entries = await readdir(path.join(dir, rel), { withFileTypes: true });
    const out: string[] = [];
    for (const entry of entries.sort((a, b) => (a.name < b.name ? -1 : 1))) {
        if (skipped(entry.name)) continue;
        const child = rel ? `${rel}/${entry.name}` : entry.name;
        if (entry.isDirectory()) out.push(...(await filesBelow(dir, child)));
        else if (entry.isFile()) out.push(child);
    }
    return out;
}

async function readJson(file: string): Promise<unknown> {
    let text: string;
    try {
        text = await readFile(file, 'utf8');
    } catch (e) {
        const code = (e as NodeJS.ErrnoException).code;
        throw new ExerciseError(`${file}: ${code === 'ENOENT' ? 'not found (an exercise folder holds exercise.json)' : String(e)}`);
    }
    try {
        return JSON.parse(text) as unknown;
    } catch (e) {
        throw new ExerciseError(`${file}: not JSON: ${(e as Error).message}`);
    }
}

async function starterFiles(folder: string, starter: string, where: string): Promise<string[]> {
    try {
        return await filesBelow(path.join(folder, ...starter.split('/')));
    } catch (e) {
        const code = (e as NodeJS.ErrnoException).code;
        throw new ExerciseError(
            `${where}: /starter: the folder ${starter} ${code === 'ENOENT' ? 'does not exist' : `cannot be read (${code})`}`,
        );
    }
}

async function readText(file: string, where: string, what: string): Promise<string> {
    try {
        const bytes = await readFile(file);
        const text = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
        if (text.includes('\u0000')) throw new TypeError('binary');
        return text;
    } catch (e) {
        const code = (e as NodeJS.ErrnoException).code;
        const why = code === 'ENOENT' ? 'does not exist' : code ? `cannot be read (${code})` : 'is not UTF-8 text';
        throw new ExerciseError(`${where}: ${what} ${why}`);
    }
}

/** Whether `inner` is `outer` or lies below it (both absolute). */
function within(outer: string, inner: string): boolean {
    const rel = path.relative(outer, inner);
    return rel === '' || (!rel.startsWith('..') && !path.isAbsolute(rel));
}

/**
 * The base folder, real path: it must exist, be a folder, lie below the exercise folder's
 * grandparent (the repository's examples/ for examples/lab/<name>) and neither hold the exercise
 * folder nor lie inside it (its solution would be released).
 */
async function baseFolder(folder: string, base: string, where: string): Promise<string> {
    const fail = (why: string) => new ExerciseError(`${where}: /base: ${why}`);
    const exercise = await realpath(folder);
    const root = path.dirname(path.dirname(exercise));
    let dir: string;
    try {
        dir = await realpath(path.resolve(folder, ...base.split('/')));
    } catch {
        throw fail(`the folder ${base} does not exist`);
    }
    if (!(await stat(dir)).isDirectory()) throw fail(`${base} is not a folder`);
    if (!within(root, dir)) throw fail(`${base} lies outside ${root} (a base lies beside the exercises, e.g. ../../toast-service)`);
    if (within(dir, exercise) || within(exercise, dir))
        throw fail(`${base} holds the exercise folder or lies in it (a base lies beside the exercises)`);
    return dir;
}

/** The starter's files and where each comes from, with the issues of `omit`. */
async function starterSources(folder: string, manifest: ExerciseManifest, where: string) {
    const own = await starterFiles(folder, manifest.starter ?? 'starter', where);
    const base = manifest.base === undefined ? undefined : await baseFolder(folder, manifest.base, where);
    const layered = layerStarter(manifest, base ? await filesBelow(base) : [], own);
    return { ...layered, base };
}

/** Reads and checks an exercise folder; an {@link ExerciseError} lists every problem by file and JSON path. */
export async function loadExercise(folder: string): Promise<LoadedExercise> {
    const name = path.basename(path.resolve(folder));
    const where = path.join(folder, EXERCISE_FILE_NAME);
    if (!EXERCISE_NAME.test(name))
        throw new ExerciseError(`${folder}: the folder's name is the exercise's name: lower case letters, digits and - only`);
    const json = await readJson(where);
    const schemaIssues = exerciseIssues(json);
    if (schemaIssues.length === 0) {
        const manifest = json as ExerciseManifest;
        const { files, issues, base } = await starterSources(folder, manifest, where);
        schemaIssues.push(
            ...issues,
            ...exerciseIssues(
                json,
                files.map((f) => f.path),
            ),
        );
        if (schemaIssues.length === 0) return readExercise(folder, name, manifest, files, where, base);
    }
    const problems = schemaIssues.map((i) => `${where}: ${i.pointer || '/'}: ${i.message}`);
    throw new ExerciseError(problems.join('\n'), problems);
}

async function readExercise(
    folder: string,
    name: string,
    manifest: ExerciseManifest,
    sources: readonly StarterSource[],
    where: string,
    base: string | undefined,
): Promise<LoadedExercise> {
    const starter = path.join(folder, ...(manifest.starter ?? 'starter').split('/'));
    const description = await readText(
        path.join(folder, ...manifest.description.split('/')),
        `${where}: /description`,
        manifest.description,
    );
    const files: Record<string, string> = {};
    for (const { path: rel, from } of sources) {
        const file = path.join(from === 'base' && base ? base : starter, ...rel.split('/'));
        files[rel] = await readText(file, file, from === 'base' ? 'the base file' : 'the starter file');
    }
    const grading = await loadGrading(folder);
    return { name, folder, manifest, description, files, ...(grading ? { grading } : {}) };
}

/** The exercise as stored and served once released, with the starter version its files are. */
export function releasedSpec(exercise: LoadedExercise, starterVersion: number): ReleasedExercise {
    const { format, title, app, readOnly, tests, platforms } = exercise.manifest;
    return {
        format,
        name: exercise.name,
        title,
        description: exercise.description,
        app,
        readOnly,
        tests,
        platforms,
        files: Object.keys(exercise.files),
        starterVersion,
    };
}
