// A grading engine for the lab's tests of its grading routes and command (the real one,
// @maa/grading, runs in grading-run.test.ts): it scores what each submission's Controller.arc
// says (`// correct` 10 points, `// tested` 30), fails on `// explode`, reports progress like the
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
    return options.submissions.map((s) => {
        const controller = readFileSync(path.join(s.root, 'toast', 'Controller.arc'), 'utf8');
        if (controller.includes('// explode')) throw new Error('the engine failed on purpose');
        const recording = path.join(options.workDir, s.id, 'standard.mcap');
        mkdirSync(path.dirname(recording), { recursive: true });
        writeFileSync(recording, `mcap of ${s.id}`);
        options.onProgress?.({ event: 'task', id: `${s.id}.tests`, status: 'ok' });
        const correct = controller.includes('// correct') ? 10 : 0;
        const tested = controller.includes('// tested') ? 30 : 0;
        return {
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
        } satisfies SubmissionGrade;
    });
}
