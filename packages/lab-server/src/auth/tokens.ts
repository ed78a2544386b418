// Secrets the lab hands out (session cookies, CSRF tokens, invitation links) and the hashes it
// keeps of them: the database holds only SHA-256 hashes, so a copy of it opens no session.
import { createHash, randomBytes } from 'node:crypto';

/** A fresh secret: 32 random bytes, base64url (URL- and cookie-safe). */
export function newSecret(): string {
    return randomBytes(32).toString('base64url');
}

/** The hash under which a secret is stored (hex SHA-256). */
export function secretHash(secret: string): string {
    return createHash('sha256').update(secret).digest('hex');
}

/** Whether a string looks like a secret newSecret made (anything else is refused before a lookup). */
export function isSecretSyntax(value: string): boolean {
    return /^[A-Za-z0-9_-]{43}$/.test(value);
}
