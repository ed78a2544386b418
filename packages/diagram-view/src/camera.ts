/**
 * The diagram's viewport operations over Sprotty's dispatcher: fit, zoom around the middle,
 * remember and restore a viewport across a new model, and bring an element into view.
 */
import type { IActionDispatcher } from 'sprotty';
import { CenterAction, GetViewportAction, SetViewportAction, type Action, type Viewport, type ViewportResult } from 'sprotty-protocol';
import { ZOOM_LIMITS } from './container.js';
import { absoluteBounds, boundsInside, visibleArea, type SchemaElement } from './schema.js';
import { fitViewport, unionBounds } from './viewport.js';

export class Camera {
    private remembered: Viewport | undefined;

    /** `dispatch` sends an action of the diagram's own (not taken for a user's selection). */
    constructor(
        private readonly dispatcher: IActionDispatcher,
        private readonly dispatch: (action: Action) => Promise<void>,
    ) {}

    /** Remembers the current viewport, for {@link restore} after the next model. */
    async remember(): Promise<void> {
        try {
            this.remembered = (await this.dispatcher.request<ViewportResult>(GetViewportAction.create())).viewport;
        } catch {
            this.remembered = undefined;
        }
    }

    /** Sets the remembered viewport on the new model (if one was remembered) and forgets it. */
    restore(root: SchemaElement): void {
        const vp = this.remembered;
        this.remembered = undefined;
        if (vp) void this.dispatch(SetViewportAction.create(root.id, vp, { animate: false }));
    }

    forget(): void {
        this.remembered = undefined;
    }

    /**
     * Fits the diagram into the canvas (viewport.ts: also diagrams too large for the minimum zoom).
     * False when the canvas has no size yet (a webview not laid out, a hidden pane): nothing is
     * done then, and the caller fits again once it has one.
     */
    async fit(root: SchemaElement, maxZoom: number, animate: boolean, readableZoom?: number): Promise<boolean | Viewport> {
        const content = unionBounds((root.children ?? []).map((c) => absoluteBounds(root, c.id)).filter((b) => b !== undefined));
        if (!content) return true;
        try {
            const { canvasBounds } = await this.dispatcher.request<ViewportResult>(GetViewportAction.create());
            if (!(canvasBounds.width > 0 && canvasBounds.height > 0)) return false;
            const viewport = fitViewport(content, canvasBounds, { padding: 20, maxZoom, minZoom: ZOOM_LIMITS.min, readableZoom });
            await this.dispatch(SetViewportAction.create(root.id, viewport, { animate }));
            return viewport;
        } catch (e) {
            console.warn('diagram fit:', e);
        }
        return true;
    }

    /** Whether the current viewport is (about) `expected`. */
    async shows(expected: Viewport): Promise<boolean> {
        try {
            const { viewport } = await this.dispatcher.request<ViewportResult>(GetViewportAction.create());
            const near = (a: number, b: number, d: number): boolean => Math.abs(a - b) <= d;
            return (
                near(viewport.zoom, expected.zoom, 0.01) &&
                near(viewport.scroll.x, expected.scroll.x, 2) &&
                near(viewport.scroll.y, expected.scroll.y, 2)
            );
        } catch {
            return true;
        }
    }

    /** Zooms by `factor` around the middle of the canvas, within the zoom limits. */
    async zoomBy(root: SchemaElement, factor: number): Promise<void> {
        try {
            const { viewport, canvasBounds } = await this.dispatcher.request<ViewportResult>(GetViewportAction.create());
            const zoom = Math.min(ZOOM_LIMITS.max, Math.max(ZOOM_LIMITS.min, viewport.zoom * factor));
            const cx = viewport.scroll.x + canvasBounds.width / 2 / viewport.zoom;
            const cy = viewport.scroll.y + canvasBounds.height / 2 / viewport.zoom;
            const scroll = { x: cx - canvasBounds.width / 2 / zoom, y: cy - canvasBounds.height / 2 / zoom };
            await this.dispatch(SetViewportAction.create(root.id, { scroll, zoom }, { animate: true }));
        } catch (e) {
            console.warn('diagram zoom:', e);
        }
    }

    /** Centers the element unless it is fully visible already. */
    async reveal(root: SchemaElement, id: string): Promise<void> {
        try {
            const res = await this.dispatcher.request<ViewportResult>(GetViewportAction.create());
            const b = absoluteBounds(root, id);
            if (b && boundsInside(b, visibleArea(res.viewport, res.canvasBounds))) return;
        } catch {
            /* center anyway */
        }
        await this.dispatch(CenterAction.create([id], { animate: true, retainZoom: true }));
    }
}
