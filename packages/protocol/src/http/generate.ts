/** `POST /api/generate` and the generated output (`GET /api/generated/file|trace`). */
import { Type, type Static } from '@sinclair/typebox';
import { Range } from '../position.js';

const NonEmpty = (field: string, description: string) =>
    Type.String({ minLength: 1, description, errorMessage: `${field} must be a non-empty string (${description})` });

export const GenerateRequest = Type.Object({
    app: NonEmpty('app', 'the .arcapp, relative to the workspace'),
    platform: NonEmpty('platform', 'a platform of the application'),
});
export type GenerateRequest = Static<typeof GenerateRequest>;

/** A diagnostic of a generation run in LSP form (0-based range), its file relative to the workspace. */
export const IdeDiagnostic = Type.Object({
    file: Type.String(),
    range: Range,
    severity: Type.String({ description: 'error, warning or info' }),
    code: Type.String(),
    message: Type.String(),
});
export type IdeDiagnostic = Static<typeof IdeDiagnostic>;

export const GeneratedFileInfo = Type.Object({
    /** Relative to the platform folder. */
    path: Type.String(),
    size: Type.Integer({ minimum: 0 }),
});
export type GeneratedFileInfo = Static<typeof GeneratedFileInfo>;

export const GenerateAnswer = Type.Object({
    ok: Type.Boolean(),
    platform: Type.String(),
    files: Type.Array(GeneratedFileInfo),
    diagnostics: Type.Array(IdeDiagnostic),
});
export type GenerateAnswer = Static<typeof GenerateAnswer>;
