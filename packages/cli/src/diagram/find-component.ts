import { fileURLToPath } from 'node:url';
import type { WorkspaceComponent } from '@maa/language-server';
import { CliError } from '../errors.js';

/** How many component names an "unknown component" message lists at most. */
const LISTED = 12;

/**
 * The component a `maa-gen diagram` argument names: the (first) component of `file` when the
 * argument was a model file; else the one with that qualified name; else the only one with that
 * simple name. Anything else is a usage error that says what there is.
 */
export function findComponent(components: readonly WorkspaceComponent[], arg: string, file: string | undefined): WorkspaceComponent {
    if (file !== undefined) {
        const inFile = components.find((c) => c.uri.startsWith('file:') && fileURLToPath(c.uri) === file);
        if (!inFile) throw new CliError(`${arg} declares no component`);
        return inFile;
    }
    const exact = components.find((c) => c.name === arg);
    if (exact) return exact;
    const bySimpleName = components.filter((c) => c.name.split('.').pop() === arg);
    if (bySimpleName.length === 1) return bySimpleName[0]!;
    if (bySimpleName.length > 1) {
        throw new CliError(`component name "${arg}" is ambiguous: ${bySimpleName.map((c) => c.name).join(', ')}; give the qualified name`);
    }
    throw new CliError(unknownComponentMessage(components, arg));
}

function unknownComponentMessage(components: readonly WorkspaceComponent[], arg: string): string {
    if (components.length === 0) return `unknown component "${arg}": the model root has no components`;
    const names = [...new Set(components.map((c) => c.name))].sort();
    const similar = names.filter((n) => isSimilar(n, arg));
    const shown = (similar.length > 0 ? similar : names).slice(0, LISTED);
    const more = (similar.length > 0 ? similar : names).length - shown.length;
    return `unknown component "${arg}"; ${similar.length > 0 ? 'similar' : 'the model root has'}: ${shown.join(', ')}${more > 0 ? `, and ${more} more` : ''}`;
}

/** Whether a qualified name resembles the argument: every word of its simple name (`ToastRobot`: toast, robot) is in the name's simple name. */
function isSimilar(name: string, arg: string): boolean {
    const simple = (name.split('.').pop() ?? name).toLowerCase();
    const words = (arg.split('.').pop() ?? arg)
        .split(/(?=[A-Z])|[_$\d]+/)
        .map((w) => w.toLowerCase())
        .filter((w) => w.length > 1);
    return words.length > 0 && words.every((w) => simple.includes(w));
}
