import type { AstNode } from 'langium';
import {
    type ast,
    chainSource,
    elementsOf,
    feedingSource,
    impliedConnectors,
    isComposed,
    subcomponentType,
    subcomponentsOf,
    type ChainGraph,
} from '@maa/language-adl';

type ComponentType = ast.ComponentType;

/** A port as a connector names it: `sub.port`, or `port` of the component itself. */
export interface PortName {
    readonly sub?: string;
    readonly port: string;
}

export function portName(access: ast.PortAccess): PortName {
    return access.subcomponent ? { sub: access.subcomponent.$refText, port: access.port.$refText } : { port: access.port.$refText };
}

/** A connector of a component by port names: written, or implied by `autoconnect` (its node is then the declaration). */
export interface NamedConnector {
    readonly source: PortName;
    readonly targets: readonly PortName[];
    readonly node: AstNode;
}

/** The connectors of a component: the written ones, then those its `autoconnect` implies. */
export function connectorsOf(c: ComponentType): NamedConnector[] {
    const result: NamedConnector[] = [];
    for (const e of elementsOf(c)) {
        if (e.$type === 'Connector') result.push({ source: portName(e.source), targets: e.targets.map(portName), node: e });
    }
    for (const i of impliedConnectors(c)) {
        result.push({
            source: { sub: i.source.sub?.name, port: i.source.info.name },
            targets: [{ sub: i.target.sub?.name, port: i.target.info.name }],
            node: i.declaration,
        });
    }
    return result;
}

/** A shown instance: its path from the shown component and its type (undefined when unresolved). */
interface ShownScope {
    readonly path: readonly string[];
    readonly type: ComponentType | undefined;
    /** The enclosing scope when the walk entered this one from it (instances inside a composed subcomponent are not shown). */
    readonly up?: ShownScope;
}

/** The shown instances as the shared connector-chain walk sees them. */
function shownGraph(typeAt: (path: readonly string[]) => ComponentType | undefined): ChainGraph<ShownScope, never> {
    return {
        child(scope, sub) {
            const decl = scope.type ? subcomponentsOf(scope.type).find((s) => s.name === sub) : undefined;
            const type = decl ? subcomponentType(decl).decl : undefined;
            return type ? { path: [...scope.path, sub], type, up: scope } : undefined;
        },
        parent(scope) {
            if (scope.type === undefined || scope.path.length === 0) return undefined;
            const path = scope.path.slice(0, -1);
            return { scope: scope.up ?? { path, type: typeAt(path) }, name: scope.path[scope.path.length - 1]! };
        },
        isAtomic: (scope) => scope.type !== undefined && !isComposed(scope.type),
        feeder(scope, target) {
            const source = scope.type ? feedingSource(connectorsOf(scope.type), target) : undefined;
            return source ? { source } : undefined;
        },
    };
}

/**
 * The out port of an atomic instance whose values reach `access` of the component at `path`
 * (instance path from the shown component, whose type `typeAt` knows for every shown
 * instance): connectors are followed into composed subcomponents (to the connector that feeds
 * their out port) and out of the component (to the connector that feeds its in port), by the
 * shared walk of `@maa/language-adl` (`chainSource`). Returns the port path
 * (`unit.sensor.value`), or `""` when the value comes from outside the shown component or no
 * connector feeds it.
 */
export function atomicSourcePath(
    typeAt: (path: readonly string[]) => ComponentType | undefined,
    path: readonly string[],
    access: PortName,
): string {
    const end = chainSource(shownGraph(typeAt), { path, type: typeAt(path) }, access);
    return end?.kind === 'atomic' ? [...end.scope.path, end.port].join('.') : '';
}
