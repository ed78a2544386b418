/**
 * Fitting a diagram into the canvas. Sprotty's FitToScreen computes the zoom that fits, then
 * clamps it to the zoom limits without moving the scroll position: a diagram that needs a zoom
 * below the minimum (a component with hundreds of subcomponents) ends up outside the canvas and
 * nothing is drawn. Here the clamp comes first and the scroll follows from the clamped zoom.
 * Pure functions, no DOM.
 */
import type { Bounds } from './schema.js';

/**
 * The zoom a new diagram opens at least with (when it does not fit at that zoom, from its top
 * left, ready to scroll): the smallest texts (port names, transition labels, live values: 10.5px)
 * are then drawn at 6.3px or more, names at 7.2px, and the example's architecture still opens
 * whole in a side pane of about 600px. Fit (the tool bar) shows the whole diagram at any zoom.
 */
export const READABLE_ZOOM = 0.6;

/** The smallest font of the diagram's texts, px (sizes.ts of the language server: ports, transitions, values). */
export const SMALLEST_FONT = 10.5;

export interface FitOptions {
    padding: number;
    maxZoom: number;
    minZoom: number;
    /**
     * When set, a diagram that fits only below this zoom is not shrunk to fit: it is shown from its
     * top at the zoom that fits its width (at least this one), readable and ready to scroll.
     */
    readableZoom?: number;
}

export interface FittedViewport {
    scroll: { x: number; y: number };
    zoom: number;
}

/** The smallest box holding every box; undefined for none. */
export function unionBounds(boxes: Iterable<Bounds>): Bounds | undefined {
    let out: Bounds | undefined;
    for (const b of boxes) {
        if (![b.x, b.y, b.width, b.height].every(Number.isFinite)) continue;
        if (!out) {
            out = { ...b };
            continue;
        }
        const x = Math.min(out.x, b.x);
        const y = Math.min(out.y, b.y);
        out = { x, y, width: Math.max(out.x + out.width, b.x + b.width) - x, height: Math.max(out.y + out.height, b.y + b.height) - y };
    }
    return out;
}

/**
 * The viewport that shows `content` in `canvas`: centred and as large as `maxZoom` allows when it
 * fits; otherwise (at `minZoom`, or at a readable zoom, see `readableZoom`) centred along an axis
 * where it fits and from its top/left edge (plus padding) along an axis where it does not.
 */
export function fitViewport(content: Bounds, canvas: { width: number; height: number }, options: FitOptions): FittedViewport {
    const { padding, maxZoom, minZoom } = options;
    const width = Math.max(content.width, 1);
    const height = Math.max(content.height, 1);
    const byWidth = (canvas.width - 2 * padding) / width;
    const fitting = Math.min(byWidth, (canvas.height - 2 * padding) / height);
    const clamp = (z: number): number => Math.min(maxZoom, Math.max(minZoom, Number.isFinite(z) && z > 0 ? z : minZoom));
    const readable = options.readableZoom;
    const zoom = readable !== undefined && !(fitting >= readable) && canvas.width > 0 ? clamp(Math.max(readable, byWidth)) : clamp(fitting);
    const axis = (start: number, size: number, canvasSize: number): number => {
        const visible = canvasSize / zoom;
        return size + (2 * padding) / zoom <= visible ? start + size / 2 - visible / 2 : start - padding / zoom;
    };
    return { zoom, scroll: { x: axis(content.x, width, canvas.width), y: axis(content.y, height, canvas.height) } };
}
