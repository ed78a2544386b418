/** Loading an exercise's grading specification (`grading/grading.json`) with errors that name the file and the field. */
import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import { GRADING_FILE_NAME, type GradingSpec, gradingSpecIssues } from '@maa/protocol/grading';

/** A grading folder whose `grading.json` is missing, unreadable or breaks the format; the message names the file and fields. */
export class GradingSpecError extends Error {
    constructor(
        readonly file: string,
        readonly issues: ReadonlyArray<{ pointer: string; message: string }>,
        message: string,
    ) {
        super(message);
        this.name = 'GradingSpecError';
    }
}

/**
 * The grading specification of a grading folder: `grading.json` checked against the format, and
 * every hidden `.stream` file a tests criterion names present in the folder.
 */
export async function loadGradingSpec(dir: string): Promise<GradingSpec> {
    const file = path.join(dir, GRADING_FILE_NAME);
    let text: string;
    try {
        text = await readFile(file, 'utf8');
    } catch (e) {
        throw new GradingSpecError(
            file,
            [],
            `${file}: cannot read the grading specification (${(e as NodeJS.ErrnoException).code ?? String(e)})`,
        );
    }
    let value: unknown;
    try {
        value = JSON.parse(text);
    } catch (e) {
        throw new GradingSpecError(file, [], `${file}: not JSON: ${(e as Error).message}`);
    }
    const issues = gradingSpecIssues(value);
    const spec = value as GradingSpec;
    if (issues.length === 0) issues.push(...(await missingStreamFiles(spec, dir)));
    if (issues.length > 0) {
        const shown = issues.slice(0, 5).map((i) => `${i.pointer || '/'}: ${i.message}`);
        if (issues.length > 5) shown.push(`(${issues.length - 5} more)`);
        throw new GradingSpecError(file, issues, `${file}: not a valid grading specification: ${shown.join('; ')}`);
    }
    return spec;
}

async function missingStreamFiles(spec: GradingSpec, dir: string): Promise<Array<{ pointer: string; message: string }>> {
    const out: Array<{ pointer: string; message: string }> = [];
    for (const [i, criterion] of spec.criteria.entries()) {
        if (criterion.kind !== 'tests') continue;
        for (const [j, name] of criterion.files.entries()) {
            const isFile = await stat(path.join(dir, name)).then(
                (s) => s.isFile(),
                () => false,
            );
            if (!isFile) out.push({ pointer: `/criteria/${i}/files/${j}`, message: `${name} does not exist in the grading folder` });
        }
    }
    return out;
}
