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
    log: Type.Array(Type.String()),
});
export type SimStatusAnswer = Static<typeof SimStatusAnswer>;
