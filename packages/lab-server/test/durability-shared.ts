// What durability-child.ts saves and durability.test.ts looks for.
export const DURABLE_PATH = 'DurableFile.arc';
export const DURABLE_LOGIN = 'durable-student';
export function durableContent(i: number): string {
    return `component Save${i} { port in Boolean b; } // save ${i}\n`;
}
