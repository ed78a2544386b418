import { mkdirSync, utimesSync, writeFileSync } from 'node:fs';
import { get } from 'node:http';
import path from 'node:path';
import { brotliDecompressSync, gunzipSync, gzipSync } from 'node:zlib';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { chooseEncoding } from '../src/compression.js';
import { BEARER, startSite, TEST_TOKEN, type TestSite } from './helpers.js';

interface Raw {
    status: number;
    headers: Record<string, string | string[] | undefined>;
    body: Buffer;
}

/** A GET whose body arrives as sent (fetch would decode it). */
function rawBody(url: string, headers: Record<string, string> = {}): Promise<Raw> {
    return new Promise((resolve, reject) => {
        get(url, { headers: { ...BEARER, ...headers } }, (res) => {
            const chunks: Buffer[] = [];
            res.on('data', (c: Buffer) => chunks.push(c));
            res.on('end', () => resolve({ status: res.statusCode ?? 0, headers: res.headers, body: Buffer.concat(chunks) }));
        }).on('error', reject);
    });
}

describe('the app served compressed (issue 18)', () => {
    let site: TestSite;
    const script = `export const words = ${JSON.stringify(Array.from({ length: 400 }, (_, i) => `word${i}`))};\n`;
    const decoded = (res: Raw) => {
        const encoding = res.headers['content-encoding'];
        if (encoding === 'br') return brotliDecompressSync(res.body).toString();
        if (encoding === 'gzip') return gunzipSync(res.body).toString();
        return res.body.toString();
    };

    beforeAll(async () => {
        site = await startSite({ empty: true });
        const app = path.join(site.dir, 'app');
        mkdirSync(path.join(app, 'assets'), { recursive: true });
        writeFileSync(path.join(app, 'index.html'), `<!doctype html><title>MAA</title>${'<!-- padding -->'.repeat(100)}`);
        writeFileSync(path.join(app, 'assets', 'main-abc.js'), script);
        writeFileSync(path.join(app, 'assets', 'tiny-abc.js'), 'export {};');
        writeFileSync(path.join(app, 'assets', 'picture.png'), Buffer.alloc(4096, 7));
        // A precompressed copy from the build: served as it is (its content tells it apart).
        writeFileSync(path.join(app, 'assets', 'pre-abc.js'), script);
        writeFileSync(path.join(app, 'assets', 'pre-abc.js.gz'), gzipSync('// the precompressed copy\n'));
        // A stale precompressed copy (older than its file) is ignored.
        writeFileSync(path.join(app, 'assets', 'stale-abc.js'), script);
        writeFileSync(path.join(app, 'assets', 'stale-abc.js.gz'), gzipSync('// stale\n'));
        const past = new Date(Date.now() - 60_000);
        utimesSync(path.join(app, 'assets', 'stale-abc.js.gz'), past, past);
        await site.server.close();
        const { startIdeServer } = await import('../src/index.js');
        site.server = await startIdeServer({ workspace: site.workspace, port: 0, token: TEST_TOKEN, appDir: app });
    });
    afterAll(() => site.dispose());

    it('picks brotli before gzip, honours q=0, and answers uncompressed to clients that name neither', () => {
        expect(chooseEncoding('gzip, deflate, br')).toBe('br');
        expect(chooseEncoding('gzip, deflate')).toBe('gzip');
        expect(chooseEncoding('br;q=0, gzip;q=0.5')).toBe('gzip');
        expect(chooseEncoding('*')).toBe('br');
        expect(chooseEncoding('*, br;q=0')).toBe('gzip');
        expect(chooseEncoding('identity')).toBeUndefined();
        expect(chooseEncoding(undefined)).toBeUndefined();
        expect(chooseEncoding('')).toBeUndefined();
    });

    it.each([
        ['gzip, deflate, br', 'br'],
        ['gzip, deflate', 'gzip'],
        ['identity', undefined],
    ])('Accept-Encoding "%s": the script comes as %s, the same bytes once decoded, its length and Vary set', async (accept, encoding) => {
        const res = await rawBody(site.url('/assets/main-abc.js'), { 'accept-encoding': accept });
        expect(res.status).toBe(200);
        expect(res.headers['content-encoding']).toBe(encoding);
        expect(res.headers['vary']).toBe('Accept-Encoding');
        expect(Number(res.headers['content-length'])).toBe(res.body.length);
        expect(decoded(res)).toBe(script);
        if (encoding) expect(res.body.length).toBeLessThan(script.length / 2);
        expect(res.headers['cache-control']).toContain('immutable');
    });

    it('gives each encoding its own ETag: a revalidation answers 304 for the same encoding only', async () => {
        const br = await rawBody(site.url('/'), { 'accept-encoding': 'br' });
        const gz = await rawBody(site.url('/'), { 'accept-encoding': 'gzip' });
        expect(br.headers['content-encoding']).toBe('br');
        expect(br.headers['cache-control']).toBe('no-cache');
        expect(br.headers.etag).not.toBe(gz.headers.etag);
        const again = await rawBody(site.url('/'), { 'accept-encoding': 'br', 'if-none-match': String(br.headers.etag) });
        expect(again.status).toBe(304);
        const other = await rawBody(site.url('/'), { 'accept-encoding': 'gzip', 'if-none-match': String(br.headers.etag) });
        expect(other.status).toBe(200);
        expect(decoded(other)).toContain('<title>MAA</title>');
    });

    it('serves small files and pictures as they are', async () => {
        const tiny = await rawBody(site.url('/assets/tiny-abc.js'), { 'accept-encoding': 'gzip, br' });
        expect(tiny.headers['content-encoding']).toBeUndefined();
        expect(tiny.body.toString()).toBe('export {};');
        const png = await rawBody(site.url('/assets/picture.png'), { 'accept-encoding': 'gzip, br' });
        expect(png.headers['content-encoding']).toBeUndefined();
        expect(png.body.length).toBe(4096);
    });

    it("serves the build's precompressed copy when it is at least as new as its file, not a stale one", async () => {
        const pre = await rawBody(site.url('/assets/pre-abc.js'), { 'accept-encoding': 'gzip' });
        expect(pre.headers['content-encoding']).toBe('gzip');
        expect(decoded(pre)).toBe('// the precompressed copy\n');
        const stale = await rawBody(site.url('/assets/stale-abc.js'), { 'accept-encoding': 'gzip' });
        expect(decoded(stale)).toBe(script);
        // no brotli copy beside it: compressed here
        const br = await rawBody(site.url('/assets/pre-abc.js'), { 'accept-encoding': 'br' });
        expect(decoded(br)).toBe(script);
    });
});
