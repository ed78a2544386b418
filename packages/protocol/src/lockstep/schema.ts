/**
 * `lockstep.json` (docs/simulation.md "Lock-step mode"): how `maa-sim` loads a python-timesync
 * build into its own process. Written by the timesync generator, read by
 * `sim-server/src/maa_sim/lockstep.py` (which checks the JSON Schema emitted into
 * `maa_sim/protocol.py`). The controller it creates exchanges JSON messages by topic once per
 * period: `step({topic: message})` returns `{topic: message | [message, ...]}`.
 */
import { Type, type Static } from '@sinclair/typebox';
import { LOCKSTEP_FORMAT } from '../formats.js';

export { LOCKSTEP_FORMAT } from '../formats.js';

export const Lockstep = Type.Object(
    {
        format: Type.Literal(LOCKSTEP_FORMAT, { errorMessage: `format must be '${LOCKSTEP_FORMAT}'` }),
        /** `module:callable`, called with `parameters`, returning the controller. */
        factory: Type.String({
            pattern: '^[A-Za-z_][A-Za-z0-9_.]*:[A-Za-z_][A-Za-z0-9_]*$',
            errorMessage: "factory must be 'module:callable'",
        }),
        /** Folders (relative to the file) put on sys.path; default `["."]`. */
        python_path: Type.Optional(
            Type.Array(Type.String({ errorMessage: 'python_path must be a list of strings' }), {
                errorMessage: 'python_path must be a list of strings',
            }),
        ),
        /** The control period in seconds (the application's time slice). */
        period: Type.Optional(Type.Number({ exclusiveMinimum: 0, errorMessage: 'period must be a positive number of seconds' })),
        /** Passed to the factory. */
        parameters: Type.Optional(Type.Record(Type.String(), Type.Unknown(), { errorMessage: 'parameters must be an object' })),
    },
    {
        $id: 'urn:maa:protocol:lockstep',
        title: 'Lockstep',
        description: 'lockstep.json: how maa-sim loads a python-timesync build (docs/simulation.md)',
        errorMessage: 'expected an object',
    },
);
export type Lockstep = Static<typeof Lockstep>;

/** A message in JSON form (`maa_sim.messages`): the fields of a ROS 2 message. */
export const JsonMessage = Type.Record(Type.String(), Type.Unknown(), { description: 'a ROS 2 message in JSON form' });
export type JsonMessage = Static<typeof JsonMessage>;

/** What one `step` returns: per topic one message or the messages of a port written several times in the slice. */
export const StepOutputs = Type.Record(Type.String({ pattern: '^/' }), Type.Union([JsonMessage, Type.Array(JsonMessage), Type.Null()]), {
    title: 'StepOutputs',
    additionalProperties: false,
    description: 'topic -> message, or list of messages, emitted in one time slice',
});
export type StepOutputs = Static<typeof StepOutputs>;
