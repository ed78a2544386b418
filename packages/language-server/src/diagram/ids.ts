/**
 * Element ids, derived from qualified names, instance paths, port and state names only (never
 * from positions in the text), so they survive edits and the client keeps selection,
 * expansion and the positions of unchanged elements across updates.
 */

/** The node of an instance: `root` for the shown component, `root.unit.sensor` below it. */
export function instanceId(path: readonly string[]): string {
    return ['root', ...path].join('.');
}

/** A port of an instance (`:` cannot occur in an instance id). */
export function portId(path: readonly string[], port: string): string {
    return `${instanceId(path)}:${port}`;
}

/** A connector from `source` to `target` (port paths relative to the component that declares it). */
export function connectorId(scope: readonly string[], source: string, target: string): string {
    return `conn:${instanceId(scope)}:${source}->${target}`;
}

export function stateId(statePath: string): string {
    return `state:${statePath}`;
}

export function transitionId(source: string, target: string): string {
    return `tr:${source}->${target}`;
}

export function labelId(owner: string, role: string): string {
    return `${owner}#${role}`;
}
