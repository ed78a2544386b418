import { contract, type ContractIssue, dedupeIssues } from '../contract.js';
import { ExerciseManifest, ReleasedExercise } from './schema.js';

export * from './schema.js';

/** Checks a parsed `exercise.json` (the schema; {@link exerciseIssues} adds the rules between fields). */
export const exerciseManifestContract = contract('exercise.json', ExerciseManifest);
/** Checks a released exercise (what the lab server stores and serves). */
export const releasedExerciseContract = contract('released exercise', ReleasedExercise);

/** Whether the starter path is one the student may not edit (`readOnly`: a path, or a folder ending in `/`). */
export function isReadOnly(exercise: { readOnly: readonly string[] }, path: string): boolean {
    return exercise.readOnly.some((entry) => (entry.endsWith('/') ? path.startsWith(entry) : path === entry));
}

/**
 * Every issue of a parsed `exercise.json`, each with the JSON pointer of the field: the schema's,
 * then, when the starter's files are given (relative paths), that the app and every visible test
 * is one of them and every `readOnly` entry names one (a folder entry: a file below it).
 */
export function exerciseIssues(value: unknown, starterFiles?: readonly string[]): ContractIssue[] {
    const issues = exerciseManifestContract.issues(value);
    if (issues.length > 0 || !starterFiles) return dedupeIssues(issues);
    const manifest = value as ExerciseManifest;
    const files = new Set(starterFiles);
    const folder = manifest.starter ?? 'starter';
    const out: ContractIssue[] = [];
    if (!files.has(manifest.app)) out.push({ pointer: '/app', message: `${folder}/${manifest.app} does not exist` });
    manifest.tests.forEach((test, i) => {
        if (!files.has(test)) out.push({ pointer: `/tests/${i}`, message: `${folder}/${test} does not exist` });
    });
    manifest.readOnly.forEach((entry, i) => {
        if (!starterFiles.some((f) => isReadOnly({ readOnly: [entry] }, f)))
            out.push({
                pointer: `/readOnly/${i}`,
                message: `${folder}/${entry} ${entry.endsWith('/') ? 'holds no file' : 'does not exist'}`,
            });
    });
    return out;
}

/** Where a starter file comes from: the exercise's starter folder, or its `base`. */
export interface StarterSource {
    path: string;
    from: 'base' | 'starter';
}

/**
 * The starter of an exercise with a `base` (docs/lab.md "Exercises"): the base's files without
 * those `omit` names (a path, or a folder ending in `/`), then the starter folder's files, which
 * add to or replace them; sorted by path. The issues: `omit` without a base, an `omit` entry that
 * names no file of the base, or one the starter folder replaces anyway (omit drops base files only).
 */
export function layerStarter(
    manifest: Pick<ExerciseManifest, 'base' | 'omit' | 'starter'>,
    baseFiles: readonly string[],
    starterFiles: readonly string[],
): { files: StarterSource[]; issues: ContractIssue[] } {
    const omit = manifest.omit ?? [];
    const folder = manifest.starter ?? 'starter';
    const issues: ContractIssue[] = [];
    if (omit.length > 0 && manifest.base === undefined)
        issues.push({ pointer: '/omit', message: 'omit drops files of the base: it needs a base' });
    const own = new Set(starterFiles);
    omit.forEach((entry, i) => {
        const named = baseFiles.filter((f) => isReadOnly({ readOnly: [entry] }, f));
        if (manifest.base !== undefined && named.length === 0)
            issues.push({
                pointer: `/omit/${i}`,
                message: `${manifest.base}/${entry} ${entry.endsWith('/') ? 'holds no file' : 'does not exist'} (omit names files of the base)`,
            });
        const replaced = named.filter((f) => own.has(f));
        if (replaced.length > 0)
            issues.push({
                pointer: `/omit/${i}`,
                message: `${folder}/${replaced[0]} replaces the base's file already: omit only what the starter leaves out`,
            });
    });
    const files = new Map<string, StarterSource['from']>();
    for (const f of baseFiles) if (!isReadOnly({ readOnly: omit }, f)) files.set(f, 'base');
    for (const f of starterFiles) files.set(f, 'starter');
    const sorted = [...files.keys()].sort((a, b) => (a < b ? -1 : a > b ? 1 : 0));
    return { files: sorted.map((p) => ({ path: p, from: files.get(p) as StarterSource['from'] })), issues };
}
