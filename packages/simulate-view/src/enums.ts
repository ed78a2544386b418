/** Enum literals per message type (ROS 2 mode's enum messages), looked up once through rosapi. */
import type { RosConnection } from './ros/index.js';
import { enumLiteralsOf, type FormatOptions } from './format.js';

export class EnumLiterals {
    /** `null`: looked up (or being looked up), no literals. */
    private readonly byType = new Map<string, string[] | null>();

    /** Looks up the literals of `type` once; `onFound` runs when there are some. */
    lookUp(conn: RosConnection | undefined, type: string, onFound: (type: string) => void): void {
        if (!type || this.byType.has(type) || !conn) return;
        this.byType.set(type, null);
        conn.messageDetails(type)
            .then((typedefs) => {
                const literals = enumLiteralsOf(typedefs[0]);
                if (!literals) return;
                this.byType.set(type, literals);
                onFound(type);
            })
            .catch(() => {
                /* no rosapi details: ordinals stay */
            });
    }

    literals(type: string): string[] | undefined {
        return this.byType.get(type) ?? undefined;
    }

    formatOptions(type: string): FormatOptions | undefined {
        const literals = this.literals(type);
        return literals ? { enumLiterals: literals } : undefined;
    }
}
