// A limit that was hit: 429 (try again later: when it frees is in Retry-After and the answer) or
// 413 (too large: free space first). The answer names the limit, its value and what was asked.
import { HttpError } from '@maa/ide-server/http';

export function tooMany(limit: string, value: number, message: string, freesAt: Date): HttpError {
    const retryAfter = Math.max(1, Math.ceil((freesAt.getTime() - Date.now()) / 1000));
    return new HttpError(429, message, { limit, value, freesAt: freesAt.toISOString(), retryAfterSeconds: retryAfter });
}

export function tooLarge(limit: string, value: number, message: string): HttpError {
    return new HttpError(413, message, { limit, value });
}
