// Roster CSV (docs/lab.md "Roster"): a header row, then one user per row with the columns
// `name`, `email` (or `e-mail`), `login` and `role` (`student` when empty). A row needs a login
// or an e-mail (the login is then the e-mail). Every problem is reported with its line number,
// and a roster with any problem imports nothing.
import { parse } from 'csv-parse/sync';
import type { NewUser, Role } from '../storage/index.js';

export interface RosterEntry {
    /** the line of the file the row starts on */
    line: number;
    user: NewUser;
}

export class RosterError extends Error {
    constructor(readonly problems: string[]) {
        super(`the roster has ${problems.length} problem${problems.length === 1 ? '' : 's'}:\n${problems.map((p) => `  ${p}`).join('\n')}`);
        this.name = 'RosterError';
    }
}

const LOGIN_SYNTAX = /^[A-Za-z0-9][A-Za-z0-9._@+-]{0,63}$/;
const EMAIL_SYNTAX = /^[^\s@,;<>"]+@[^\s@,;<>"]+\.[^\s@,;<>"]+$/;
const COLUMNS: Record<string, keyof Row> = { name: 'name', email: 'email', 'e-mail': 'email', mail: 'email', login: 'login', role: 'role' };

interface Row {
    name: string;
    email: string;
    login: string;
    role: string;
}

/** Parses and checks a roster; throws a RosterError listing every problem (with line numbers). */
export function parseRoster(text: string): RosterEntry[] {
    let records: Array<{ record: string[]; info: { lines: number } }>;
    try {
        // With `info: true` csv-parse returns { record, info } per row; its types do not follow the option.
        records = parse(text, { bom: true, info: true, skip_empty_lines: true, trim: true }) as unknown as typeof records;
    } catch (e) {
        const err = e as Error & { lines?: number };
        throw new RosterError([`line ${err.lines ?? '?'}: ${err.message.replace(/^Invalid Record Length: /, '')}`]);
    }
    const [header, ...rows] = records;
    if (!header) throw new RosterError(['the file is empty (expected a header row: name,email,login,role)']);
    const columns = headerColumns(header.record, header.info.lines);
    const problems: string[] = [];
    const entries: RosterEntry[] = [];
    const seen = new Map<string, number>();
    for (const { record, info } of rows) {
        const row: Row = { name: '', email: '', login: '', role: '' };
        columns.forEach((column, i) => {
            if (column) row[column] = record[i] ?? '';
        });
        const entry = checkRow(row, info.lines, problems);
        if (!entry) continue;
        for (const key of new Set([entry.user.login.toLowerCase(), entry.user.email?.toLowerCase()])) {
            if (!key) continue;
            const first = seen.get(key);
            if (first !== undefined) problems.push(`line ${info.lines}: ${key} is already on line ${first}`);
            else seen.set(key, info.lines);
        }
        entries.push(entry);
    }
    if (problems.length > 0) throw new RosterError(problems);
    if (entries.length === 0) throw new RosterError(['the roster has a header but no users']);
    return entries;
}

function headerColumns(header: string[], line: number): Array<keyof Row | undefined> {
    const columns = header.map((h) => COLUMNS[h.toLowerCase()]);
    const unknown = header.filter((_, i) => columns[i] === undefined);
    if (unknown.length > 0)
        throw new RosterError([
            `line ${line}: unknown column ${unknown.map((u) => JSON.stringify(u)).join(', ')} (the columns are name, email, login, role)`,
        ]);
    if (!columns.includes('name')) throw new RosterError([`line ${line}: the header has no "name" column`]);
    if (!columns.includes('login') && !columns.includes('email'))
        throw new RosterError([`line ${line}: the header needs a "login" or an "email" column`]);
    return columns;
}

function checkRow(row: Row, line: number, problems: string[]): RosterEntry | undefined {
    const before = problems.length;
    if (row.name === '') problems.push(`line ${line}: the name is empty`);
    if (row.email !== '' && !EMAIL_SYNTAX.test(row.email))
        problems.push(`line ${line}: ${JSON.stringify(row.email)} is not an e-mail address`);
    const login = row.login || row.email;
    if (login === '') problems.push(`line ${line}: the row needs a login or an e-mail`);
    else if (!LOGIN_SYNTAX.test(login))
        problems.push(`line ${line}: the login ${JSON.stringify(login)} may hold only letters, digits and . _ @ + - (at most 64)`);
    const role = (row.role || 'student').toLowerCase();
    if (role !== 'student' && role !== 'instructor')
        problems.push(`line ${line}: the role ${JSON.stringify(row.role)} is neither student nor instructor`);
    if (problems.length > before) return undefined;
    return { line, user: { login, name: row.name, role: role as Role, email: row.email || null } };
}

/** Whether a login is acceptable (the same rule as the roster's, for `maa-lab users add`). */
export function loginProblem(login: string): string | undefined {
    return LOGIN_SYNTAX.test(login)
        ? undefined
        : `the login ${JSON.stringify(login)} may hold only letters, digits and . _ @ + - (at most 64)`;
}
