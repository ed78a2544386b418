// Loads an exercise folder (examples/lab/<name>/): exercise.json checked against the format of
// @maa/protocol/exercise, its description and its starter files. Nothing else of the folder (a
// reference solution) is read, so nothing else can be released.
import { readdir, readFile } from 'node:fs/promises';
import path from 'node:path';
import { EXERCISE_FILE_NAME, type ExerciseManifest, exerciseIssues, type ReleasedExercise } from '@maa/protocol/exercise';
import { ExerciseError } from './errors.js';

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

/** Reads and checks an exercise folder; an {@link ExerciseError} lists every problem by file and JSON path. */
export async function loadExercise(folder: string): Promise<LoadedExercise> {
    const name = path.basename(path.resolve(folder));
    const where = path.join(folder, EXERCISE_FILE_NAME);
    if (!EXERCISE_NAME.test(name))
        throw new ExerciseError(`${folder}: the folder's name is the exercise's name: lower case letters, digits and - only`);
    const json = await readJson(where);
    const schemaIssues = exerciseIssues(json);
    if (schemaIssues.length === 0) {
        const starter = (json as ExerciseManifest).starter ?? 'starter';
        const paths = await starterFiles(folder, starter, where);
        schemaIssues.push(...exerciseIssues(json, paths));
        if (schemaIssues.length === 0) return readExercise(folder, name, json as ExerciseManifest, paths, where);
    }
    const problems = schemaIssues.map((i) => `${where}: ${i.pointer || '/'}: ${i.message}`);
    throw new ExerciseError(problems.join('\n'), problems);
}

async function readExercise(
    folder: string,
    name: string,
    manifest: ExerciseManifest,
    paths: string[],
    where: string,
): Promise<LoadedExercise> {
    const starter = path.join(folder, ...(manifest.starter ?? 'starter').split('/'));
    const description = await readText(
        path.join(folder, ...manifest.description.split('/')),
        `${where}: /description`,
        manifest.description,
    );
    const files: Record<string, string> = {};
    for (const rel of paths)
        files[rel] = await readText(path.join(starter, ...rel.split('/')), path.join(starter, rel), 'the starter file');
    return { name, folder, manifest, description, files };
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
