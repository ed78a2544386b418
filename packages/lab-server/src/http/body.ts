// Request bodies of the lab's API: JSON only (a cross-site form cannot send it without a CORS
// preflight, which the lab never grants), bounded in size (413), fields checked (400).
import type { IncomingMessage } from 'node:http';
import { HttpError, readJsonObject } from '@maa/ide-server/http';
import type { User } from '../storage/index.js';

/** The default limit of a request body (a workspace file travels in one: see the quotas). */
export const DEFAULT_BODY_LIMIT = 1024 * 1024;

/** Reads a JSON object body; 415 when it is not declared as JSON, 413 past `limit` bytes. */
export function readJson(req: IncomingMessage, limit = DEFAULT_BODY_LIMIT): Promise<Record<string, unknown>> {
    const type = (req.headers['content-type'] ?? '').split(';')[0]?.trim().toLowerCase();
    if (type !== 'application/json') throw new HttpError(415, 'the request body must be JSON (Content-Type: application/json)');
    return readJsonObject(req, limit);
}

/** A string field of a body (400 when missing, empty or too long). */
export function stringField(body: Record<string, unknown>, field: string, maxLength = 1024): string {
    const value = body[field];
    if (typeof value !== 'string' || value === '') throw new HttpError(400, `missing or empty string field '${field}'`);
    if (value.length > maxLength) throw new HttpError(400, `the field '${field}' is longer than ${maxLength} characters`);
    return value;
}

/** What the API shows of a user (never the password hash). */
export function userView(user: User): { id: number; login: string; name: string; email: string | null; role: User['role'] } {
    return { id: user.id, login: user.login, name: user.name, email: user.email, role: user.role };
}
