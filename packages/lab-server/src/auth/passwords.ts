// Password hashing with Argon2id (@node-rs/argon2, the library's defaults: 19 MiB memory, 2
// passes, OWASP's recommendation). Only the encoded hash is stored; a password is never logged.
import { hash, verify } from '@node-rs/argon2';

export const MIN_PASSWORD_LENGTH = 10;
/** Longer inputs are refused before hashing (a megabyte "password" would only cost CPU). */
export const MAX_PASSWORD_LENGTH = 1024;

/** Why a new password cannot be used, or undefined when it can. */
export function passwordProblem(password: string): string | undefined {
    if (password.length < MIN_PASSWORD_LENGTH) return `the password must have at least ${MIN_PASSWORD_LENGTH} characters`;
    if (password.length > MAX_PASSWORD_LENGTH) return `the password may have at most ${MAX_PASSWORD_LENGTH} characters`;
    if (password.trim() !== password) return 'the password may not start or end with blanks';
    return undefined;
}

export function hashPassword(password: string): Promise<string> {
    return hash(password);
}

/** A hash of a random password, verified against when the login is unknown, so both cases take as long. */
let decoy: Promise<string> | undefined;

/** Whether `password` matches the stored hash; with no hash (unknown user, SSO-only) false after the same work. */
export async function verifyPassword(storedHash: string | null | undefined, password: string): Promise<boolean> {
    if (password.length > MAX_PASSWORD_LENGTH) return false;
    if (!storedHash) {
        decoy ??= hash(`decoy-${Math.random()}`);
        await verify(await decoy, password).catch(() => false);
        return false;
    }
    try {
        return await verify(storedHash, password);
    } catch {
        return false; // a malformed stored hash opens nothing
    }
}
