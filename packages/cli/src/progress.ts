import type { CliIo } from './io.js';

export interface Progress {
    update(message: string): void;
    done(): void;
}

/**
 * A one-line progress display on stderr, redrawn in place. Only for terminals: when stderr is
 * not a TTY (pipes, CI logs, tests) nothing is written at all.
 */
export function createProgress(io: CliIo): Progress | undefined {
    if (!io.stderrIsTTY) return undefined;
    const width = Math.max(20, (io.stderrColumns || 80) - 1);
    let shown = false;
    return {
        update(message) {
            const line = message.replace(/\s+/g, ' ');
            io.err(`\r\x1b[K${line.length > width ? `${line.slice(0, width - 1)}…` : line}`);
            shown = true;
        },
        done() {
            if (shown) io.err('\r\x1b[K');
            shown = false;
        },
    };
}
