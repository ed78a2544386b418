/** The simulation sessions: `POST /api/sim/start|stop`, `GET /api/sim/status`, `GET /api/sim/topics`. */
import { Type, type Static } from '@sinclair/typebox';

/** `lockstep` runs a timesync platform, `ros2` a ros2 platform. */
export const SimMode = Type.Union([Type.Literal('lockstep'), Type.Literal('ros2')]);
export type SimMode = Static<typeof SimMode>;

export const SimStartRequest = Type.Object({
    app: Type.String({ minLength: 1, errorMessage: 'app must be a non-empty string (the .arcapp, relative to the workspace)' }),
    platform: Type.String({ minLength: 1, errorMessage: 'platform must be a non-empty string (a platform of the application)' }),
    /** Default: the platform's kind decides. */
    mode: Type.Optional(Type.Union(SimMode.anyOf, { errorMessage: 'mode must be "lockstep" or "ros2"' })),
    /** Simulated seconds per real second; 0 = as fast as possible. */
    speed: Type.Optional(
        Type.Number({ minimum: 0, maximum: 1000, errorMessage: 'speed must be a number from 0 (as fast as possible) to 1000' }),
    ),
    /** Record the run to `<workspace>/recordings/<App>-<UTC yyyymmdd-hhmmss>.mcap` (maa-sim's `--record`). */
    record: Type.Optional(Type.Boolean({ errorMessage: 'record must be true or false' })),
});
export type SimStartRequest = Static<typeof SimStartRequest>;

export const SimStartAnswer = Type.Object({
    ok: Type.Literal(true),
    session: Type.String(),
    mode: SimMode,
    /** The rosbridge WebSocket path on the backend's origin. */
    rosbridge: Type.String(),
    /** The viser viewer's path on the backend's origin. */
    viser: Type.String(),
});
export type SimStartAnswer = Static<typeof SimStartAnswer>;

export const SimStatusAnswer = Type.Object({
    running: Type.Boolean(),
    /** A start is under way: the ROS 2 environment is being set up or the interface package built (log shows progress). */
    preparing: Type.Optional(Type.Boolean()),
    session: Type.Optional(Type.String()),
    mode: Type.Optional(SimMode),
    app: Type.Optional(Type.String()),
    platform: Type.Optional(Type.String()),
    exitCode: Type.Optional(Type.Union([Type.Integer(), Type.Null()])),
    /** The session replays this recording (a name of `GET /api/sim/recordings`), not a run. */
    replay: Type.Optional(Type.String()),
    /** The run is being recorded to this recording (its name). */
    recording: Type.Optional(Type.String()),
    log: Type.Array(Type.String()),
});
export type SimStatusAnswer = Static<typeof SimStatusAnswer>;

/** A recording's name: a file of the workspace's `recordings/` folder, no path. */
export const RECORDING_NAME = /^[A-Za-z0-9][A-Za-z0-9._-]{0,199}\.mcap$/;

/** One recording of `GET /api/sim/recordings` (the run's application and platform when the IDE recorded it). */
export const SimRecordingInfo = Type.Object({
    /** The file name in `recordings/` (what `POST /api/sim/replay` takes). */
    name: Type.String(),
    size: Type.Integer({ minimum: 0 }),
    /** Last change, ISO 8601. */
    modified: Type.String(),
    app: Type.Optional(Type.String()),
    platform: Type.Optional(Type.String()),
    mode: Type.Optional(SimMode),
});
export type SimRecordingInfo = Static<typeof SimRecordingInfo>;

export const SimRecordingsAnswer = Type.Object({
    /** Newest first. */
    recordings: Type.Array(SimRecordingInfo),
});
export type SimRecordingsAnswer = Static<typeof SimRecordingsAnswer>;

export const SimReplayRequest = Type.Object({
    recording: Type.String({ minLength: 1, errorMessage: 'recording must be the name of a recording (GET /api/sim/recordings)' }),
});
export type SimReplayRequest = Static<typeof SimReplayRequest>;

/**
 * A replay session: maa-sim `replay` serving the recording's 3D scene (viser) and its services
 * over rosbridge (`/sim/seek`, `/sim/get_status`, `/sim/replay_messages`; docs/simulation.md).
 */
export const SimReplayAnswer = Type.Object({
    ok: Type.Literal(true),
    session: Type.String(),
    recording: SimRecordingInfo,
    rosbridge: Type.String(),
    viser: Type.String(),
});
export type SimReplayAnswer = Static<typeof SimReplayAnswer>;
