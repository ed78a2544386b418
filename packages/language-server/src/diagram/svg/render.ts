import type { Bounds, SEdge, SLabel, SModelElement, SModelRoot } from 'sprotty-protocol';
import { TYPES, type ComponentNode, type PortNode, type StateNode } from '../model.js';
import { DiagramGeometry, union } from './geometry.js';
import { standaloneStylesheet } from './stylesheet.js';
import { componentView, edgeView, genericView, labelView, portView, stateView, type ViewContext } from './views.js';
import { el, num, serialize, type XmlElement, type XmlNode } from './xml.js';

/**
 * A laid-out diagram model (what the diagram server sends the IDE: `buildComponentDiagram` or
 * `buildAutomatonDiagram` after `MaaLayoutEngine`) as a standalone SVG document, without a
 * browser: the elements of the IDE's diagram views with their classes and ids (views.ts), the
 * edges routed as Sprotty routes them (geometry.ts), and the IDE's diagram stylesheet inside,
 * resolved to its light palette like the IDE's Export SVG (stylesheet.ts).
 */

export interface SvgRenderOptions {
    /**
     * Put before every element's id (default `maa-diagram_`): the IDE's export has
     * `<baseDiv>_<id>` (e.g. `maa-diagram-1_root.ctrl`), so the model id is what follows the
     * first `_` in both.
     */
    readonly idPrefix?: string;
}

export const DEFAULT_ID_PREFIX = 'maa-diagram_';
/** Room around the drawing. */
const MARGIN = 12;

export function renderDiagramSvg(root: SModelRoot, options: SvgRenderOptions = {}): string {
    const geometry = new DiagramGeometry(root);
    const ctx: ViewContext = {
        geometry,
        idPrefix: options.idPrefix ?? DEFAULT_ID_PREFIX,
        renderChildren: (element) => (element.children ?? []).map((c) => renderElement(c, ctx)).filter((n): n is XmlElement => !!n),
    };
    const css = standaloneStylesheet();
    const box = drawingBounds(root, geometry) ?? { x: 0, y: 0, width: 0, height: 0 };
    const view = { x: box.x - MARGIN, y: box.y - MARGIN, width: box.width + 2 * MARGIN, height: box.height + 2 * MARGIN };
    const svg = el(
        'svg',
        {
            xmlns: 'http://www.w3.org/2000/svg',
            id: ctx.idPrefix + root.id,
            // As the IDE's graph view has it (it would add maa-graph-automaton for a graph with diagramType, which the server's has not).
            class: 'sprotty-graph maa-graph',
            version: '1.1',
            viewBox: [view.x, view.y, view.width, view.height].map(num).join(' '),
            width: num(view.width),
            height: num(view.height),
        },
        el('style', {}, `\n${css}`),
        // The stylesheet's `.maa-graph` background as a shape: rasterizers draw no CSS background of an SVG.
        el('rect', { class: 'maa-background', ...view, fill: backgroundOf(css), stroke: 'none' }),
        el('g', { transform: 'scale(1) translate(0,0)' }, ...ctx.renderChildren(root)),
    );
    return `<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n${serialize(svg)}\n`;
}

function renderElement(element: SModelElement, ctx: ViewContext): XmlNode | undefined {
    switch (element.type) {
        case TYPES.component:
            return componentView(element as ComponentNode, ctx);
        case TYPES.port:
            return portView(element as PortNode, ctx);
        case TYPES.state:
            return stateView(element as StateNode, ctx);
        case TYPES.connector:
        case TYPES.transition:
            return edgeView(element as SEdge, ctx);
        case TYPES.valueLabel:
        case TYPES.chipLabel:
            return undefined; // the room of a run's live value and current state: empty without a run
        default:
            return element.type.startsWith('label') ? labelView(element as SLabel, ctx) : genericView(element, ctx);
    }
}

/** The fill of the `.maa-graph` rule's background (white if it has none). */
function backgroundOf(css: string): string {
    return /\.maa-graph\s*\{[^}]*\bbackground:\s*([^;}]+)/.exec(css)?.[1]?.trim() ?? '#ffffff';
}

/** What the drawing covers: every node, port and label, every edge's route, the initial markers. */
function drawingBounds(root: SModelRoot, geometry: DiagramGeometry): Bounds | undefined {
    const all: Array<Bounds | undefined> = [];
    const visit = (element: SModelElement): void => {
        if ('sourceId' in element) {
            const o = geometry.origin(geometry.parentId(element.id));
            for (const p of geometry.route(element as SEdge)) all.push({ x: p.x + o.x, y: p.y + o.y, width: 0, height: 0 });
        } else if (element !== root) {
            const b = geometry.absoluteBounds(element.id);
            all.push(b);
            // The initial marker stands left of the state (x -20..0, y 10..18).
            if (b && (element as Partial<StateNode>).initial) all.push({ x: b.x - 20, y: b.y + 10, width: 20, height: 8 });
        }
        for (const child of element.children ?? []) visit(child);
    };
    visit(root);
    return union(all);
}
