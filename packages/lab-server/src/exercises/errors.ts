/** An exercise that cannot be loaded, released or updated; the message says where and why (one line each). */
export class ExerciseError extends Error {
    constructor(
        message: string,
        /** every problem as `file: /json/pointer: message` (or `file: message`) */
        readonly problems: readonly string[] = [message],
    ) {
        super(message);
        this.name = 'ExerciseError';
    }
}
