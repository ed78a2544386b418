/**
 * The pointer and wheel input of a time-based drawing (plots, state timeline): the wheel zooms
 * around the pointer's time, a drag pans, a click (no drag) points at its time (the cursor, and the
 * transition taken last by then: PanelContext.pointAt), or does what the panel's `click` says for
 * the element under the pointer.
 */
import { tOf } from '../timeline/window.js';
import type { PanelContext } from './context.js';

/** A pointer that moved less than this many pixels clicked. */
const CLICK_SLOP = 4;

export function attachTimeInput(target: HTMLElement | SVGElement, ctx: PanelContext, click?: (ev: MouseEvent, t: number) => boolean): void {
    const width = (): number => target.getBoundingClientRect().width;
    const timeAt = (clientX: number): number => {
        const r = target.getBoundingClientRect();
        return tOf(clientX - r.left, ctx.window.span(ctx.store.start, ctx.store.end), r.width);
    };
    target.addEventListener('wheel', (ev) => {
        const e = ev as WheelEvent;
        e.preventDefault();
        const span = ctx.window.span(ctx.store.start, ctx.store.end);
        ctx.window.zoom(span, Math.exp(e.deltaY / 300), timeAt(e.clientX));
        ctx.redraw();
    });
    let drag: { x: number; moved: boolean; span: { t0: number; t1: number } } | undefined;
    target.addEventListener('pointerdown', (ev) => {
        const e = ev as PointerEvent;
        if (e.button !== 0) return;
        drag = { x: e.clientX, moved: false, span: ctx.window.span(ctx.store.start, ctx.store.end) };
    });
    target.addEventListener('pointermove', (ev) => {
        const e = ev as PointerEvent;
        if (!drag) return;
        const dx = e.clientX - drag.x;
        if (!drag.moved && Math.abs(dx) < CLICK_SLOP) return;
        if (!drag.moved) target.setPointerCapture?.(e.pointerId); // only a drag: a click keeps its target
        drag.moved = true;
        const w = width();
        if (w > 0) ctx.window.pan(drag.span, (-dx / w) * (drag.span.t1 - drag.span.t0));
        ctx.redraw();
    });
    target.addEventListener('pointerup', (ev) => {
        const e = ev as PointerEvent;
        const was = drag;
        drag = undefined;
        if (!was || was.moved) return;
        const t = timeAt(e.clientX);
        if (click?.(e, t)) return;
        ctx.pointAt(t);
    });
    target.addEventListener('pointercancel', () => {
        drag = undefined;
    });
}
