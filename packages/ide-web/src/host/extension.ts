/**
 * The MontiArc extension as the host's workbench loads it: its manifest and files as built by
 * `packages/vscode-extension/bin/build.mjs --web` into `maa-extension/` next to index.html (see
 * vite.config.ts), registered in VS Code's extension service (the local extension host runs
 * its `browser` entry, activated by the manifest's activation events like in VS Code).
 */
import type { IExtensionManifest } from '@codingame/monaco-vscode-api/extensions';

/** The folder of the built extension, relative to the page. */
export const EXTENSION_DIR = 'maa-extension/';

/** The file listing the build writes next to the manifest (vite.config.ts): every file of the extension, `/`-separated. */
export const FILE_LIST = 'files.json';

/** The extension's files as the workbench registers them: relative paths, without the manifest and the listing itself. */
export function extensionFiles(listing: unknown): string[] {
    if (!Array.isArray(listing)) throw new Error(`${EXTENSION_DIR}${FILE_LIST} is not a list of files`);
    return listing.filter(
        (f): f is string =>
            typeof f === 'string' && f !== 'package.json' && f !== FILE_LIST && !f.startsWith('/') && !f.split('/').includes('..'),
    );
}

/** The extension as the workbench registers it: its manifest and a URL for each of its files. */
export interface LoadedExtension {
    manifest: IExtensionManifest;
    files: Map<string, URL>;
}

/** Fetches the built extension's manifest and file listing. */
export async function loadExtension(base: URL): Promise<LoadedExtension> {
    const dir = new URL(EXTENSION_DIR, base);
    const [manifest, listing] = await Promise.all([json(new URL('package.json', dir)), json(new URL(FILE_LIST, dir))]);
    const files = new Map<string, URL>();
    for (const file of extensionFiles(listing)) files.set(file, new URL(file, dir));
    return { manifest: manifest as IExtensionManifest, files };
}

async function json(url: URL): Promise<unknown> {
    const response = await fetch(url);
    if (!response.ok)
        throw new Error(
            `the MontiArc extension is not built into ${url.pathname} (${response.status}); run "npm run build -w @maa/ide-web"`,
        );
    return response.json();
}
