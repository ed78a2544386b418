/** Client model classes of the diagram's element types (docs/ide.md "Diagram protocol"). */
import { SEdgeImpl, SGraphImpl, SNodeImpl, SPortImpl } from 'sprotty';

export type BehaviorKind = 'automaton' | 'robotarm' | 'compute' | 'handwritten' | 'composed' | string;
export type Severity = 'error' | 'warning' | undefined;

export class MaaGraph extends SGraphImpl {
    declare component?: string;
    declare diagramType?: string;
}

export class ComponentNode extends SNodeImpl {
    /** The condition of the `varif` the element belongs to (variable architectures). */
    declare variationPoint?: string;
    declare name?: string;
    declare componentType?: string;
    declare instancePath?: string;
    declare behaviorKind?: BehaviorKind;
    declare composed?: boolean;
    declare expanded?: boolean;
    declare severity?: Severity;
    declare trace?: string;
    /** A subcomponent declared in a mode (mode automata): the mode it is active in. */
    declare mode?: string;
    /** A decomposed component with a mode automaton (its automaton view shows the modes). */
    declare modeAutomaton?: boolean;
}

export class MaaPort extends SPortImpl {
    /** The condition of the `varif` the element belongs to (variable architectures). */
    declare variationPoint?: string;
    declare name?: string;
    declare direction?: 'in' | 'out';
    declare portType?: string;
    declare portPath?: string;
    declare severity?: Severity;
    declare trace?: string;
}

export class ConnectorEdge extends SEdgeImpl {
    /** The condition of the `varif` the element belongs to (variable architectures). */
    declare variationPoint?: string;
    declare sourcePortPath?: string;
    declare severity?: Severity;
    declare trace?: string;
    /** A connector declared in a mode (mode automata): the mode it is active in. */
    declare mode?: string;
}

export class StateNode extends SNodeImpl {
    declare name?: string;
    declare initial?: boolean;
    declare statePath?: string;
    declare severity?: Severity;
    declare trace?: string;
}

export class TransitionEdge extends SEdgeImpl {
    declare label?: string;
    /** The transition's position in allTransitions order (the index of a run's transition events). */
    declare transitionIndex?: number;
    declare severity?: Severity;
    declare trace?: string;
}
