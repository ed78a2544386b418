import { createReadStream, existsSync } from 'node:fs';
import { realpath, stat } from 'node:fs/promises';
import type { IncomingMessage, ServerResponse } from 'node:http';
import path from 'node:path';
import { chooseEncoding, CompressedFiles, compressible } from './compression.js';
import { sendJson, sendText } from './http-util.js';

const CONTENT_TYPES: Record<string, string> = {
    '.html': 'text/html; charset=utf-8',
    '.js': 'text/javascript; charset=utf-8',
    '.mjs': 'text/javascript; charset=utf-8',
    '.cjs': 'text/javascript; charset=utf-8',
    '.css': 'text/css; charset=utf-8',
    '.json': 'application/json; charset=utf-8',
    '.map': 'application/json; charset=utf-8',
    '.wasm': 'application/wasm',
    '.svg': 'image/svg+xml',
    '.png': 'image/png',
    '.jpg': 'image/jpeg',
    '.jpeg': 'image/jpeg',
    '.gif': 'image/gif',
    '.ico': 'image/x-icon',
    '.webp': 'image/webp',
    '.ttf': 'font/ttf',
    '.otf': 'font/otf',
    '.woff': 'font/woff',
    '.woff2': 'font/woff2',
    '.txt': 'text/plain; charset=utf-8',
    '.xml': 'application/xml; charset=utf-8',
};

export function contentType(file: string): string {
    return CONTENT_TYPES[path.extname(file).toLowerCase()] ?? 'application/octet-stream';
}

/**
 * Serves the built web app. Vite puts content-hashed files under `assets/`, which may be cached
 * for good; everything else (index.html above all) is revalidated by ETag on every load. Text
 * files go out compressed (brotli or gzip, by Accept-Encoding; compression.ts), each encoding
 * with an ETag of its own.
 */
export class StaticApp {
    private readonly compressed = new CompressedFiles();

    /** @param shownDir how the folder is named in answers (no absolute paths in error bodies) */
    constructor(
        readonly dir: string,
        private readonly shownDir = 'the --app-dir folder',
    ) {}

    async handle(req: IncomingMessage, res: ServerResponse, pathname: string): Promise<void> {
        if (req.method !== 'GET' && req.method !== 'HEAD') {
            res.setHeader('Allow', 'GET, HEAD');
            sendJson(res, 405, { error: `method ${req.method} not allowed on ${pathname}` });
            return;
        }
        if (!existsSync(this.dir)) {
            sendText(
                res,
                503,
                `The IDE's web app is not built (${this.shownDir} does not exist). Run "npm run build -w @maa/ide-web" and reload.\n`,
            );
            return;
        }
        let decoded: string;
        try {
            decoded = decodeURIComponent(pathname);
        } catch {
            sendJson(res, 400, { error: `malformed URL: ${pathname}` });
            return;
        }
        const segments = decoded.split('/').filter((s) => s !== '' && s !== '.');
        if (decoded.includes('\0') || decoded.includes('\\') || segments.includes('..')) {
            sendJson(res, 400, { error: `invalid path: ${pathname}` });
            return;
        }
        let file = path.join(this.dir, ...segments);
        let info = await stat(file).catch(() => undefined);
        if (info?.isDirectory()) {
            file = path.join(file, 'index.html');
            info = await stat(file).catch(() => undefined);
        }
        if (!info?.isFile() || !(await this.confined(file))) {
            sendJson(res, 404, { error: `not found: ${pathname}` });
            return;
        }
        const encoding = compressible(file, info.size) ? chooseEncoding(req.headers['accept-encoding']) : undefined;
        const etag = `W/"${info.size.toString(16)}-${Math.floor(info.mtimeMs).toString(16)}${encoding ? `-${encoding}` : ''}"`;
        const immutable = segments[0] === 'assets';
        res.setHeader('ETag', etag);
        res.setHeader('Last-Modified', info.mtime.toUTCString());
        res.setHeader('Cache-Control', immutable ? 'public, max-age=31536000, immutable' : 'no-cache');
        if (compressible(file, info.size)) res.setHeader('Vary', 'Accept-Encoding');
        if (req.headers['if-none-match'] === etag) {
            res.writeHead(304);
            res.end();
            return;
        }
        const body = encoding ? await this.compressed.get(file, info, encoding, (f) => this.confined(f)).catch(() => undefined) : undefined;
        if (encoding && !body) res.setHeader('ETag', etag.replace(`-${encoding}"`, '"')); // served as it is
        const headers: Record<string, string | number> = { 'Content-Type': contentType(file), 'X-Content-Type-Options': 'nosniff' };
        if (body && encoding) headers['Content-Encoding'] = encoding;
        headers['Content-Length'] = !body ? info.size : 'body' in body ? body.body.length : body.size;
        res.writeHead(200, headers);
        if (req.method === 'HEAD') {
            res.end();
            return;
        }
        if (body && 'body' in body) {
            res.end(body.body);
            return;
        }
        createReadStream(body?.file ?? file)
            .on('error', () => res.destroy())
            .pipe(res);
    }

    /** Symlinks inside the app folder must not lead out of it. */
    private async confined(file: string): Promise<boolean> {
        try {
            const [root, real] = await Promise.all([realpath(this.dir), realpath(file)]);
            return real === root || real.startsWith(root + path.sep);
        } catch {
            return false;
        }
    }
}
