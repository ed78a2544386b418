/**
 * The workspace's recordings (docs/ide.md "Record and replay"): MCAP files that maa-sim's
 * `--record` writes into `<workspace>/recordings/`, each with a small JSON file beside it that
 * says which application and platform ran (`<name>.json`). Clients name a recording by its file
 * name only (RECORDING_NAME: no folders, no `..`); it is resolved inside the workspace's
 * confinement (symlinks out of the workspace are refused), so no route reaches any other file.
 */
import { mkdir, readdir, readFile, stat, writeFile } from 'node:fs/promises';
import path from 'node:path';
import { RECORDING_NAME, type SimMode, type SimRecordingInfo } from '@maa/protocol';
import { HttpError } from './http-util.js';
import type { Workspace } from './workspace.js';

export const RECORDINGS_DIR = 'recordings';

/** What the IDE knows of a recording it started (the JSON file beside it). */
interface RecordingMeta {
    app: string;
    platform: string;
    mode: SimMode;
}

/** `20260124-170302`: a UTC time in a file name. */
export function fileStamp(now: Date): string {
    const iso = now.toISOString(); // 2026-01-24T17:03:02.123Z
    return `${iso.slice(0, 10).replaceAll('-', '')}-${iso.slice(11, 19).replaceAll(':', '')}`;
}

/** `examples/TR.arcapp` at 17:03:02 UTC → `TR-20260124-170302.mcap` (other characters than letters, digits, `_`, `-` become `_`). */
export function recordingName(app: string, now: Date, taken: ReadonlySet<string> = new Set()): string {
    const stem =
        path.posix
            .basename(app)
            .replace(/\.arcapp$/, '')
            .replace(/[^A-Za-z0-9_-]/g, '_')
            .slice(0, 80) || 'run';
    const base = `${/^[A-Za-z0-9]/.test(stem) ? '' : 'run'}${stem}-${fileStamp(now)}`;
    let name = `${base}.mcap`;
    for (let i = 2; taken.has(name); i++) name = `${base}-${i}.mcap`;
    return name;
}

export class Recordings {
    constructor(private readonly workspace: Workspace) {}

    /** The folder's absolute path (it need not exist). */
    private async folder(): Promise<string> {
        return this.workspace.confined.resolve(RECORDINGS_DIR);
    }

    /** A new recording's absolute path, its folder made and its JSON file written (a run of `app` on `platform`). */
    async newTarget(meta: RecordingMeta, now = new Date()): Promise<{ name: string; file: string }> {
        const dir = await this.folder();
        await mkdir(dir, { recursive: true });
        const taken = new Set(await readdir(dir).catch(() => [] as string[]));
        // a recording in progress is `<name>.part` until the run ends (maa_sim.recorder)
        for (const n of [...taken]) if (n.endsWith('.mcap.part')) taken.add(n.slice(0, -'.part'.length));
        const name = recordingName(meta.app, now, taken);
        const file = await this.workspace.confined.resolveWritable(`${RECORDINGS_DIR}/${name}`);
        await writeFile(metaPath(file), `${JSON.stringify(meta, null, 2)}\n`, { mode: 0o664 });
        return { name, file };
    }

    /** Every complete recording, newest first (the `.part` files of runs still recording are left out). */
    async list(): Promise<SimRecordingInfo[]> {
        let dir: string;
        try {
            dir = await this.folder();
        } catch {
            return []; // no workspace folder to hold it (404): no recordings
        }
        const names = await readdir(dir).catch(() => [] as string[]);
        const infos: SimRecordingInfo[] = [];
        for (const name of names) {
            if (!RECORDING_NAME.test(name)) continue;
            const info = await this.info(name).catch(() => undefined);
            if (info) infos.push(info);
        }
        return infos.sort((a, b) => b.modified.localeCompare(a.modified) || a.name.localeCompare(b.name));
    }

    /** A recording by name: its absolute path and what is known of it; 400 for a bad name, 404 when there is none. */
    async resolve(name: string): Promise<{ file: string; info: SimRecordingInfo }> {
        if (!RECORDING_NAME.test(name)) {
            throw new HttpError(
                400,
                `not a recording name: ${JSON.stringify(name.slice(0, 80))} (a .mcap file name in ${RECORDINGS_DIR}/)`,
            );
        }
        const file = await this.workspace.confined.resolve(`${RECORDINGS_DIR}/${name}`, 'recording');
        const info = await this.info(name).catch(() => undefined);
        if (!info) throw new HttpError(404, `no recording ${name}`);
        return { file, info };
    }

    private async info(name: string): Promise<SimRecordingInfo | undefined> {
        const file = await this.workspace.confined.resolve(`${RECORDINGS_DIR}/${name}`, 'recording');
        const s = await stat(file);
        if (!s.isFile()) return undefined;
        return { name, size: s.size, modified: s.mtime.toISOString(), ...(await readMeta(file)) };
    }
}

function metaPath(file: string): string {
    return file.replace(/\.mcap$/, '.json');
}

/** The JSON file beside a recording, what of it is well-formed (a recording from elsewhere has none). */
async function readMeta(file: string): Promise<Partial<RecordingMeta>> {
    let value: unknown;
    try {
        value = JSON.parse(await readFile(metaPath(file), 'utf8'));
    } catch {
        return {};
    }
    if (!value || typeof value !== 'object') return {};
    const { app, platform, mode } = value as Record<string, unknown>;
    return {
        ...(typeof app === 'string' ? { app } : {}),
        ...(typeof platform === 'string' ? { platform } : {}),
        ...(mode === 'lockstep' || mode === 'ros2' ? { mode } : {}),
    };
}
