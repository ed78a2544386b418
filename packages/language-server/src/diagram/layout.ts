import ElkModule from 'elkjs/lib/elk.bundled.js';
import type { ELK, ELKConstructorArguments, ElkNode, LayoutOptions } from 'elkjs/lib/elk-api.js';
import { DefaultElementFilter, DefaultLayoutConfigurator, ElkLayoutEngine } from 'sprotty-elk/lib/elk-layout.js';
import type { Dimension, SGraph, SLabel, SModelElement, SModelIndex, SNode, SPort } from 'sprotty-protocol';
import { TYPES, type ComponentNode, type PortNode, type StateNode } from './model.js';
import { CachingElk } from './layout-cache.js';
import { PORT_SIZE } from './sizes.js';

/**
 * The server-side layout of our diagrams (the client shows them as they come), with ELK's
 * layered algorithm over the whole hierarchy at once (INCLUDE_CHILDREN).
 *
 * - C&C view: left to right; in ports on the west and out ports on the east border (their
 *   centres on the border), ordered by ELK. Nodes are sized here from their texts (header with
 *   name, type and badge, then one row per port), so ELK only places nodes, ports and
 *   connectors; the labels of nodes and ports are placed here afterwards, at fixed offsets.
 * - Automaton view: top to bottom (state machines read downwards; the long transition labels
 *   then stand beside the vertical edges instead of stretching the rows); the transition
 *   labels are real ELK edge labels (centred), so the layout reserves their room; states are
 *   sized here, initial states get room on their left for the client's initial marker.
 *
 * ELK is deterministic (fixed seed) and keeps the model order of nodes and edges where it can,
 * so a small edit changes little of the layout; an edit that changes nothing ELK sees reuses the
 * last layout (`CachingElk`).
 */
export class MaaLayoutEngine extends ElkLayoutEngine {
    constructor() {
        // ELK remembers its last layouts: an edit that leaves the laid-out graph as it was needs none.
        super(() => new CachingElk(createElk()) as unknown as ELK, new MaaElementFilter(), new MaaLayoutConfigurator());
    }

    override async layout(graph: SGraph, index?: SModelIndex): Promise<SGraph> {
        for (const child of graph.children) sizeNodes(child);
        const result = await super.layout(graph, index);
        for (const child of result.children) placeLabels(child);
        return result;
    }

    /** Initial states first: ELK's model order then puts them at the top. */
    protected override transformGraph(sgraph: SGraph, index: SModelIndex): ElkNode {
        return initialFirst(super.transformGraph(sgraph, index), index);
    }

    /** Initial states get an invisible label on their left: ELK keeps its room free for the client's marker. */
    protected override transformNode(snode: SNode, index: SModelIndex): ElkNode {
        const node = initialFirst(super.transformNode(snode, index), index);
        if (snode.type === TYPES.state && (snode as StateNode).initial) {
            node.labels = [
                ...(node.labels ?? []),
                {
                    id: `${snode.id}$initial-marker`,
                    text: 'initial', // ELK places no label without a text
                    width: INITIAL_MARKER.width,
                    height: INITIAL_MARKER.height,
                    // Left of the node's top (without H_PRIORITY, above it).
                    layoutOptions: { 'org.eclipse.elk.nodeLabels.placement': '[OUTSIDE, H_LEFT, V_TOP, H_PRIORITY]' },
                },
            ];
        }
        return node;
    }
}

function initialFirst(node: ElkNode, index: SModelIndex): ElkNode {
    const initial = (n: ElkNode): boolean => (index.getById(n.id) as Partial<StateNode> | undefined)?.initial === true;
    if (node.children?.some(initial)) node.children = [...node.children.filter(initial), ...node.children.filter((n) => !initial(n))];
    return node;
}

/** Room the client's initial marker (a dot and an arrow left of the state's top, `x` -20..0, `y` 10..18) needs. */
export const INITIAL_MARKER: Dimension = { width: 24, height: 20 };

/** Inner margin of component and state boxes. */
const PAD = 8;
/** The header of a component: name (y 4) and type (y 20) at the left, badge at the right. */
const HEADER = 40;
/** Vertical gap between ports on a side (ports are PORT_SIZE high). */
const PORT_GAP = 8;
/** Gap between a port and its label, inside the node. */
const PORT_LABEL_GAP = 3;
/** Gap between a port's label and the room of its live value. */
const VALUE_GAP = 4;
/** Room between the labels of in ports and those of out ports. */
const SIDE_GAP = 20;
/** The row of the current-state chip at the bottom of a component: the chip and a gap above it. */
const CHIP_ROW = 14 + 6;
/** The height of a behavior line (atomic component shown on its own). */
const LINE_STEP = 16;
/** Node widths are multiples of this. */
const WIDTH_GRID = 10;
/** Height of a state without substates; room above substates for the state's name. */
const STATE_HEIGHT = 32;
const STATE_HEADER = 28;

const width = (e: SModelElement | undefined): number => (e as SLabel | undefined)?.size?.width ?? 0;
const childOf = (n: SModelElement, type: string): SLabel | undefined =>
    (n.children ?? []).find((c) => c.type === type) as SLabel | undefined;
const childrenOf = (n: SModelElement, type: string): SModelElement[] => (n.children ?? []).filter((c) => c.type === type);
const portsOf = (n: SModelElement, direction: 'in' | 'out'): PortNode[] =>
    childrenOf(n, TYPES.port).filter((p) => (p as PortNode).direction === direction) as PortNode[];
/** The width a port's texts take inside its node: its name and the room of its live value. */
const portTextWidth = (p: PortNode): number => {
    const value = childOf(p, TYPES.valueLabel);
    return width(childOf(p, TYPES.portLabel)) + (value ? VALUE_GAP + width(value) : 0);
};
const maxLabel = (ports: PortNode[]): number => Math.max(0, ...ports.map(portTextWidth));
const hasNodes = (n: SModelElement): boolean => (n.children ?? []).some((c) => c.type === TYPES.component || c.type === TYPES.state);
const behaviorLinesOf = (n: SModelElement): SLabel[] => childrenOf(n, TYPES.behaviorLabel) as SLabel[];

/** Room the client's expand/collapse button of a composed subcomponent takes right of the type. */
export const EXPAND_TOGGLE_ROOM = 22;

/** Width of a component's header: name and badge side by side, the type (and the expand button) below. */
function headerWidth(node: SModelElement): number {
    const component = node as Partial<ComponentNode>;
    const toggle = component.composed && component.instancePath ? EXPAND_TOGGLE_ROOM : 0;
    return Math.max(
        width(childOf(node, TYPES.nameLabel)) + 12 + width(childOf(node, TYPES.badgeLabel)),
        width(childOf(node, TYPES.typeLabel)) + toggle,
    );
}

/** Height below a component's ports: its behavior lines and the row of its current-state chip. */
function footerHeight(node: SModelElement): number {
    const lines = behaviorLinesOf(node).length;
    return (lines > 0 ? lines * LINE_STEP + 4 : 0) + (childOf(node, TYPES.chipLabel) ? CHIP_ROW : 0);
}

/** Width the footer's texts need (behavior lines, the chip) with the node's margins. */
function footerWidth(node: SModelElement): number {
    return 2 * PAD + Math.max(0, width(childOf(node, TYPES.chipLabel)), ...behaviorLinesOf(node).map(width));
}

/** The size of a component without shown children, and of a state, from their texts. */
export function nodeSize(node: SModelElement): Dimension {
    if (node.type === TYPES.state) {
        const w = Math.max(64, width(childOf(node, TYPES.stateLabel)) + 2 * 12);
        return { width: Math.ceil(w / WIDTH_GRID) * WIDTH_GRID, height: hasNodes(node) ? STATE_HEADER + 2 * PAD : STATE_HEIGHT };
    }
    const ins = portsOf(node, 'in');
    const outs = portsOf(node, 'out');
    const rows = Math.max(1, ins.length, outs.length);
    const inner = PORT_SIZE / 2 + PORT_LABEL_GAP;
    const portsWidth = inner + maxLabel(ins) + (ins.length && outs.length ? SIDE_GAP : 0) + maxLabel(outs) + inner;
    return {
        // Rounded up to a grid, so a slightly longer or shorter name leaves the layout as it was.
        width: Math.ceil(Math.max(90, 2 * PAD + headerWidth(node), portsWidth, footerWidth(node)) / WIDTH_GRID) * WIDTH_GRID,
        height: HEADER + rows * PORT_SIZE + (rows - 1) * PORT_GAP + PAD + footerHeight(node),
    };
}

/**
 * Sets the sizes of nodes without children, which ELK keeps (those with children get minimum
 * sizes), and the places of such a component's ports: one row each below the header, in
 * declaration order from the top, centred on the west (in) and east (out) border. (ELK's own
 * port placement centres the ports in the whole height, over the header and the footer.)
 */
function sizeNodes(element: SModelElement): void {
    if (element.type !== TYPES.component && element.type !== TYPES.state) return;
    if (!hasNodes(element)) {
        const size = nodeSize(element);
        (element as SNode).size = size;
        if (element.type === TYPES.component) {
            for (const direction of ['in', 'out'] as const) {
                portsOf(element, direction).forEach((p, i) => {
                    const w = p.size?.width ?? PORT_SIZE;
                    p.position = { x: direction === 'in' ? -w / 2 : size.width - w / 2, y: HEADER + i * (PORT_SIZE + PORT_GAP) };
                });
            }
        }
    }
    for (const child of element.children ?? []) sizeNodes(child);
}

/** A port's name beside it and the room of its live value beside the name, inside the node. */
function placePortLabels(port: PortNode, open: boolean): void {
    const portLabel = childOf(port, TYPES.portLabel);
    if (!portLabel) return;
    const value = childOf(port, TYPES.valueLabel);
    // Beside the port; in an open node, whose ports have connectors inside too, above their line.
    const height = portLabel.size?.height ?? 14;
    const y = open ? -height + 2 : ((port.size?.height ?? PORT_SIZE) - height) / 2;
    if (port.direction === 'out') {
        portLabel.position = { x: -PORT_LABEL_GAP - width(portLabel), y };
        if (value) value.position = { x: portLabel.position.x - VALUE_GAP - width(value), y };
    } else {
        portLabel.position = { x: (port.size?.width ?? PORT_SIZE) + PORT_LABEL_GAP, y };
        if (value) value.position = { x: portLabel.position.x + width(portLabel) + VALUE_GAP, y };
    }
}

/** Node and port labels at their fixed places (ELK sees only edge labels). */
function placeLabels(element: SModelElement): void {
    const node = element as SNode;
    const w = node.size?.width ?? 0;
    const h = node.size?.height ?? 0;
    if (element.type === TYPES.component) {
        const open = hasNodes(element);
        const lines = behaviorLinesOf(element);
        const chip = childOf(element, TYPES.chipLabel);
        // The footer from the bottom up: the chip (as wide as the node allows), the behavior lines above it.
        let bottom = h - PAD;
        if (chip) {
            chip.size = { width: w - 2 * PAD, height: chip.size?.height ?? 14 };
            chip.position = { x: PAD, y: bottom - chip.size.height };
            bottom -= CHIP_ROW;
        }
        for (const [i, l] of lines.entries()) l.position = { x: PAD, y: bottom - (lines.length - i) * LINE_STEP };
        for (const label of node.children ?? []) {
            const l = label as SLabel;
            if (l.type === TYPES.nameLabel) l.position = { x: PAD, y: 4 };
            else if (l.type === TYPES.typeLabel) l.position = { x: PAD, y: 20 };
            else if (l.type === TYPES.badgeLabel) l.position = { x: w - PAD - width(l), y: 5 };
            else if (l.type === TYPES.port) placePortLabels(l as unknown as PortNode, open);
        }
    } else if (element.type === TYPES.state) {
        const label = childOf(element, TYPES.stateLabel);
        if (label)
            label.position = { x: (w - width(label)) / 2, y: hasNodes(element) ? 6 : (STATE_HEIGHT - (label.size?.height ?? 16)) / 2 };
    }
    for (const child of node.children ?? []) placeLabels(child);
}

/** ELK lays out nodes, ports, edges and edge labels; node and port labels are placed by us. */
class MaaElementFilter extends DefaultElementFilter {
    protected override filterLabel(label: SLabel, _index: SModelIndex): boolean {
        return label.type === TYPES.transitionLabel;
    }
}

/** Options both views share: deterministic, model order kept where it costs no crossings. */
const COMMON: LayoutOptions = {
    'org.eclipse.elk.algorithm': 'org.eclipse.elk.layered',
    'org.eclipse.elk.randomSeed': '1',
    'org.eclipse.elk.edgeRouting': 'ORTHOGONAL',
    'org.eclipse.elk.layered.considerModelOrder.strategy': 'NODES_AND_EDGES',
    // Back edges are those against the model order (not a heuristic's choice that an edit may flip).
    'org.eclipse.elk.layered.cycleBreaking.strategy': 'MODEL_ORDER',
    'org.eclipse.elk.layered.nodePlacement.strategy': 'BRANDES_KOEPF',
    'org.eclipse.elk.layered.nodePlacement.bk.fixedAlignment': 'BALANCED',
};

const CC: LayoutOptions = {
    ...COMMON,
    'org.eclipse.elk.direction': 'RIGHT',
    'org.eclipse.elk.spacing.nodeNode': '20',
    'org.eclipse.elk.layered.spacing.nodeNodeBetweenLayers': '36',
    'org.eclipse.elk.spacing.edgeNode': '12',
    'org.eclipse.elk.spacing.edgeEdge': '8',
    'org.eclipse.elk.layered.spacing.edgeNodeBetweenLayers': '12',
    'org.eclipse.elk.layered.spacing.edgeEdgeBetweenLayers': '8',
};

const AUTOMATON: LayoutOptions = {
    ...COMMON,
    'org.eclipse.elk.direction': 'DOWN',
    'org.eclipse.elk.spacing.nodeNode': '40',
    'org.eclipse.elk.layered.spacing.nodeNodeBetweenLayers': '30',
    'org.eclipse.elk.spacing.edgeNode': '16',
    'org.eclipse.elk.spacing.edgeEdge': '12',
    'org.eclipse.elk.layered.spacing.edgeNodeBetweenLayers': '16',
    'org.eclipse.elk.layered.spacing.edgeEdgeBetweenLayers': '12',
    'org.eclipse.elk.spacing.edgeLabel': '6',
    'org.eclipse.elk.spacing.labelNode': '8',
    'org.eclipse.elk.layered.edgeLabels.sideSelection': 'SMART_DOWN',
    'org.eclipse.elk.layered.edgeLabels.centerLabelPlacementStrategy': 'MEDIAN_LAYER',
};

class MaaLayoutConfigurator extends DefaultLayoutConfigurator {
    protected override graphOptions(graph: SGraph, _index: SModelIndex): LayoutOptions {
        const automaton = graph.id.startsWith('automaton:');
        return {
            ...(automaton ? AUTOMATON : CC),
            'org.eclipse.elk.hierarchyHandling': 'INCLUDE_CHILDREN',
            'org.eclipse.elk.padding': '[top=12,left=12,bottom=12,right=12]',
        };
    }

    protected override nodeOptions(node: SNode, _index: SModelIndex): LayoutOptions {
        const size = nodeSize(node);
        if (node.type === TYPES.state) {
            return {
                ...AUTOMATON,
                'org.eclipse.elk.nodeSize.constraints': '[MINIMUM_SIZE]',
                'org.eclipse.elk.nodeSize.minimum': `(${size.width}, ${size.height})`,
                // Substates below the name (initial markers have their room as labels).
                'org.eclipse.elk.padding': hasNodes(node)
                    ? `[top=${STATE_HEADER},left=${PAD * 2},bottom=${PAD * 2},right=${PAD * 2}]`
                    : '[top=0,left=0,bottom=0,right=0]',
            };
        }
        const open = hasNodes(node);
        const inner = PORT_SIZE / 2 + PORT_LABEL_GAP + 12;
        const footer = footerHeight(node);
        return {
            ...CC,
            // Ports in declaration order: placed by sizeNodes in a closed node, numbered by portOptions in an open one.
            'org.eclipse.elk.portConstraints': open ? 'FIXED_ORDER' : 'FIXED_POS',
            'org.eclipse.elk.portAlignment.default': 'CENTER',
            'org.eclipse.elk.spacing.portPort': `${PORT_GAP}`,
            // Ports below the header and above the footer (behavior lines, state chip).
            'org.eclipse.elk.spacing.portsSurrounding': `[top=${HEADER},left=0,bottom=${PAD + footer},right=0]`,
            'org.eclipse.elk.nodeSize.constraints': '[PORTS, MINIMUM_SIZE]',
            'org.eclipse.elk.nodeSize.minimum': open
                ? `(${Math.ceil(Math.max(2 * PAD + headerWidth(node), footerWidth(node)))}, ${HEADER + 20 + footer})`
                : `(${size.width}, ${size.height})`,
            // Children below the header and above the footer; the labels of the node's own ports beside them.
            'org.eclipse.elk.padding': open
                ? `[top=${HEADER + 16},left=${Math.max(20, inner + maxLabel(portsOf(node, 'in')))},bottom=${16 + footer},right=${Math.max(20, inner + maxLabel(portsOf(node, 'out')))}]`
                : `[top=${PAD},left=${PAD},bottom=${PAD},right=${PAD}]`,
        };
    }

    protected override portOptions(port: SPort, index: SModelIndex): LayoutOptions {
        const direction = (port as Partial<PortNode>).direction;
        return {
            'org.eclipse.elk.port.side': direction === 'out' ? 'EAST' : 'WEST',
            'org.eclipse.elk.port.index': `${portIndex(port, index)}`,
            'org.eclipse.elk.port.borderOffset': `${-(port.size?.width ?? 0) / 2}`,
        };
    }

    protected override labelOptions(label: SLabel, _index: SModelIndex): LayoutOptions | undefined {
        if (label.type !== TYPES.transitionLabel) return undefined;
        return { 'org.eclipse.elk.edgeLabels.placement': 'CENTER', 'org.eclipse.elk.edgeLabels.inline': 'false' };
    }
}

/**
 * A port's place in ELK's fixed order, which runs clockwise from the top left: down the east
 * side, then up the west side. Out ports (east) and in ports (west) are numbered so that both
 * sides read top to bottom in declaration order.
 */
function portIndex(port: SPort, index: SModelIndex): number {
    const parent = index.getParent(port.id);
    const direction = (port as Partial<PortNode>).direction === 'out' ? 'out' : 'in';
    const side = parent ? portsOf(parent, direction) : [];
    const at = Math.max(
        0,
        side.findIndex((p) => p.id === port.id),
    );
    const all = parent ? childrenOf(parent, TYPES.port).length : 0;
    return direction === 'out' ? at : 2 * all - at;
}

/**
 * elk.bundled.js is CommonJS (`module.exports = ELK`, plus `.default`); its typings describe an
 * ES module, so TypeScript types the default import as the namespace. The constructor is the
 * `default` member in both module systems' views.
 */
const ElkConstructor = (ElkModule as unknown as { default: new (args?: ELKConstructorArguments) => ELK }).default;

/**
 * A new ELK instance. elk.bundled.js decides on first use whether it runs as ELK's own Web
 * Worker: with `self` defined and no `document` (our language server's worker), it would take
 * over `self.onmessage`, the LSP channel, and export nothing. It is shown a `document` while it
 * loads, so it stays a library in every environment.
 */
export function createElk(): ELK {
    const scope = globalThis as { document?: unknown; self?: unknown };
    const pretend = scope.document === undefined && scope.self !== undefined;
    if (pretend) scope.document = {};
    try {
        return new ElkConstructor();
    } finally {
        if (pretend) delete scope.document;
    }
}
