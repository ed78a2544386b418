/**
 * The trace file `<out>/<platform>/.maa-trace.json` (docs/generating.md "Trace file"): which
 * generated lines come from which model element. Written by generator-core's orchestrator with
 * every generation, read by the IDE (generate panel: generated code ↔ model).
 *
 * Positions follow the package's one convention (position.ts): 0-based lines and characters.
 */
import { Type, type Static } from '@sinclair/typebox';
import { TRACE_FORMAT_VERSION } from '../formats.js';
import { Range } from '../position.js';

export { TRACE_FORMAT_VERSION } from '../formats.js';

export const TraceElement = Type.Object(
    {
        /** The model file, relative to the model root (or a URI when the document is not a file). */
        file: Type.String(),
        /** The element's text range in `file`, 0-based (LSP); null when the element has no text (built in). */
        range: Type.Union([Range, Type.Null()]),
        /** Langium's AST node path inside the file (`/component/ports@0`). */
        path: Type.String(),
        /** The AST type (`ComponentType`). */
        type: Type.String(),
        name: Type.Optional(Type.String()),
    },
    { description: 'The model element a range of generated lines comes from' },
);
export type TraceElement = Static<typeof TraceElement>;

/** Generated lines, 0-based, both ends inclusive. */
export const LineSpan = Type.Object(
    {
        first: Type.Integer({ minimum: 0, description: '0-based first generated line' }),
        last: Type.Integer({ minimum: 0, description: '0-based last generated line (inclusive)' }),
    },
    { description: 'Generated lines, 0-based, both ends inclusive' },
);
export type LineSpan = Static<typeof LineSpan>;

export const Trace = Type.Object({
    lines: LineSpan,
    /** The generator that wrote the lines (`timesync.Components`). */
    generator: Type.String(),
    element: TraceElement,
});
export type Trace = Static<typeof Trace>;

export const TracedFile = Type.Object({
    /** The generated file, relative to the platform folder, `/`-separated. */
    path: Type.String(),
    generator: Type.String(),
    /** A user file (written once, kept afterwards). */
    userFile: Type.Boolean(),
    sha256: Type.String({ pattern: '^[0-9a-f]{64}$' }),
    /** The number of lines of the file. */
    lines: Type.Integer({ minimum: 0 }),
    traces: Type.Array(Trace),
});
export type TracedFile = Static<typeof TracedFile>;

export const TraceGenerator = Type.Object({
    name: Type.String(),
    kind: Type.String(),
    package: Type.String(),
    version: Type.String(),
});
export type TraceGenerator = Static<typeof TraceGenerator>;

export const TraceFile = Type.Object(
    {
        version: Type.Literal(TRACE_FORMAT_VERSION),
        /** The application's name (`ToastServiceRobot`). */
        application: Type.String(),
        platform: Type.String(),
        /** The qualified root component (`toast.ToastServiceRobot`). */
        rootComponent: Type.String(),
        /** The model root, relative to the platform folder (`../../models`). */
        modelRoot: Type.String(),
        generators: Type.Array(TraceGenerator),
        files: Type.Array(TracedFile),
    },
    {
        $id: 'urn:maa:protocol:trace-file',
        title: 'MontiArcAutomaton trace file (.maa-trace.json)',
        description: 'Generated line ranges -> model elements; positions 0-based like LSP',
    },
);
export type TraceFile = Static<typeof TraceFile>;
