/** The body of every failed request (4xx, 5xx). */
import { Type, type Static } from '@sinclair/typebox';
import { IdeDiagnostic } from './generate.js';

export const ErrorAnswer = Type.Object({
    error: Type.String(),
    /** The simulator's log tail (a failed start). */
    log: Type.Optional(Type.Array(Type.String())),
    /** The generation's diagnostics (a start whose generation failed, 409). */
    diagnostics: Type.Optional(Type.Array(IdeDiagnostic)),
});
export type ErrorAnswer = Static<typeof ErrorAnswer>;
