import type { AstNode } from 'langium';
import { ast, elementsOf, impliedConnectors, isComposed, subcomponentType, subcomponentsOf } from '@maa/language-adl';

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
            node: i.declaration
        });
    }
    return result;
}

/**
 * The out port of an atomic instance whose values reach `access` of the component at `path`
 * (instance path from the shown component, whose type `typeAt` knows for every shown
 * instance): connectors are followed into composed subcomponents (to the connector that feeds
 * their out port) and out of the component (to the connector that feeds its in port). Returns
 * the port path (`unit.sensor.value`), or `""` when the value comes from outside the shown
 * component or no connector feeds it.
 */
export function atomicSourcePath(typeAt: (path: readonly string[]) => ComponentType | undefined, path: readonly string[], access: PortName): string {
    let scope = [...path];
    let current: PortName = access;
    // Each step moves one level in or out; a bound guards against cyclic or broken models.
    for (let step = 0; step < 256; step++) {
        const type = typeAt(scope);
        if (!type) return '';
        if (current.sub !== undefined) {
            const sub = subcomponentsOf(type).find((s) => s.name === current.sub);
            const subType = sub ? subcomponentType(sub).decl : undefined;
            if (!subType) return '';
            if (!isComposed(subType)) return [...scope, current.sub, current.port].join('.');
            // Into the composed subcomponent: who feeds its out port inside?
            const feeding = feeder(subType, { port: current.port });
            if (!feeding) return '';
            const inner = [...scope, current.sub];
            const innerType = subType;
            const outerTypeAt = typeAt;
            typeAt = (p) => (p.join('.') === inner.join('.') ? innerType : outerTypeAt(p));
            scope = inner;
            current = feeding;
        } else {
            // Out of the component: who feeds this in port in the parent?
            if (scope.length === 0) return '';
            const name = scope[scope.length - 1]!;
            const parentPath = scope.slice(0, -1);
            const parent = typeAt(parentPath);
            const feeding = parent ? feeder(parent, { sub: name, port: current.port }) : undefined;
            if (!feeding) return '';
            scope = parentPath;
            current = feeding;
        }
    }
    return '';
}

/** The source of the connector in `c` whose targets include `target`. */
function feeder(c: ComponentType, target: PortName): PortName | undefined {
    for (const e of connectorsOf(c)) {
        if (e.targets.some((t) => t.port === target.port && t.sub === target.sub)) return e.source;
    }
    return undefined;
}
