import type { AstNode } from 'langium';
import {
    allPorts,
    type ast,
    behaviorsOf,
    inSubcomponent,
    isComposed,
    printType,
    stereotypeNames,
    subcomponentType,
    subcomponentsOf,
    variationCondition,
    type PortInfo,
} from '@maa/language-adl';
import { behaviorLanguageOf, componentQualifiedName, modeAutomatonView, modeSubcomponentsOf } from '@maa/generator-core';
import type { SModelElement } from 'sprotty-protocol';
import type { BuildContext } from './context.js';
import { connectorId, instanceId, labelId, portId } from './ids.js';
import { TYPES, type ComponentNode, type ConnectorEdge, type MaaGraph, type MaaLabel, type PortNode } from './model.js';
import { PORT_SIZE, labelSize } from './sizes.js';
import { behaviorLines, chipStates, widestState } from './behavior-summary.js';
import { atomicSourcePath, connectorsOf, type NamedConnector, type PortName } from './source-ports.js';

type ComponentType = ast.ComponentType;

/**
 * The component & connector view of a component: the component with its ports on the border,
 * its subcomponent instances as nested nodes with their ports, its connectors as edges.
 * Composed subcomponents are shown closed unless their instance path is in `expanded`; an
 * expanded one shows its own subcomponents and connectors the same way.
 */
export function buildComponentDiagram(root: ComponentType, expanded: ReadonlySet<string>, ctx: BuildContext): MaaGraph {
    const qualifiedName = componentQualifiedName(root);
    const types = new Map<string, ComponentType>();
    const typeAt = (path: readonly string[]): ComponentType | undefined => types.get(path.join('.'));
    const ports = new Set<string>();
    const rootNode = componentNode(root, [], undefined, true);
    return { type: TYPES.graph, id: ctx.id(`graph:${qualifiedName}`), component: qualifiedName, children: [rootNode] };

    function componentNode(type: ComponentType, path: string[], decl: ast.Subcomponent | undefined, open: boolean): ComponentNode {
        types.set(path.join('.'), type);
        const id = ctx.id(instanceId(path), decl ?? type);
        // The subcomponents of modes make a component composed too (mode automata, language-automata).
        const composed = isComposed(type) || modeSubcomponentsOf(type).length > 0;
        const name = decl?.name ?? type.name;
        const componentType = componentQualifiedName(type);
        const node: ComponentNode = {
            type: TYPES.component,
            id,
            name,
            componentType,
            instancePath: path.join('.'),
            behaviorKind: behaviorKind(type),
            composed,
            expanded: composed && open,
            children: [],
        };
        if (modeAutomatonView(type)) node.modeAutomaton = true;
        const severity = ctx.severity(decl, type);
        if (severity) node.severity = severity;
        const condition = variationCondition(decl);
        if (condition) node.variationPoint = condition;
        ctx.trace(node, decl ?? type);
        node.children!.push(
            label(TYPES.nameLabel, labelId(id, 'name'), name, decl ?? type),
            label(TYPES.typeLabel, labelId(id, 'type'), decl ? type.name : componentType, type),
            label(TYPES.badgeLabel, labelId(id, 'badge'), node.behaviorKind, type),
        );
        // Own ports of an atomic component shown on its own name their types too (its interface).
        const alone = path.length === 0 && !composed;
        for (const p of allPorts(type))
            node.children!.push(portNode(p, path, valueSlot(p.direction, path.length === 0, composed && open), alone));
        // Room for the current state (automaton) or mode during a run.
        const widest = widestState(chipStates(type));
        if (widest !== undefined) node.children!.push(label(TYPES.chipLabel, labelId(id, 'chip'), widest, type));
        if (alone) {
            for (const [i, line] of behaviorLines(type).entries()) {
                const l = label(TYPES.behaviorLabel, labelId(id, `behavior${i}`), line.text, line.source);
                if (line.opens) l.opens = line.opens;
                node.children!.push(l);
            }
        }
        if (composed && open) {
            for (const sub of subcomponentsOf(type)) {
                const subType = subcomponentType(sub).decl;
                if (!subType) continue;
                const subPath = [...path, sub.name];
                // A shown configuration (withVariant) decides the subcomponent's variation points by its own features.
                node.children!.push(inSubcomponent(sub, () => componentNode(subType, subPath, sub, expanded.has(subPath.join('.')))));
            }
            node.children!.push(...connectors(connectorsOf(type), path));
            // Modes: the subcomponents and connectors of every mode, marked with their mode.
            const modes = modeAutomatonView(type);
            if (modes) {
                const byName = new Map(modeSubcomponentsOf(type).map((s) => [s.name, s]));
                for (const m of modes.modes) {
                    for (const name of m.subcomponents) {
                        const sub = byName.get(name);
                        const subType = sub && subcomponentType(sub).decl;
                        if (!sub || !subType) continue;
                        const subPath = [...path, sub.name];
                        const child = componentNode(subType, subPath, sub, expanded.has(subPath.join('.')));
                        child.mode = m.name;
                        node.children!.push(child);
                    }
                    const named: NamedConnector[] = m.connectors.map((k) => ({
                        source: { sub: k.source.subcomponent, port: k.source.port },
                        targets: k.targets.map((t) => ({ sub: t.subcomponent, port: t.port })),
                        node: k.node,
                    }));
                    node.children!.push(...connectors(named, path, m.name));
                }
            }
        } else if (open) {
            // A shown configuration may leave no subcomponent (`varif (f) { Sub s; ... } else { in -> out; }`).
            node.children!.push(...connectors(connectorsOf(type), path));
        }
        return node;
    }

    function portNode(p: PortInfo, path: string[], slot: boolean, typed: boolean): PortNode {
        const id = ctx.id(portId(path, p.name));
        ports.add(id);
        const node: PortNode = {
            type: TYPES.port,
            id,
            name: p.name,
            direction: p.direction,
            portType: printType(p.type),
            portPath: [...path, p.name].join('.'),
            size: { width: PORT_SIZE, height: PORT_SIZE },
            children: [label(TYPES.portLabel, labelId(id, 'name'), typed ? `${p.name}: ${printType(p.type)}` : p.name, p.port)],
        };
        if (slot) node.children!.push(label(TYPES.valueLabel, labelId(id, 'value'), '', p.port));
        const severity = ctx.severity(p.port);
        if (severity) node.severity = severity;
        const condition = variationCondition(p.port);
        if (condition) node.variationPoint = condition;
        ctx.trace(node, p.port);
        return node;
    }

    function connectors(list: readonly NamedConnector[], path: string[], mode?: string): ConnectorEdge[] {
        const edges: ConnectorEdge[] = [];
        for (const e of list) {
            const source = e.source;
            const sourceId = endpointId(path, source);
            if (!ports.has(sourceId)) continue; // a broken reference: nothing to connect
            const sourcePortPath = atomicSourcePath(typeAt, path, source);
            for (const target of e.targets) {
                const targetId = endpointId(path, target);
                if (!ports.has(targetId)) continue;
                const edge: ConnectorEdge = {
                    type: TYPES.connector,
                    // Two modes may connect the same ports: the mode keeps their ids apart.
                    id: ctx.id(connectorId(path, local(source), mode ? `${local(target)}@${mode}` : local(target))),
                    sourceId,
                    targetId,
                    sourcePortPath,
                    ...(mode ? { mode } : {}),
                };
                const condition = variationCondition(e.node);
                if (condition) edge.variationPoint = condition;
                ctx.trace(edge, e.node);
                edges.push(edge);
            }
        }
        return edges;
    }

    function label(type: string, id: string, text: string, source: AstNode): MaaLabel {
        const l: MaaLabel = { type, id: ctx.id(id), text, size: labelSize(type, text) };
        ctx.trace(l, source);
        return l;
    }
}

/**
 * Whether a port gets room for its live value: the ports values flow out of in the view, i.e.
 * the out ports of a subcomponent (opened or not: ids do not depend on what is open) and the in
 * ports of the shown component (fed from outside), and every port of an atomic component shown
 * on its own.
 */
function valueSlot(direction: 'in' | 'out', isRoot: boolean, open: boolean): boolean {
    if (isRoot) return direction === 'in' || !open;
    return direction === 'out';
}

function endpointId(scope: readonly string[], p: PortName): string {
    return portId(p.sub !== undefined ? [...scope, p.sub] : scope, p.port);
}

function local(p: PortName): string {
    return p.sub !== undefined ? `${p.sub}.${p.port}` : p.port;
}

/** What implements a component: `composed`, `handwritten`, or its behavior block's language (`compute` without one). */
export function behaviorKind(c: ComponentType): ComponentNode['behaviorKind'] {
    if (isComposed(c)) return 'composed';
    if (stereotypeNames(c.stereotype).includes('handwritten')) return 'handwritten';
    const main = behaviorsOf(c).find((b) => b.behavior && b.behavior.$type !== 'InitBlock')?.behavior;
    return main ? behaviorLanguageOf(main) : 'compute';
}

/** Every element of a model below (and including) `element`, depth first. */
export function* allElements(element: SModelElement): Generator<SModelElement> {
    yield element;
    for (const child of element.children ?? []) yield* allElements(child);
}
