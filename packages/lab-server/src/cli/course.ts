// `maa-lab course create | enroll | list` (docs/lab.md "Running a lab").
import { Command } from 'commander';
import { StorageConflictError } from '../storage/index.js';
import { DATA_DIR_HELP, LabCliError, type LabIo, withStore } from './io.js';

const COURSE_NAME = /^[a-z0-9][a-z0-9._-]{0,63}$/;

export function courseCommand(io: LabIo): Command {
    const course = new Command('course').description('create courses and enroll users');
    course
        .command('create')
        .description('create a course')
        .argument('<name>', 'the course name used in commands and URLs (lower case letters, digits, . _ -)')
        .requiredOption('--title <title>', 'the title students see')
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .action((name: string, options: { title: string; dataDir?: string }) => {
            if (!COURSE_NAME.test(name))
                throw new LabCliError(
                    `the course name ${JSON.stringify(name)} may hold only lower case letters, digits and . _ - (at most 64)`,
                );
            return withStore(io, options.dataDir, async (store) => {
                await store.createCourse({ name, title: options.title }).catch((e: unknown) => {
                    if (e instanceof StorageConflictError) throw new LabCliError(`the course ${name} exists already`);
                    throw e;
                });
                io.out(`created the course ${name} (${options.title})\n`);
            });
        });
    course
        .command('enroll')
        .description('enroll users in a course')
        .argument('<course>', 'the course name')
        .argument('<logins...>', 'the users to enroll')
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .action((name: string, logins: string[], options: { dataDir?: string }) =>
            withStore(io, options.dataDir, async (store) => {
                const found = await store.findCourse(name);
                if (!found) throw new LabCliError(`there is no course ${JSON.stringify(name)}`);
                const users = await Promise.all(logins.map((login) => store.findUserByLogin(login)));
                const missing = logins.filter((_, i) => !users[i]);
                if (missing.length > 0) throw new LabCliError(`there is no user ${missing.join(', ')} (nobody was enrolled)`);
                for (const user of users) if (user) await store.enroll(found.id, user.id);
                io.out(`enrolled ${logins.join(', ')} in ${name}\n`);
            }),
        );
    course
        .command('list')
        .description('list the users enrolled in a course')
        .argument('<course>', 'the course name')
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .action((name: string, options: { dataDir?: string }) =>
            withStore(io, options.dataDir, async (store) => {
                const found = await store.findCourse(name);
                if (!found) throw new LabCliError(`there is no course ${JSON.stringify(name)}`);
                for (const u of await store.listEnrolled(found.id)) io.out(`${u.login}\t${u.role}\t${u.name}\n`);
            }),
        );
    return course;
}
