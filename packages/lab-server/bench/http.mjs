// The lab bench's HTTP client: node:http with a keep-alive agent, a session cookie and the CSRF
// token per simulated user, and the time of every request.
import { Agent, request } from 'node:http';
import { performance } from 'node:perf_hooks';

export class BenchClient {
    /** @param base the lab's URL; @param record (kind, ms, ok, status, text) for each request */
    constructor(base, record = () => undefined) {
        this.base = base;
        this.record = record;
        this.cookie = undefined;
        this.csrf = undefined;
        this.agent = new Agent({ keepAlive: true, maxSockets: 2 });
    }

    /** One request; resolves {status, headers, text, json} (never rejects: a network error is status 0). */
    async send(kind, method, path, body, extraHeaders = {}) {
        const started = performance.now();
        const payload = body === undefined ? undefined : typeof body === 'string' ? body : JSON.stringify(body);
        const headers = {};
        if (payload !== undefined) headers['Content-Type'] = typeof body === 'string' ? 'text/plain; charset=utf-8' : 'application/json';
        if (this.cookie) headers.Cookie = this.cookie;
        if (this.csrf && method !== 'GET') headers['X-CSRF-Token'] = this.csrf;
        Object.assign(headers, extraHeaders);
        const answer = await new Promise((resolve) => {
            const req = request(new URL(path, this.base), { method, headers, agent: this.agent }, (res) => {
                const chunks = [];
                res.on('data', (c) => chunks.push(c));
                res.on('end', () =>
                    resolve({ status: res.statusCode ?? 0, headers: res.headers, text: Buffer.concat(chunks).toString('utf8') }),
                );
                res.on('error', (e) => resolve({ status: 0, headers: {}, text: String(e) }));
            });
            req.on('error', (e) => resolve({ status: 0, headers: {}, text: String(e) }));
            req.end(payload);
        });
        const ms = performance.now() - started;
        let json;
        try {
            json = JSON.parse(answer.text);
        } catch {
            json = undefined;
        }
        const ok = answer.status >= 200 && answer.status < 400;
        if (kind) this.record(kind, ms, ok, answer.status, answer.text);
        for (const c of answer.headers['set-cookie'] ?? []) {
            const pair = c.split(';')[0] ?? '';
            if (/session/.test(pair.slice(0, pair.indexOf('=')))) this.cookie = pair;
        }
        if (typeof json?.csrfToken === 'string') this.csrf = json.csrfToken;
        return { status: answer.status, headers: answer.headers, text: answer.text, json };
    }

    /** POST /api/login; throws unless it succeeded. */
    async login(login, password) {
        const a = await this.send('login', 'POST', '/api/login', { login, password });
        if (a.status !== 200 || !this.cookie || !this.csrf) throw new Error(`login of ${login} failed: ${a.status} ${a.text}`);
    }

    close() {
        this.agent.destroy();
    }
}
