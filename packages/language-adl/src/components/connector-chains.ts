/**
 * Connector chains: which port feeds a port, following connectors through nested components.
 * A value reaches an in port of a subcomponent from the connector of its parent that targets
 * it; that connector's source is an out port of a sibling (an atomic one: the chain ends; a
 * composed one: the chain continues inside it, at the connector that feeds its out port) or an
 * in port of the parent (the chain continues in the grandparent). The walk is the same for
 * every client (the ROS 2 generator's topics, the diagram's source ports); what a scope is and
 * which connectors it has (written, implied by `autoconnect`, declared in modes) is the client's.
 */

/** A port as a connector names it: `sub.port`, or `port` of the component itself. */
export interface PortEnd {
    readonly sub?: string | undefined;
    readonly port: string;
}

/** What feeds a port inside a scope: a connector's source, or a point where the client stops the walk. */
export type ChainFeed<Stop> = { readonly source: PortEnd } | { readonly stop: Stop };

/** The instance tree as the walk sees it (a scope is one component instance). */
export interface ChainGraph<Scope, Stop> {
    /** The instance of subcomponent `sub` of `scope`, if there is one. */
    child(scope: Scope, sub: string): Scope | undefined;
    /** The enclosing instance and the name `scope` has in it; undefined at the outermost scope. */
    parent(scope: Scope): { readonly scope: Scope; readonly name: string } | undefined;
    /** An atomic instance: its out ports are sources of their own. */
    isAtomic(scope: Scope): boolean;
    /** What feeds `target` inside `scope`, if anything does. */
    feeder(scope: Scope, target: PortEnd): ChainFeed<Stop> | undefined;
}

/** Where a chain ends. */
export type ChainEnd<Scope, Stop> =
    /** an out port of an atomic instance */
    | { readonly kind: 'atomic'; readonly scope: Scope; readonly port: string }
    /** an in port of the outermost scope: fed from outside */
    | { readonly kind: 'boundary'; readonly scope: Scope; readonly port: string }
    /** a point where the client's `feeder` stopped the walk */
    | { readonly kind: 'stop'; readonly stop: Stop };

/** Each step moves one level in or out; the bound guards against cyclic or broken models. */
const MAX_STEPS = 256;

/**
 * The end of the chain that feeds `end` as seen from `scope` (`sub.port`: an out port of a subcomponent, or
 * `port`: an in port of the scope itself), or undefined when no connector feeds it.
 */
export function chainSource<Scope, Stop>(graph: ChainGraph<Scope, Stop>, scope: Scope, end: PortEnd): ChainEnd<Scope, Stop> | undefined {
    let at = scope;
    let current = end;
    for (let step = 0; step < MAX_STEPS; step++) {
        let feed: ChainFeed<Stop> | undefined;
        if (current.sub !== undefined) {
            // Into the subcomponent: an atomic one is the source, a composed one has a connector feeding its out port.
            const child = graph.child(at, current.sub);
            if (child === undefined) return undefined;
            if (graph.isAtomic(child)) return { kind: 'atomic', scope: child, port: current.port };
            feed = graph.feeder(child, { port: current.port });
            at = child;
        } else {
            // Out of the scope: who feeds this in port in the parent?
            const up = graph.parent(at);
            if (up === undefined) return { kind: 'boundary', scope: at, port: current.port };
            feed = graph.feeder(up.scope, { sub: up.name, port: current.port });
            at = up.scope;
        }
        if (feed === undefined) return undefined;
        if ('stop' in feed) return { kind: 'stop', stop: feed.stop };
        current = feed.source;
    }
    return undefined;
}

/** The source of the first connector among `connectors` whose targets include `target`. */
export function feedingSource(
    connectors: Iterable<{ readonly source: PortEnd; readonly targets: readonly PortEnd[] }>,
    target: PortEnd,
): PortEnd | undefined {
    for (const c of connectors) {
        if (c.targets.some((t) => t.port === target.port && t.sub === target.sub)) return c.source;
    }
    return undefined;
}
