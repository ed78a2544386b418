/**
 * The platform quick pick of **MontiArc: Generate**: the platforms the workspace's application
 * configurations (`.arcapp`) declare. A small scanner over the text (comments and strings
 * skipped) rather than the language server: the quick pick needs only names, and it must work
 * while a model has errors elsewhere.
 */

export interface PlatformItem {
    /** The platform name (`timesync`). */
    readonly label: string;
    /** The application and its file (`TR — examples/toast-service/TR.arcapp`). */
    readonly description: string;
    readonly appFile: string;
    readonly application: string;
    readonly platform: string;
}

/** The text without comments and string contents (kept as blanks so positions stay). */
function code(text: string): string {
    return text.replace(/\/\*[\s\S]*?\*\/|\/\/[^\n]*|"(?:\\.|[^"\\])*"/g, (m) => m.replace(/[^\n]/g, ' '));
}

/** The application name and its platforms, in order, of one `.arcapp` text; undefined when it declares no application. */
export function platformsOf(text: string): { application: string; platforms: string[] } | undefined {
    const src = code(text);
    const app = /(?<![\w$])application\s+([A-Za-z_$][\w$]*)/.exec(src);
    if (!app?.[1]) return undefined;
    const platforms: string[] = [];
    for (const m of src.matchAll(/(?<![\w$.])platform\s+([A-Za-z_$][\w$]*)\s*\{/g)) {
        if (m[1] && !platforms.includes(m[1])) platforms.push(m[1]);
    }
    return { application: app[1], platforms };
}

/** The quick pick items of every platform of every application configuration (`files`: path → text), sorted by file. */
export function platformItems(files: ReadonlyArray<{ file: string; displayPath: string; text: string }>): PlatformItem[] {
    const items: PlatformItem[] = [];
    for (const f of [...files].sort((a, b) => a.displayPath.localeCompare(b.displayPath))) {
        const app = platformsOf(f.text);
        if (!app) continue;
        for (const platform of app.platforms) {
            items.push({
                label: platform,
                description: `${app.application} — ${f.displayPath}`,
                appFile: f.file,
                application: app.application,
                platform,
            });
        }
    }
    return items;
}
