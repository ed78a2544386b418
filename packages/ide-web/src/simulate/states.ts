/**
 * `/maa/automaton_states` (`std_msgs/msg/String`, `data` = JSON `{"<node path>": "<state path>"}`)
 * → active state by instance path. Pure.
 */
import { nodeToInstancePath } from './topics.js';

/** Parses the message; node paths outside the root are dropped, malformed data gives an empty map. */
export function parseAutomatonStates(message: unknown, rootComponent: string, knownInstancePaths?: Iterable<string>): Map<string, string> {
    const result = new Map<string, string>();
    let data: unknown = message;
    if (data && typeof data === 'object' && 'data' in data) data = (data as { data: unknown }).data;
    if (typeof data !== 'string') return result;
    let parsed: unknown;
    try {
        parsed = JSON.parse(data);
    } catch {
        return result;
    }
    if (!parsed || typeof parsed !== 'object' || Array.isArray(parsed)) return result;
    const known = knownInstancePaths ? [...knownInstancePaths] : undefined;
    for (const [node, state] of Object.entries(parsed as Record<string, unknown>)) {
        if (typeof state !== 'string' || state.length === 0) continue;
        const inst = nodeToInstancePath(rootComponent, node, known);
        if (inst !== undefined) result.set(inst, state);
    }
    return result;
}
