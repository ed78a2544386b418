import { readFile } from 'node:fs/promises';
import type { appAst } from '@maa/generator-core';
import type { AppInfo } from '@maa/protocol';
import { HttpError } from './http-util.js';
import { walkTree } from './walk.js';
import { isSkippedName, type Workspace } from './workspace.js';

export type { AppInfo, AppPlatformInfo } from '@maa/protocol';

type Parse = (text: string, file: string) => appAst.ArcAppModel;

let parser: Promise<Parse> | undefined;

/** The family's `.arcapp` parser (loaded on first use; parsing needs no linking or registry). */
function arcappParser(): Promise<Parse> {
    parser ??= (async () => {
        const [{ createMaaServices }, { NodeFileSystem }, { URI }] = await Promise.all([
            import('@maa/language-server'),
            import('langium/node'),
            import('langium'),
        ]);
        const services = createMaaServices(NodeFileSystem);
        return (text: string, file: string) =>
            services.shared.workspace.LangiumDocumentFactory.fromString<appAst.ArcAppModel>(text, URI.file(file)).parseResult.value;
    })();
    return parser;
}

/** `ros2.Components` → `ros2`; the most common family of a platform's generators wins. */
export function platformKind(generators: readonly string[]): string {
    const counts = new Map<string, number>();
    for (const g of generators) {
        const family = g.split('.')[0] ?? g;
        counts.set(family, (counts.get(family) ?? 0) + 1);
    }
    let best = '';
    let bestCount = 0;
    for (const [family, count] of counts) {
        if (count > bestCount) [best, bestCount] = [family, count];
    }
    return best;
}

/** Parses one `.arcapp` (its application, or undefined when the file declares none). */
export async function readApp(workspace: Workspace, rel: string): Promise<AppInfo | undefined> {
    const abs = await workspace.confined.resolve(rel, 'app');
    let text: string;
    try {
        text = await readFile(abs, 'utf8');
    } catch {
        throw new HttpError(404, `not found: ${rel}`);
    }
    const app = (await arcappParser())(text, abs).application;
    if (!app) return undefined;
    return {
        path: rel,
        name: app.name,
        component: app.component.$refText,
        platforms: app.platforms.map((p) => {
            const generators = p.generators.map((g) => g.generator.$refText);
            return { name: p.name, kind: platformKind(generators), generators };
        }),
    };
}

/** Every application configuration of the workspace, sorted by path. */
export async function listApps(workspace: Workspace): Promise<AppInfo[]> {
    const files: string[] = [];
    for await (const { dirent, rel } of walkTree(workspace.root, ({ dirent }) => !isSkippedName(dirent.name))) {
        if (dirent.isFile() && dirent.name.endsWith('.arcapp') && !isSkippedName(dirent.name)) files.push(rel);
    }
    files.sort();
    const apps: AppInfo[] = [];
    for (const f of files) {
        const app = await readApp(workspace, f);
        if (app) apps.push(app);
    }
    return apps;
}
