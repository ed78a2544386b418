/**
 * The diagram's tool bar: Fit, zoom, SVG export, the switch between a component's architecture
 * and its automaton (or mode automaton), and the title.
 */
import type { DiagramTarget } from './contracts.js';
import { shownComponentNode, type SchemaElement } from './schema.js';

function button(label: string, title: string, testid: string, onClick: () => void): HTMLButtonElement {
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = label;
    b.title = title;
    b.className = 'maa-diagram-button';
    b.dataset['testid'] = testid;
    b.addEventListener('click', onClick);
    return b;
}

export interface ToolbarActions {
    fit(): void;
    zoomBy(factor: number): void;
    exportSvg(): void;
    /** The architecture ↔ automaton switch. */
    switchView(): void;
}

/** The shown component: the model's `component`, else the target's. */
export function shownComponent(schema: SchemaElement | undefined, target: DiagramTarget | undefined): string {
    return (schema?.['component'] as string | undefined) ?? target?.component ?? '';
}

export class Toolbar {
    readonly element = document.createElement('div');
    private readonly title = document.createElement('span');
    private readonly switchButton: HTMLButtonElement;

    constructor(actions: ToolbarActions) {
        this.element.className = 'maa-diagram-toolbar';
        this.title.className = 'maa-diagram-title';
        this.switchButton = button('Automaton', 'Show the state machine of this component', 'diagram-switch', () => actions.switchView());
        this.element.append(
            button('Fit', 'Fit the diagram into the view', 'diagram-fit', () => actions.fit()),
            button('−', 'Zoom out', 'diagram-zoom-out', () => actions.zoomBy(1 / 1.25)),
            button('+', 'Zoom in', 'diagram-zoom-in', () => actions.zoomBy(1.25)),
            button('Export SVG', 'Download the diagram as SVG', 'diagram-export', () => actions.exportSvg()),
            this.switchButton,
            this.title,
        );
    }

    /** The switch and the title for the shown diagram. */
    update(schema: SchemaElement | undefined, target: DiagramTarget | undefined): void {
        const comp = shownComponent(schema, target);
        const simple = comp.split('.').pop() ?? '';
        if (target?.diagramType === 'maa-automaton') {
            this.switchButton.hidden = false;
            this.switchButton.textContent = 'Architecture';
            this.switchButton.title = 'Back to the component diagram';
            this.title.textContent = `${simple} — automaton`;
            return;
        }
        const node = schema ? shownComponentNode(schema) : undefined;
        const modes = (node?.['modeAutomaton'] ?? schema?.['modeAutomaton']) === true;
        this.switchButton.hidden = (node?.['behaviorKind'] ?? schema?.['behaviorKind']) !== 'automaton' && !modes;
        this.switchButton.textContent = 'Automaton';
        this.switchButton.title = modes ? 'Show the mode automaton of this component' : 'Show the state machine of this component';
        this.title.textContent = simple;
    }
}
