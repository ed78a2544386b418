/**
 * The room of the 3D view: a drag handle between the view and the port table sets the view's
 * share of the panel's width (arrow keys move it too, a double click goes back to the default),
 * and the share is kept in the host's view state, so a reopened panel or a reloaded webview keeps
 * it. The pure parts (clamping, the stored state) are exported for tests.
 */
import type { Disposable, ViewState } from './contracts.js';
import { el } from './dom.js';

/** The 3D view's default share of the width. */
export const DEFAULT_VIEW_FRACTION = 0.55;
/** Neither side gets less than this share. */
export const MIN_FRACTION = 0.15;
export const MAX_FRACTION = 0.85;
/** One arrow key press moves the handle this much. */
export const KEY_STEP = 0.05;
/** The key of the share in the host's view state. */
export const LAYOUT_STATE_KEY = 'simulate.layout';

/** A share clamped to what both sides need; anything that is not a number is the default. */
export function clampFraction(fraction: unknown): number {
    if (typeof fraction !== 'number' || !Number.isFinite(fraction)) return DEFAULT_VIEW_FRACTION;
    return Math.min(MAX_FRACTION, Math.max(MIN_FRACTION, fraction));
}

/** The share for a pointer at `x` over a box from `left` of `width` pixels. */
export function fractionAt(x: number, left: number, width: number): number {
    if (!(width > 0)) return DEFAULT_VIEW_FRACTION;
    return clampFraction((x - left) / width);
}

/** The share stored in the view state (`{viewFraction}`); the default when there is none or it is bad. */
export function storedFraction(state: unknown): number {
    if (!state || typeof state !== 'object') return DEFAULT_VIEW_FRACTION;
    return clampFraction((state as Record<string, unknown>)['viewFraction']);
}

/** The box holding the 3D view, the handle and the port table, side by side. */
export class SplitLayout implements Disposable {
    readonly element: HTMLElement;
    readonly handle = el('div', {
        class: 'maa-sim-split',
        role: 'separator',
        tabindex: '0',
        'aria-orientation': 'vertical',
        'aria-label': 'Resize the 3D view',
        title: 'Drag to resize the 3D view (arrow keys; double click: default)',
        'data-testid': 'sim-split',
    });
    private fraction: number;

    constructor(
        private readonly view: HTMLElement,
        table: HTMLElement,
        private readonly state?: ViewState,
    ) {
        this.element = el('div', { class: 'maa-sim-body' }, view, this.handle, table);
        this.fraction = storedFraction(state?.get(LAYOUT_STATE_KEY));
        this.apply();
        this.handle.addEventListener('pointerdown', (e) => this.drag(e));
        this.handle.addEventListener('keydown', (e) => {
            const step = e.key === 'ArrowLeft' ? -KEY_STEP : e.key === 'ArrowRight' ? KEY_STEP : 0;
            if (step === 0) return;
            e.preventDefault();
            this.set(this.fraction + step);
        });
        this.handle.addEventListener('dblclick', () => this.set(DEFAULT_VIEW_FRACTION));
    }

    /** The 3D view's share of the width. */
    get viewFraction(): number {
        return this.fraction;
    }

    set(fraction: number): void {
        this.fraction = clampFraction(fraction);
        this.apply();
        this.state?.set(LAYOUT_STATE_KEY, { viewFraction: this.fraction });
    }

    dispose(): void {
        this.element.classList.remove('maa-sim-resizing');
    }

    private apply(): void {
        this.view.style.flexBasis = `${(this.fraction * 100).toFixed(2)}%`;
        this.handle.setAttribute('aria-valuenow', String(Math.round(this.fraction * 100)));
    }

    /** Follows the pointer until it is released; the iframe must not swallow the moves meanwhile. */
    private drag(start: PointerEvent): void {
        if (start.button !== 0) return;
        start.preventDefault();
        this.handle.setPointerCapture(start.pointerId);
        this.element.classList.add('maa-sim-resizing');
        const move = (e: PointerEvent): void => {
            const box = this.element.getBoundingClientRect();
            this.fraction = fractionAt(e.clientX, box.left, box.width);
            this.apply();
        };
        const end = (): void => {
            this.handle.removeEventListener('pointermove', move);
            this.handle.removeEventListener('pointerup', end);
            this.handle.removeEventListener('pointercancel', end);
            this.element.classList.remove('maa-sim-resizing');
            this.set(this.fraction);
        };
        this.handle.addEventListener('pointermove', move);
        this.handle.addEventListener('pointerup', end);
        this.handle.addEventListener('pointercancel', end);
    }
}
