// `maa-lab exercise release | update` (docs/lab.md "Exercises"). The maa-lab program adds this
// command (registerExerciseCommands or exerciseCommand); it also runs on its own program in tests.
import path from 'node:path';
import { Command } from 'commander';
import { type LabStore, openLabStore, storageFromEnvironment, type User } from '../storage/index.js';
import { courseNamed } from './course.js';
import { ExerciseError } from './errors.js';
import type { LoadedGrading } from './grading-folder.js';
import { loadExercise } from './load.js';
import { releaseExercise } from './release.js';
import type { FileUpdate } from './update-workspace.js';
import { updateExercise } from './update.js';

/** What the commands talk to (maa-lab's LabIo has these and more). */
export interface ExerciseIo {
    readonly cwd: string;
    readonly env: NodeJS.ProcessEnv;
    out(text: string): void;
}

interface Options {
    course: string;
    as?: string;
    dataDir?: string;
}

const DATA_DIR_HELP = 'the embedded database folder (default ./lab-data; ignored when DATABASE_URL is set)';

async function withStore<T>(io: ExerciseIo, dataDir: string | undefined, work: (store: LabStore) => Promise<T>): Promise<T> {
    const store = await openLabStore(storageFromEnvironment(io.env, path.resolve(io.cwd, dataDir ?? 'lab-data')));
    try {
        return await work(store);
    } finally {
        await store.close();
    }
}

/** The instructor a release is recorded for: --as, else the course's only instructor, else the lab's only one. */
export async function instructor(store: LabStore, courseName: string, login: string | undefined): Promise<User> {
    if (login) {
        const user = await store.findUserByLogin(login);
        if (!user) throw new ExerciseError(`there is no user ${JSON.stringify(login)}`);
        if (user.role !== 'instructor') throw new ExerciseError(`${login} is no instructor`);
        return user;
    }
    const course = await courseNamed(store, courseName);
    const inCourse = (await store.listEnrolled(course.id)).filter((u) => u.role === 'instructor');
    const candidates = inCourse.length > 0 ? inCourse : (await store.listUsers()).filter((u) => u.role === 'instructor');
    if (candidates.length === 1 && candidates[0]) return candidates[0];
    throw new ExerciseError(
        candidates.length === 0
            ? 'the lab has no instructor: add one first (maa-lab users)'
            : 'name the instructor releasing it: --as LOGIN',
    );
}

function describeGrading(grading: LoadedGrading): string {
    const criteria = Array.isArray(grading.spec['criteria']) ? grading.spec['criteria'].length : 0;
    const hidden = Object.keys(grading.files).length;
    return `graded by grading/grading.json: ${criteria} criteria, ${hidden} hidden test file${hidden === 1 ? '' : 's'} (never shown to students)\n`;
}

function describeUpdates(login: string, files: readonly FileUpdate[]): string[] {
    return files
        .filter((f) => f.outcome !== 'unchanged')
        .map((f) =>
            f.outcome === 'conflict'
                ? `  ${login}: ${f.path}: CONFLICT, kept the student's file; the markers are in ${f.path}.conflict`
                : `  ${login}: ${f.path}: ${f.outcome}`,
        );
}

function withFolder(command: Command, description: string): Command {
    return command
        .description(description)
        .argument('<folder>', 'the exercise folder (with exercise.json; e.g. examples/lab/toast-controller)')
        .requiredOption('--course <name>', 'the course')
        .option('--as <login>', "the instructor doing it (default: the course's only instructor)")
        .option('--data-dir <dir>', DATA_DIR_HELP);
}

/** The `exercise` command with `release` and `update`. */
export function exerciseCommand(io: ExerciseIo): Command {
    const exercise = new Command('exercise').description('release exercises to a course and update them');
    withFolder(exercise.command('release'), 'release an exercise folder to a course: every enrolled user gets the starter').action(
        (folder: string, options: Options) =>
            withStore(io, options.dataDir, async (store) => {
                const loaded = await loadExercise(path.resolve(io.cwd, folder));
                const author = await instructor(store, options.course, options.as);
                const released = await releaseExercise(store, loaded, { course: options.course, authorId: author.id });
                const who = released.workspaces.length > 0 ? ` (${released.workspaces.join(', ')})` : '';
                io.out(
                    `released ${loaded.name} to ${options.course}: ${Object.keys(loaded.files).length} starter files, ` +
                        `${released.workspaces.length} workspaces${who}; students enrolled later get it when they open it\n`,
                );
                if (loaded.grading) io.out(describeGrading(loaded.grading));
            }),
    );
    withFolder(
        exercise.command('update'),
        "bring an updated exercise folder to a released exercise: starter changes are merged into students' files",
    ).action((folder: string, options: Options) =>
        withStore(io, options.dataDir, async (store) => {
            const loaded = await loadExercise(path.resolve(io.cwd, folder));
            const author = await instructor(store, options.course, options.as);
            const updated = await updateExercise(store, loaded, { course: options.course, authorId: author.id });
            if (!updated.newStarter) io.out(`updated ${loaded.name} in ${options.course}: the starter is unchanged\n`);
            else io.out(`updated ${loaded.name} in ${options.course}: starter version ${updated.spec.starterVersion}\n`);
            const lines = updated.workspaces.flatMap((w) => describeUpdates(w.login, w.files));
            if (lines.length > 0) io.out(`${lines.join('\n')}\n`);
            const conflicts = updated.workspaces.filter((w) => w.files.some((f) => f.outcome === 'conflict')).length;
            if (updated.workspaces.length > 0) io.out(`${updated.workspaces.length} workspaces, ${conflicts} with conflicts\n`);
            io.out(loaded.grading ? describeGrading(loaded.grading) : 'no grading/ folder: the exercise is not graded\n');
        }),
    );
    return exercise;
}

/** Adds `exercise release` and `exercise update` to the program. */
export function registerExerciseCommands(program: Command, io: ExerciseIo): Command {
    return program.addCommand(exerciseCommand(io));
}
