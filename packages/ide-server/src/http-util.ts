import type { IncomingMessage, ServerResponse } from 'node:http';
import { formatIssues, type Contract, type Static, type TSchema } from '@maa/protocol';

/** An error answered as `{"error": message}` with its HTTP status. */
export class HttpError extends Error {
    constructor(
        readonly status: number,
        message: string,
        readonly extra?: Record<string, unknown>,
    ) {
        super(message);
        this.name = 'HttpError';
    }
}

export function sendJson(res: ServerResponse, status: number, body: unknown): void {
    const text = JSON.stringify(body);
    res.writeHead(status, {
        'Content-Type': 'application/json; charset=utf-8',
        'Content-Length': Buffer.byteLength(text),
        'Cache-Control': 'no-store',
    });
    res.end(text);
}

export function sendText(res: ServerResponse, status: number, text: string, contentType = 'text/plain; charset=utf-8'): void {
    res.writeHead(status, { 'Content-Type': contentType, 'Content-Length': Buffer.byteLength(text), 'Cache-Control': 'no-store' });
    res.end(text);
}

/** Turns texts sent to clients into ones without absolute paths (see PathRedactor). */
export interface Redact {
    value<T>(value: T): T;
}

/**
 * Answers an error; anything that is not an HttpError is a bug of ours (500): the client learns
 * only which request failed, the details (with paths and stack) go to maa-ide's stderr.
 */
export function sendError(res: ServerResponse, error: unknown, redact?: Redact, what = 'the request'): void {
    if (!(error instanceof HttpError)) console.error(`maa-ide: internal error in ${what}:`, error);
    if (res.headersSent) {
        res.destroy();
        return;
    }
    if (error instanceof HttpError) {
        const body = { error: error.message, ...error.extra };
        sendJson(res, error.status, redact ? redact.value(body) : body);
        return;
    }
    sendJson(res, 500, { error: `internal error in ${what} (details are in maa-ide's log)` });
}

/** Reads the request body, refusing (413) more than `limit` bytes. */
export async function readBody(req: IncomingMessage, limit: number): Promise<Buffer> {
    const declared = Number(req.headers['content-length']);
    if (Number.isFinite(declared) && declared > limit) {
        // Drain nothing: answering 413 and closing is cheaper than reading megabytes we refuse.
        req.resume();
        throw new HttpError(413, `request body too large (${declared} bytes; the limit is ${limit})`);
    }
    const chunks: Buffer[] = [];
    let size = 0;
    for await (const chunk of req) {
        const buffer = chunk as Buffer;
        size += buffer.length;
        if (size > limit) {
            req.resume();
            throw new HttpError(413, `request body too large (more than ${limit} bytes)`);
        }
        chunks.push(buffer);
    }
    return Buffer.concat(chunks);
}

/** Reads a JSON object body (400 for anything else). */
export async function readJsonObject(req: IncomingMessage, limit = 1024 * 1024): Promise<Record<string, unknown>> {
    const text = (await readBody(req, limit)).toString('utf8');
    let value: unknown;
    try {
        value = JSON.parse(text);
    } catch (e) {
        throw new HttpError(400, `the request body is not valid JSON: ${(e as Error).message}`);
    }
    if (typeof value !== 'object' || value === null || Array.isArray(value))
        throw new HttpError(400, 'the request body must be a JSON object');
    return value as Record<string, unknown>;
}

/** Reads a JSON body that must keep a request contract of @maa/protocol (400 naming the bad fields). */
export async function readRequest<T extends TSchema>(req: IncomingMessage, request: Contract<T>): Promise<Static<T>> {
    const body = await readJsonObject(req);
    const issues = request.issues(body);
    if (issues.length > 0) throw new HttpError(400, `invalid ${request.name}: ${formatIssues(issues)}`);
    return body as Static<T>;
}

export function requireString(body: Record<string, unknown>, field: string): string {
    const value = body[field];
    if (typeof value !== 'string' || value === '') throw new HttpError(400, `missing or empty string field '${field}'`);
    return value;
}

export function requireQuery(query: URLSearchParams, name: string): string {
    const value = query.get(name);
    if (value === null || value === '') throw new HttpError(400, `missing query parameter '${name}'`);
    return value;
}
