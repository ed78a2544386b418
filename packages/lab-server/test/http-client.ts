// A small HTTP client for the lab server tests: node:http (so Host and Origin can be set to
// anything), a cookie jar per client, JSON in and out.
import { request as httpRequest, type IncomingHttpHeaders } from 'node:http';

export interface Answer {
    status: number;
    headers: IncomingHttpHeaders;
    text: string;
    // biome-ignore lint/suspicious/noExplicitAny: test answers are read field by field
    json: any;
}

export interface RequestOptions {
    method?: string;
    body?: unknown;
    /** raw body text (sent as is) */
    raw?: string;
    headers?: Record<string, string>;
}

export class Client {
    readonly cookies = new Map<string, string>();
    /** the CSRF token the last login or /api/me gave */
    csrf: string | undefined;

    constructor(readonly base: string) {}

    async send(path: string, options: RequestOptions = {}): Promise<Answer> {
        const url = new URL(path, this.base);
        const payload = options.raw ?? (options.body === undefined ? undefined : JSON.stringify(options.body));
        const headers: Record<string, string> = {
            ...(payload !== undefined ? { 'Content-Type': 'application/json' } : {}),
            ...(this.cookies.size > 0 ? { Cookie: [...this.cookies].map(([k, v]) => `${k}=${v}`).join('; ') } : {}),
            ...options.headers,
        };
        const answer = await new Promise<Answer>((resolve, reject) => {
            const req = httpRequest(url, { method: options.method ?? (payload === undefined ? 'GET' : 'POST'), headers }, (res) => {
                const chunks: Buffer[] = [];
                res.on('data', (c: Buffer) => chunks.push(c));
                res.on('end', () => {
                    const text = Buffer.concat(chunks).toString('utf8');
                    let json: unknown;
                    try {
                        json = JSON.parse(text);
                    } catch {
                        json = undefined;
                    }
                    resolve({ status: res.statusCode ?? 0, headers: res.headers, text, json });
                });
                res.on('error', reject);
            });
            req.on('error', reject);
            req.end(payload);
        });
        for (const cookie of answer.headers['set-cookie'] ?? []) {
            const [pair] = cookie.split(';');
            const eq = (pair ?? '').indexOf('=');
            const name = (pair ?? '').slice(0, eq);
            const value = (pair ?? '').slice(eq + 1);
            if (value === '' || /Max-Age=0/i.test(cookie)) this.cookies.delete(name);
            else this.cookies.set(name, value);
        }
        if (typeof answer.json?.csrfToken === 'string') this.csrf = answer.json.csrfToken;
        return answer;
    }

    /** A state-changing request with the CSRF token. */
    post(path: string, body: unknown = {}, headers: Record<string, string> = {}): Promise<Answer> {
        return this.send(path, { body, headers: { ...(this.csrf ? { 'X-CSRF-Token': this.csrf } : {}), ...headers } });
    }

    login(login: string, password: string): Promise<Answer> {
        return this.send('/api/login', { body: { login, password } });
    }
}
