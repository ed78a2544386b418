/**
 * The one position convention on the wire: LSP's. Lines and characters count from 0; a range's
 * end is exclusive. Every contract of this package that names a place in a text uses these.
 */
import { Type, type Static } from '@sinclair/typebox';

export const Position = Type.Object(
    {
        /** 0-based line. */
        line: Type.Integer({ minimum: 0, description: '0-based line' }),
        /** 0-based character (UTF-16 code unit) in the line. */
        character: Type.Integer({ minimum: 0, description: '0-based character (UTF-16 code unit) in the line' }),
    },
    { description: 'A position in a text, 0-based like LSP' },
);
export type Position = Static<typeof Position>;

export const Range = Type.Object(
    {
        start: Position,
        /** Exclusive, like LSP. */
        end: Position,
    },
    { description: 'A range in a text, 0-based like LSP, end exclusive' },
);
export type Range = Static<typeof Range>;
