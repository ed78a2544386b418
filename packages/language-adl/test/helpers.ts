import { EmptyFileSystem } from 'langium';
import { ModelTestBench, type Finding } from '../src/testing/index.js';
import { createAdlServices } from '../src/index.js';

export type { Finding };

const bench = new ModelTestBench(() => createAdlServices(EmptyFileSystem), 'adl');

/** Validates a model root given as files (path relative to the root -> text). */
export function validate(files: Readonly<Record<string, string>>): Promise<Finding[]> {
    return bench.validate(files);
}

/** The errors of a model root as `code@text` (the text the diagnostic marks). */
export async function errorsOf(files: Readonly<Record<string, string>>): Promise<string[]> {
    const found = await validate(files);
    return found.filter((f) => f.severity === 'error').map((f) => `${f.code}@${f.text}`);
}
