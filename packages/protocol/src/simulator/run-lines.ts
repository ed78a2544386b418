/**
 * The JSON lines `maa-sim run` prints on stdout for the program that started it (`maa-gen sim`):
 * with `--progress-json` a {@link SimulatorProgress} about once a wall second while it runs, with
 * `--status-json` a {@link SimulatorFinished} when the run is over (after the ready line, which
 * carries `/sim/get_status`'s fields). docs/simulation.md, "`maa-sim run` reference".
 */
import { Type, type Static } from '@sinclair/typebox';

export const SimulatorProgress = Type.Object(
    {
        event: Type.Literal('progress'),
        /** Simulated seconds (the clock). */
        time: Type.Number(),
        /** Wall seconds since the run started. */
        wall_seconds: Type.Number({ minimum: 0 }),
        /** Simulated seconds per wall second over the last periods (0 while paused). */
        real_time_factor: Type.Number(),
        periods: Type.Integer({ minimum: 0 }),
        paused: Type.Boolean(),
        toast_level: Type.Number(),
        /** The goal: the toast lies on the plate (what `--until-goal` waits for). */
        goal_reached: Type.Boolean(),
        /** Messages written to the `--record` file so far; null without a recording. */
        recorded_messages: Type.Union([Type.Integer({ minimum: 0 }), Type.Null()]),
    },
    {
        $id: 'urn:maa:protocol:simulator-progress',
        title: 'SimulatorProgress',
        description: "maa-sim run's progress line (--progress-json)",
    },
);
export type SimulatorProgress = Static<typeof SimulatorProgress>;

export const SimulatorRecording = Type.Object(
    {
        /** The MCAP file (absolute), complete and under its final name. */
        path: Type.String(),
        messages: Type.Integer({ minimum: 0 }),
        /** Messages per recorded topic (every port topic, the simulator's topics, `/sim/scene`). */
        topics: Type.Record(Type.String(), Type.Integer({ minimum: 0 })),
    },
    { title: 'SimulatorRecording', description: 'the recording of a run (--record)' },
);
export type SimulatorRecording = Static<typeof SimulatorRecording>;

export const SimulatorFinished = Type.Object(
    {
        event: Type.Literal('finished'),
        /** `goal reached`, `time limit reached`, `signal SIGINT`, `error: ...`, `a node failed`. */
        reason: Type.String(),
        /** Simulated seconds at the end. */
        time: Type.Number(),
        goal_reached: Type.Boolean(),
        /** Wall seconds from the start of the loop to the end of the run. */
        wall_seconds: Type.Number({ minimum: 0 }),
        /** time / wall_seconds. */
        real_time_factor: Type.Number(),
        record: Type.Union([SimulatorRecording, Type.Null()]),
    },
    { $id: 'urn:maa:protocol:simulator-finished', title: 'SimulatorFinished', description: "maa-sim run's last line (--status-json)" },
);
export type SimulatorFinished = Static<typeof SimulatorFinished>;
