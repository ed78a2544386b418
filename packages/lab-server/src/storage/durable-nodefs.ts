// PGlite's NodeFS with real fsync. PGlite runs PostgreSQL with synchronous_commit = on on
// Emscripten's NODEFS, which writes every page and WAL record straight to the host file with
// fs.writeSync: a commit PGlite acknowledged survives a killed process (the data is in the
// kernel). But PGlite starts PostgreSQL with fsync off (`-F`), and NODEFS has no fsync operation
// either, so it would not survive a power loss. connect.ts turns fsync on with the WAL synced by
// fsync() (durableStartParams)
// and this filesystem gives NODEFS streams an fsync that calls fs.fsyncSync on the host
// descriptor, so a commit PGlite acknowledges is on the disk, as with a PostgreSQL server.
import { fsyncSync } from 'node:fs';
import { NodeFS } from '@electric-sql/pglite/nodefs';

type PGliteArg = Parameters<NodeFS['init']>[0];
type EmscriptenOpts = Parameters<NodeFS['init']>[1];
type PreRun = NonNullable<EmscriptenOpts['preRun']>[number];

/** A NODEFS stream as Emscripten hands it to stream operations (`nfd`: the host descriptor). */
interface NodeFsStream {
    nfd?: number;
}

/** How many host fsyncs the durable filesystems of this process made (the tests check it grows). */
let fsyncCount = 0;
export function durableFsyncCount(): number {
    return fsyncCount;
}

export class DurableNodeFS extends NodeFS {
    override async init(pg: PGliteArg, opts: EmscriptenOpts): ReturnType<NodeFS['init']> {
        const { emscriptenOpts } = await super.init(pg, opts);
        const installFsync: PreRun = (mod) => {
            // NODEFS is Emscripten's object; its stream_ops are shared by every node it creates.
            const nodefs = mod.NODEFS as unknown as { stream_ops: Record<string, unknown> };
            nodefs.stream_ops['fsync'] = (stream: NodeFsStream) => {
                if (typeof stream.nfd === 'number') {
                    fsyncSync(stream.nfd);
                    fsyncCount += 1;
                }
                return 0;
            };
        };
        // Before NodeFS's own preRun mounts the data directory, so every stream sees it.
        return { emscriptenOpts: { ...emscriptenOpts, preRun: [installFsync, ...(emscriptenOpts.preRun ?? [])] } };
    }
}
