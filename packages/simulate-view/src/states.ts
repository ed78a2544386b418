/**
 * `/maa/automaton_states` (`std_msgs/msg/String`, `data` = JSON `{"<node path>": "<state path>"}`)
 * → active state (or current mode) by instance path. Pure.
 */

/**
 * Parses the message; `instanceOf` maps a node path to its instance path (port-map.ts, from the
 * backend's topic map): nodes it does not know are dropped, malformed data gives an empty map.
 */
export function parseAutomatonStates(message: unknown, instanceOf: (node: string) => string | undefined): Map<string, string> {
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
    for (const [node, state] of Object.entries(parsed as Record<string, unknown>)) {
        if (typeof state !== 'string' || state.length === 0) continue;
        const inst = instanceOf(node);
        if (inst !== undefined) result.set(inst, state);
    }
    return result;
}
