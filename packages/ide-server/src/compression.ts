import type { Stats } from 'node:fs';
import { readFile, stat } from 'node:fs/promises';
import path from 'node:path';
import { promisify } from 'node:util';
import { brotliCompress, constants, gzip } from 'node:zlib';

/** The content encodings the app is served with, in order of preference. */
export type Encoding = 'br' | 'gzip';

/** Text-like files worth compressing (images and woff fonts are compressed already). */
const COMPRESSIBLE = new Set(['.html', '.js', '.mjs', '.cjs', '.css', '.json', '.map', '.svg', '.wasm', '.txt', '.xml', '.ttf', '.otf']);
/** Below this size the headers cost about what compression saves. */
const MIN_BYTES = 1024;
/** The file extension of a precompressed copy written by the app's build (packages/ide-web/vite.config.ts). */
export const PRECOMPRESSED: Record<Encoding, string> = { br: '.br', gzip: '.gz' };

const brotli = promisify(brotliCompress);
const gzipAsync = promisify(gzip);

/**
 * The encoding to answer with, from the request's Accept-Encoding: brotli before gzip, neither
 * when the client refuses it (`;q=0`) or does not name it; `undefined` answers uncompressed.
 */
export function chooseEncoding(header: string | string[] | undefined): Encoding | undefined {
    const accepted = new Map<string, number>();
    for (const part of (Array.isArray(header) ? header.join(',') : (header ?? '')).split(',')) {
        const [name, ...params] = part.trim().toLowerCase().split(';');
        if (!name) continue;
        const q = params.map((p) => /^\s*q=([0-9.]+)\s*$/.exec(p)?.[1]).find((v) => v !== undefined);
        accepted.set(name, q === undefined ? 1 : Number(q));
    }
    const weight = (name: Encoding) => accepted.get(name) ?? (accepted.has('*') ? (accepted.get('*') ?? 0) : 0);
    if (weight('br') > 0) return 'br';
    if (weight('gzip') > 0) return 'gzip';
    return undefined;
}

/** Whether a file of this name and size is served compressed to a client that accepts it. */
export function compressible(file: string, size: number): boolean {
    return size >= MIN_BYTES && COMPRESSIBLE.has(path.extname(file).toLowerCase());
}

/** A compressed representation: a precompressed file beside the original, or bytes compressed here. */
export type Compressed = { file: string; size: number } | { body: Buffer };

/**
 * Compressed copies of the app's files: the build's precompressed `.br`/`.gz` beside a file when
 * it is at least as new as the file, else compressed on the fly off the main thread (zlib's
 * thread pool) and kept in memory (bounded; concurrent requests share one compression).
 */
export class CompressedFiles {
    private readonly cache = new Map<string, Promise<Buffer>>();
    private readonly sizes = new Map<string, number>();
    private cachedBytes = 0;

    constructor(private readonly maxBytes = 64 * 1024 * 1024) {}

    /** @param confined whether a precompressed copy may be served (symlinks must not lead out of the app) */
    async get(file: string, info: Stats, encoding: Encoding, confined: (file: string) => Promise<boolean>): Promise<Compressed> {
        const pre = `${file}${PRECOMPRESSED[encoding]}`;
        const preInfo = await stat(pre).catch(() => undefined);
        if (preInfo?.isFile() && preInfo.mtimeMs >= info.mtimeMs && (await confined(pre))) return { file: pre, size: preInfo.size };
        const key = `${encoding}:${file}:${info.size}:${info.mtimeMs}`;
        let body = this.cache.get(key);
        if (!body) {
            body = this.compress(file, encoding);
            this.cache.set(key, body);
            body.then(
                (b) => this.account(key, b.length),
                () => this.cache.delete(key),
            );
        }
        return { body: await body };
    }

    private async compress(file: string, encoding: Encoding): Promise<Buffer> {
        const raw = await readFile(file);
        return encoding === 'br'
            ? brotli(raw, {
                  params: {
                      // quality 5: most of brotli's gain at a fraction of the time of 11 (the build precompresses at 11)
                      [constants.BROTLI_PARAM_QUALITY]: 5,
                      [constants.BROTLI_PARAM_MODE]: constants.BROTLI_MODE_TEXT,
                      [constants.BROTLI_PARAM_SIZE_HINT]: raw.length,
                  },
              })
            : gzipAsync(raw, { level: 6 });
    }

    /** Keeps the cache under its bound: the oldest entries go first. */
    private account(key: string, size: number): void {
        if (!this.cache.has(key)) return;
        this.sizes.set(key, size);
        this.cachedBytes += size;
        for (const old of this.cache.keys()) {
            if (this.cachedBytes <= this.maxBytes || old === key) break;
            this.cachedBytes -= this.sizes.get(old) ?? 0;
            this.sizes.delete(old);
            this.cache.delete(old);
        }
    }
}
