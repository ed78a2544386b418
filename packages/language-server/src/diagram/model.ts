import type { SEdge, SGraph, SLabel, SNode, SPort } from 'sprotty-protocol';

/**
 * The diagram model the IDE's Sprotty client renders (docs/ide.md, "Diagram protocol"): element
 * types and the properties the client relies on. Positions and sizes come from the server's
 * ELK layout, so the client needs no layout of its own.
 */

export const DIAGRAM_TYPES = ['maa-cc', 'maa-automaton'] as const;
export type DiagramType = (typeof DIAGRAM_TYPES)[number];

/** The options of a RequestModelAction for our diagrams. */
export interface MaaDiagramOptions {
    readonly diagramType: DiagramType;
    readonly sourceUri: string;
    /** Qualified name of the component to show (default: the component of `sourceUri`). */
    readonly component?: string;
    /** Instance paths of composed subcomponents to show opened. */
    readonly expanded?: readonly string[];
    /**
     * A feature configuration to show (C&C diagram of a variable component): values of the shown
     * component's features; the diagram shows the first admitted configuration (constraints,
     * feature bindings) that agrees with them, features not given take that configuration's
     * value. Without it, every variation point is shown.
     */
    readonly features?: Readonly<Record<string, boolean>>;
    readonly needsClientLayout?: boolean;
}

export type BehaviorKind = 'automaton' | 'robotarm' | 'compute' | 'handwritten' | 'composed';
export type MarkerSeverity = 'error' | 'warning';

export const TYPES = {
    graph: 'graph',
    component: 'node:component',
    port: 'port',
    connector: 'edge:connector',
    state: 'node:state',
    transition: 'edge:transition',
    nameLabel: 'label:name',
    typeLabel: 'label:type',
    badgeLabel: 'label:badge',
    portLabel: 'label:port',
    stateLabel: 'label:state',
    transitionLabel: 'label:transition',
    /** The room a live value takes beside a port (empty text; the client draws a run's value in it). */
    valueLabel: 'label:value',
    /** The room the current-state chip of an automaton or mode automaton takes (empty text; drawn during a run). */
    chipLabel: 'label:chip',
    /** A line about the behavior of an atomic component shown on its own (its automaton, its RobotArm programs). */
    behaviorLabel: 'label:behavior',
} as const;

interface Traced {
    /** langium-sprotty's trace: `<document uri>?<start line>:<start col>-<end line>:<end col>#<AST path>`. */
    trace?: string;
}

export interface MaaGraph extends SGraph {
    /** Qualified name of the shown component. */
    component: string;
    /** The features (own and inherited) of the shown component, if it has any (C&C diagram). */
    features?: string[];
    /**
     * The feature values of the shown configuration when the request asked for one and an
     * admitted configuration agrees with it; absent when every variation point is shown.
     */
    configuration?: Record<string, boolean>;
    /** Set when the requested feature values admit no configuration (every variation point is shown). */
    configurationRejected?: boolean;
}

export interface ComponentNode extends SNode, Traced {
    /** The condition of the variation point (`varif`) the element belongs to, if any (MontiArc's variable architectures). */
    variationPoint?: string;
    type: typeof TYPES.component;
    name: string;
    /** Qualified name of the component type. */
    componentType: string;
    /** Subcomponent names from the shown component (`""` for the shown component itself). */
    instancePath: string;
    /** One of BehaviorKind, or the block keyword of a further behavior language. */
    behaviorKind: BehaviorKind | (string & Record<never, never>);
    composed: boolean;
    expanded: boolean;
    severity?: MarkerSeverity;
    /** A subcomponent of a mode (mode automata): the mode it is active in. */
    mode?: string;
    /** Set on a decomposed component with a mode automaton (its automaton view shows the modes). */
    modeAutomaton?: boolean;
}

export interface PortNode extends SPort, Traced {
    /** The condition of the variation point (`varif`) the element belongs to, if any (MontiArc's variable architectures). */
    variationPoint?: string;
    type: typeof TYPES.port;
    name: string;
    direction: 'in' | 'out';
    portType: string;
    /** Instance path and port name (`ctrl.arm`; just `arm` for a port of the shown component). */
    portPath: string;
    severity?: MarkerSeverity;
}

export interface ConnectorEdge extends SEdge, Traced {
    /** The condition of the variation point (`varif`) the element belongs to, if any (MontiArc's variable architectures). */
    variationPoint?: string;
    type: typeof TYPES.connector;
    /** The out port of an atomic instance whose values flow through this connector (`""` if none). */
    sourcePortPath: string;
    /** A connector of a mode (mode automata): the mode it is active in. */
    mode?: string;
}

export interface StateNode extends SNode, Traced {
    type: typeof TYPES.state;
    name: string;
    initial: boolean;
    /** State names from the top level (`Outer.Inner`). */
    statePath: string;
    severity?: MarkerSeverity;
}

export interface TransitionEdge extends SEdge, Traced {
    type: typeof TYPES.transition;
    /** `trigger [guard] / action` as written (whitespace collapsed). */
    label: string;
    /**
     * The transition's 0-based position in `allTransitions(automaton)` order (@maa/language-automata;
     * for a mode automaton, in the order of its transitions): the index a run's transition events carry.
     * (Not `index`: Sprotty's client elements have an `index`, their model index.)
     */
    transitionIndex: number;
}

export interface MaaLabel extends SLabel, Traced {
    /** The whole text of a label shown shortened (a long transition label), for a tooltip. */
    fullText?: string;
    /** A behavior line the client makes a link: `automaton` opens the component's automaton view. */
    opens?: 'automaton';
}
