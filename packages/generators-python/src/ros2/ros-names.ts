// ROS names of model elements, on their own so that front ends (the browser IDE maps port topics
// back to ports) can import them without the generators: only generator-core's naming below.
import { snakeCase } from '@maa/generator-core/naming';

/** A ROS name token (node, namespace or topic segment, package): lower snake_case starting with a letter. */
export function rosName(name: string): string {
    const s = snakeCase(name).replace(/[^a-z0-9_]/g, '_');
    return /^[a-z]/.test(s) ? s : `x_${s}`;
}
