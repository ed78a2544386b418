// `maa-lab grade --course C --exercise E` (docs/lab.md "Grading"): grades every student's latest
// submission of the exercise, progress on stderr, a table of the scores on stdout; exit code 1
// when the run failed.
import { Command } from 'commander';
import { DATA_DIR_HELP, DEFAULT_DATA_DIR, LabCliError, type LabIo, withStore } from '../cli/io.js';
import { ExerciseError } from '../exercises/errors.js';
import { courseNamed } from '../exercises/course.js';
import { instructor } from '../exercises/command.js';
import path from 'node:path';
import type { LabStore } from '../storage/index.js';
import type { GradeEngine } from './engine.js';
import { GradingBusy, GradingService, GradingUnavailable } from './service.js';
import { resultView, type ResultView } from './views.js';

interface GradeOptions {
    course: string;
    exercise: string;
    rayAddress?: string;
    python?: string;
    as?: string;
    dataDir?: string;
}

/** The scores as a table: one row per student, a column per criterion, the total. */
export function scoreTable(criteria: readonly string[], results: readonly ResultView[]): string {
    const header = ['student', ...criteria, 'total'];
    const rows = results.map((r) => [
        r.student.login,
        ...criteria.map((id) => {
            const c = r.criteria.find((x) => x.id === id);
            return c ? `${round(c.score)}/${round(c.max)}` : '-';
        }),
        `${round(r.score)}/${round(r.maxScore)}`,
    ]);
    const widths = header.map((h, i) => Math.max(h.length, ...rows.map((row) => (row[i] ?? '').length)));
    return [header, ...rows]
        .map((row) =>
            row
                .map((cell, i) => cell.padEnd(widths[i] ?? 0))
                .join('  ')
                .trimEnd(),
        )
        .join('\n');
}

function round(n: number): string {
    return String(Math.round(n * 100) / 100);
}

async function gradeExercise(io: LabIo, store: LabStore, options: GradeOptions, engine: GradeEngine | undefined): Promise<void> {
    const course = await courseNamed(store, options.course);
    const exercise = await store.findExercise(course.id, options.exercise);
    if (!exercise?.releasedAt)
        throw new LabCliError(`the course ${course.name} has no released exercise ${JSON.stringify(options.exercise)}`);
    const by = await instructor(store, course.name, options.as);
    const service = new GradingService(store, {
        ...(engine ? { engine } : {}),
        dataDir: path.resolve(io.cwd, options.dataDir ?? DEFAULT_DATA_DIR),
        ...(options.rayAddress ? { rayAddress: options.rayAddress } : {}),
        ...(options.python ? { python: path.resolve(io.cwd, options.python) } : {}),
        onProgress: (_run, p) => io.err(`maa-lab: grading ${exercise.name}: ${p.done}/${p.total} tasks done\n`),
    });
    let run = await service.gradeCourse(exercise, by).catch((e: unknown) => {
        if (e instanceof GradingUnavailable || e instanceof GradingBusy) throw new LabCliError(e.message);
        throw e;
    });
    io.err(`maa-lab: grading ${run.total} submissions of ${exercise.name} (run ${run.id})\n`);
    await service.settled();
    run = (await store.findGradingRun(run.id)) ?? run;
    if (run.status !== 'done') throw new LabCliError(`the grading run ${run.id} failed: ${run.error ?? run.status}`);
    const results = [];
    for (const result of await store.runResults(run.id)) {
        const user = await store.findUserById(result.userId);
        if (user) results.push(resultView(result, user));
    }
    const criteria = results[0]?.criteria.map((c) => c.id) ?? [];
    io.out(`${scoreTable(criteria, results)}\n`);
    io.out(`graded ${results.length} submissions of ${exercise.name} in ${course.name} (run ${run.id})\n`);
}

/** The `grade` command; `engine` replaces @maa/grading (tests). */
export function gradeCommand(io: LabIo, engine?: GradeEngine): Command {
    return new Command('grade')
        .description("grade every student's latest submission of an exercise (the exercise's grading/ folder says how)")
        .requiredOption('--course <name>', 'the course')
        .requiredOption('--exercise <name>', 'the released exercise')
        .option('--ray-address <address>', 'run the tasks on this Ray cluster (default: RAY_ADDRESS, else Ray on this machine)')
        .option('--python <file>', "the sim-server venv's interpreter (default: the grading engine's)")
        .option('--as <login>', "the instructor the run is recorded for (default: the course's only instructor)")
        .option('--data-dir <dir>', `${DATA_DIR_HELP}; recordings go to its recordings/`)
        .action((options: GradeOptions) =>
            withStore(io, options.dataDir, (store) =>
                gradeExercise(io, store, options, engine).catch((e: unknown) => {
                    if (e instanceof ExerciseError) throw new LabCliError(e.message);
                    throw e;
                }),
            ),
        );
}
