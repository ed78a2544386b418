// Which paths a workspace file may have: relative, `/`-separated, no `.`/`..`/empty segments, no
// backslash or control characters, at most MAX_PATH_LENGTH characters. The HTTP routes confine
// paths too; storage refuses what no route should ever pass (defense in depth).
import { InvalidPathError } from './types.js';

export const MAX_PATH_LENGTH = 512;

// biome-ignore lint/suspicious/noControlCharactersInRegex: control characters are what it refuses
const FORBIDDEN = /[\u0000-\u001f\u007f\\]/;

export function checkWorkspacePath(path: string): string {
    if (typeof path !== 'string' || path.length === 0) throw new InvalidPathError('a workspace path must not be empty');
    if (path.length > MAX_PATH_LENGTH) throw new InvalidPathError(`a workspace path is at most ${MAX_PATH_LENGTH} characters`);
    if (FORBIDDEN.test(path))
        throw new InvalidPathError(`the workspace path ${JSON.stringify(path)} has a backslash or a control character`);
    for (const segment of path.split('/')) {
        if (segment === '' || segment === '.' || segment === '..') {
            throw new InvalidPathError(`the workspace path ${JSON.stringify(path)} must be relative, without empty, "." or ".." segments`);
        }
    }
    return path;
}
