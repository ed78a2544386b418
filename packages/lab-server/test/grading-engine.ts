// A grading engine for the lab's tests of its grading routes and command (the real one,
// @maa/grading, runs in grading-run.test.ts): it scores what each submission's Controller.arc
// says (`// correct` 10 points, `// tested` 30), fails on `// explode`, waits on `// hold` until
// releaseHeld(), reports progress like the
// driver, and writes a recording per submission into its work folder.
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import type { SubmissionGrade } from '@maa/protocol/grading';
import type { EngineOptions } from '../src/grading/index.js';

/** Grades by the files: 10 points when Controller.arc says `// correct`, the hidden tests when it says `// tested`. */
export async function engine(options: EngineOptions): Promise<SubmissionGrade[]> {
    for (const criterion of options.spec.criteria)
        if (criterion.kind === 'tests') for (const file of criterion.files) readFileSync(path.join(options.gradingDir, file), 'utf8'); // throws when a hidden file is missing
    options.onProgress?.({ event: 'started', tasks: options.submissions.length, mode: 'local', nodes: 1, cpus: 1 });
    const grades: SubmissionGrade[] = [];
    for (const s of options.submissions) {
        const controller = readFileSync(path.join(s.root, 'toast', 'Controller.arc'), 'utf8');
        if (controller.includes('// explode')) throw new Error('the engine failed on purpose');
        if (controller.includes('// hold')) await new Promise<void>((resolve) => held.push(resolve));
        const recording = path.join(options.workDir, s.id, 'standard.mcap');
        mkdirSync(path.dirname(recording), { recursive: true });
        writeFileSync(recording, `mcap of ${s.id}`);
        options.onProgress?.({ event: 'task', id: `${s.id}.tests`, status: 'ok' });
        const correct = controller.includes('// correct') ? 10 : 0;
        const tested = controller.includes('// tested') ? 30 : 0;
        grades.push({
            submission: s.id,
            score: correct + tested,
            maxScore: 40,
            criteria: [
                { id: 'no-errors', title: 'The model has no errors', kind: 'diagnostics', score: correct, max: 10, feedback: [] },
                {
                    id: 'hidden-tests',
                    title: 'Hidden stream tests',
                    kind: 'tests',
                    score: tested,
                    max: 30,
                    feedback: tested
                        ? []
                        : [
                              {
                                  severity: 'error',
                                  text: "Hidden test 'serves' failed",
                                  element: { qualifiedName: 'toast.Controller', file: 'toast/Controller.arc', line: 3 },
                              },
                          ],
                },
            ],
            recordings: [{ scenario: 'standard', file: recording }],
            tasks: [{ id: `${s.id}.tests`, status: 'ok', seconds: 0.1 }],
        });
    }
    return grades;
}

/** The gradings waiting on `// hold`. */
const held: Array<() => void> = [];

/** Lets the gradings waiting on `// hold` go on; returns how many waited. */
export function releaseHeld(): number {
    const waiting = held.splice(0);
    for (const go of waiting) go();
    return waiting.length;
}
