/** `GET /api/files`, `PUT|DELETE /api/file` (docs/ide.md "Backend HTTP API"). */
import { Type, type Static } from '@sinclair/typebox';

export const WorkspaceEntry = Type.Object({
    /** Relative to the workspace, `/`-separated. */
    path: Type.String(),
    type: Type.Union([Type.Literal('file'), Type.Literal('directory')]),
    /** Bytes, for files. */
    size: Type.Optional(Type.Integer({ minimum: 0 })),
});
export type WorkspaceEntry = Static<typeof WorkspaceEntry>;

/** `GET /api/files`: every entry, sorted by path. */
export const FilesAnswer = Type.Object({
    /** The workspace folder's name. */
    root: Type.String(),
    entries: Type.Array(WorkspaceEntry),
});
export type FilesAnswer = Static<typeof FilesAnswer>;

/** The answer of a request that only succeeds or fails (`PUT /api/file`, `POST /api/sim/stop`). */
export const OkAnswer = Type.Object({ ok: Type.Literal(true) });
export type OkAnswer = Static<typeof OkAnswer>;
