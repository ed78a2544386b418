// `maa-lab users add | import | list` (docs/lab.md "Accounts", "Roster").
import { readFile, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { Command, Option } from 'commander';
import { DEFAULT_INVITATION_DAYS, invitationLink, inviteUser, newInvitation } from '../auth/invitations.js';
import { hashPassword, passwordProblem } from '../auth/passwords.js';
import { loginProblem, parseRoster, RosterError, type RosterEntry } from '../auth/roster.js';
import { DEFAULT_PORT } from '../http/server.js';
import { type ImportedUser, type LabStore, type Role, StorageConflictError } from '../storage/index.js';
import { DATA_DIR_HELP, LabCliError, type LabIo, withStore } from './io.js';

const PUBLIC_URL_HELP = `the address students open, for the invitation links (default http://127.0.0.1:${DEFAULT_PORT})`;

function days(value: string): number {
    const n = Number(value);
    if (!Number.isInteger(n) || n < 1 || n > 365)
        throw new LabCliError(`--expires-days must be a whole number from 1 to 365, not ${value}`);
    return n;
}

async function courseId(store: LabStore, name: string | undefined): Promise<number | undefined> {
    if (name === undefined) return undefined;
    const course = await store.findCourse(name);
    if (!course)
        throw new LabCliError(`there is no course ${JSON.stringify(name)} (create it with: maa-lab course create ${name} --title ...)`);
    return course.id;
}

interface AddOptions {
    name: string;
    role: Role;
    email?: string;
    course?: string;
    passwordStdin?: boolean;
    publicUrl?: string;
    expiresDays: string;
    dataDir?: string;
}

export function usersCommand(io: LabIo): Command {
    const users = new Command('users').description('add users, import a roster, list users');
    users
        .command('add')
        .description('add one user; prints a one-time invitation link, or sets the password read from stdin (--password-stdin)')
        .argument('<login>', 'the login name')
        .requiredOption('--name <name>', 'the full name')
        .addOption(new Option('--role <role>', 'instructor or student').choices(['instructor', 'student']).default('student'))
        .option('--email <address>', 'the e-mail address (single sign-on finds users by it)')
        .option('--course <name>', 'enroll the user in this course')
        .option('--password-stdin', 'read the password from standard input instead of printing an invitation link')
        .option('--public-url <url>', PUBLIC_URL_HELP)
        .option('--expires-days <n>', 'how long the invitation link works', String(DEFAULT_INVITATION_DAYS))
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .action((login: string, options: AddOptions) => addUser(io, login, options));
    users
        .command('import')
        .description(
            'import a roster CSV (columns name, email, login, role); prints a one-time invitation link per user, or writes them to --out',
        )
        .argument('<roster.csv>', 'the roster file')
        .option('--course <name>', 'enroll everyone in this course')
        .option('--out <file.csv>', 'write the links to this CSV file (login,name,email,link) instead of printing them')
        .option('--public-url <url>', PUBLIC_URL_HELP)
        .option('--expires-days <n>', 'how long the invitation links work', String(DEFAULT_INVITATION_DAYS))
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .action((file: string, options: { course?: string; out?: string; publicUrl?: string; expiresDays: string; dataDir?: string }) =>
            importRoster(io, file, options),
        );
    users
        .command('invite')
        .description('make a new one-time invitation link for an existing user (e.g. when the first expired)')
        .argument('<login>', 'the login name')
        .option('--public-url <url>', PUBLIC_URL_HELP)
        .option('--expires-days <n>', 'how long the invitation link works', String(DEFAULT_INVITATION_DAYS))
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .action((login: string, options: { publicUrl?: string; expiresDays: string; dataDir?: string }) =>
            withStore(io, options.dataDir, async (store) => {
                const user = await store.findUserByLogin(login);
                if (!user) throw new LabCliError(`there is no user ${login}`);
                const link = await inviteUser(store, user, publicUrl(options.publicUrl), days(options.expiresDays));
                io.out(`a new one-time invitation link for ${login}:\n${link}\n`);
            }),
        );
    users
        .command('list')
        .description('list every user (login, role, name, e-mail)')
        .option('--data-dir <dir>', DATA_DIR_HELP)
        .action((options: { dataDir?: string }) =>
            withStore(io, options.dataDir, async (store) => {
                for (const u of await store.listUsers()) io.out(`${u.login}\t${u.role}\t${u.name}\t${u.email ?? ''}\n`);
            }),
        );
    return users;
}

async function addUser(io: LabIo, login: string, options: AddOptions): Promise<void> {
    const problem = loginProblem(login);
    if (problem) throw new LabCliError(problem);
    const expires = days(options.expiresDays);
    let passwordHash: string | undefined;
    if (options.passwordStdin) {
        const password = await io.readSecret(`password for ${login}: `);
        const weak = passwordProblem(password);
        if (weak) throw new LabCliError(weak);
        passwordHash = await hashPassword(password);
    }
    await withStore(io, options.dataDir, async (store) => {
        const course = await courseId(store, options.course);
        const invitation = passwordHash ? undefined : newInvitation(expires);
        const entry: ImportedUser = {
            user: { login, name: options.name, role: options.role, email: options.email ?? null, passwordHash: passwordHash ?? null },
            ...(invitation ? { invitation: { id: invitation.id, expiresAt: invitation.expiresAt } } : {}),
        };
        await store.importUsers([entry], course).catch(conflict(`the login ${login} or the e-mail ${options.email ?? ''} is taken`));
        if (invitation) {
            io.out(`added ${options.role} ${login}; the one-time invitation link (valid ${expires} days):\n`);
            io.out(`${invitationLink(publicUrl(options.publicUrl), invitation.token)}\n`);
        } else io.out(`added ${options.role} ${login} with the password given on stdin\n`);
    });
}

async function importRoster(
    io: LabIo,
    file: string,
    options: { course?: string; out?: string; publicUrl?: string; expiresDays: string; dataDir?: string },
): Promise<void> {
    const expires = days(options.expiresDays);
    const text = await readFile(path.resolve(io.cwd, file), 'utf8').catch((e: Error) => {
        throw new LabCliError(`cannot read the roster ${file}: ${e.message}`);
    });
    let entries: RosterEntry[];
    try {
        entries = parseRoster(text);
    } catch (e) {
        if (e instanceof RosterError) throw new LabCliError(`${file}: ${e.message}\nnothing was imported`);
        throw e;
    }
    await withStore(io, options.dataDir, async (store) => {
        const course = await courseId(store, options.course);
        const taken = await takenInStore(store, entries);
        if (taken.length > 0) throw new LabCliError(`${file}: ${taken.join('\n')}\nnothing was imported`);
        const prepared = entries.map(({ user }) => ({ user, invitation: newInvitation(expires) }));
        await store
            .importUsers(
                prepared.map(({ user, invitation }) => ({ user, invitation: { id: invitation.id, expiresAt: invitation.expiresAt } })),
                course,
            )
            .catch(conflict(`${file}: a login or e-mail was taken while importing; nothing was imported`));
        const base = publicUrl(options.publicUrl);
        const rows = prepared.map(({ user, invitation }) => [
            user.login,
            user.name,
            user.email ?? '',
            invitationLink(base, invitation.token),
        ]);
        const csv = `login,name,email,link\n${rows.map((r) => r.map(csvField).join(',')).join('\n')}\n`;
        const where = options.course ? ` into ${options.course}` : '';
        if (options.out) {
            await writeFile(path.resolve(io.cwd, options.out), csv, { mode: 0o600 });
            io.out(
                `imported ${entries.length} users${where}; their one-time invitation links (valid ${expires} days) are in ${options.out}\n`,
            );
        } else {
            io.out(`imported ${entries.length} users${where}; their one-time invitation links (valid ${expires} days):\n${csv}`);
        }
    });
}

/** The rows whose login or e-mail a user in the store has already, with their lines. */
async function takenInStore(store: LabStore, entries: RosterEntry[]): Promise<string[]> {
    const taken: string[] = [];
    for (const { line, user } of entries) {
        if (await store.findUserByLogin(user.login)) taken.push(`line ${line}: the login ${user.login} exists already`);
        if (user.email && (await store.findUserByEmail(user.email)))
            taken.push(`line ${line}: the e-mail ${user.email} belongs to a user already`);
    }
    return taken;
}

function csvField(value: string): string {
    return /[",\n\r]/.test(value) ? `"${value.replace(/"/g, '""')}"` : value;
}

function publicUrl(given: string | undefined): string {
    const url = given ?? `http://127.0.0.1:${DEFAULT_PORT}`;
    try {
        new URL(url);
    } catch {
        throw new LabCliError(`--public-url is not a URL: ${url}`);
    }
    return url;
}

function conflict(message: string): (e: unknown) => never {
    return (e) => {
        if (e instanceof StorageConflictError) throw new LabCliError(message);
        throw e;
    };
}
