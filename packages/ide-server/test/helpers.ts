import { request } from 'node:http';
import { cpSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startIdeServer, type IdeServer, type IdeServerOptions } from '../src/index.js';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', '..');

export interface TestSite {
  /** The temporary folder: the workspace is `ws/` inside, generated output `.maa-ide-out/`. */
  dir: string;
  workspace: string;
  server: IdeServer;
  url(pathAndQuery: string): string;
  dispose(): Promise<void>;
}

/** A workspace in a fresh temporary folder (a copy of examples/ unless `empty`) and a backend on a free port. */
export async function startSite(options: { empty?: boolean } & Partial<IdeServerOptions> = {}): Promise<TestSite> {
  const dir = mkdtempSync(path.join(tmpdir(), 'maa-ide-test-'));
  const workspace = path.join(dir, 'ws');
  if (options.empty) mkdirSync(workspace);
  else cpSync(path.join(repo, 'examples'), workspace, { recursive: true });
  const server = await startIdeServer({ appDir: path.join(dir, 'no-app'), ...options, workspace, port: 0 });
  const site: TestSite = {
    dir,
    workspace,
    server,
    url: (p) => new URL(p, site.server.url).toString(),
    async dispose() {
      await site.server.close();
      rmSync(dir, { recursive: true, force: true });
    },
  };
  return site;
}

/** The query string `path=...` with the value encoded as given (so `%2e%2e` stays literal). */
export function q(params: Record<string, string>): string {
  return Object.entries(params)
    .map(([k, v]) => `${k}=${encodeURIComponent(v)}`)
    .join('&');
}

export async function json<T = Record<string, unknown>>(response: Response): Promise<T> {
  return (await response.json()) as T;
}

/** A GET with the path sent byte for byte (fetch would normalize `%2e%2e` segments away). */
export function rawGet(base: string, rawPath: string): Promise<{ status: number; body: string }> {
  return new Promise((resolve, reject) => {
    const req = request(base, { path: rawPath, method: 'GET' }, (res) => {
      let body = '';
      res.setEncoding('utf8');
      res.on('data', (c: string) => (body += c));
      res.on('end', () => resolve({ status: res.statusCode ?? 0, body }));
    });
    req.on('error', reject);
    req.end();
  });
}
