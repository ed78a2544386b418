/**
 * The simulator's 3D view: viser in an iframe during a run, a placeholder otherwise. A button
 * makes it fill the whole panel (full screen within the panel: a webview may not take the
 * screen) and back; Escape leaves too, when the key reaches the panel (a key pressed inside the
 * viser frame stays in that frame, another site: the button is always there).
 */
import type { Disposable } from './contracts.js';
import { el } from './dom.js';

const ENTER_TITLE = 'Full screen: the 3D view fills the panel (Escape leaves)';

export class Viewer implements Disposable {
    readonly element = el('div', { class: 'maa-sim-viewer', 'data-testid': 'sim-viewer' });
    readonly fullScreenBtn = el(
        'button',
        { type: 'button', class: 'maa-sim-fullscreen', 'data-testid': 'sim-fullscreen', title: ENTER_TITLE, 'aria-pressed': 'false' },
        'Full screen',
    );
    private readonly placeholder = el('div', { class: 'maa-sim-placeholder' }, 'The 3D view appears here once the simulation runs.');
    private iframe: HTMLIFrameElement | undefined;
    private readonly onKey = (e: KeyboardEvent): void => {
        if (e.key === 'Escape' && this.fullScreen) {
            e.preventDefault();
            this.setFullScreen(false);
        }
    };

    /** @param url the viser page (endpoints.ts) */
    constructor(private readonly url: string) {
        this.fullScreenBtn.hidden = true; // until a run shows the view
        this.element.append(this.placeholder, this.fullScreenBtn);
        this.fullScreenBtn.addEventListener('click', () => this.setFullScreen(!this.fullScreen));
        document.addEventListener('keydown', this.onKey);
    }

    get shown(): boolean {
        return this.iframe !== undefined;
    }

    get fullScreen(): boolean {
        return this.element.classList.contains('maa-sim-viewer-full');
    }

    setFullScreen(on: boolean): void {
        this.element.classList.toggle('maa-sim-viewer-full', on);
        this.fullScreenBtn.setAttribute('aria-pressed', String(on));
        this.fullScreenBtn.textContent = on ? 'Leave full screen' : 'Full screen';
        this.fullScreenBtn.title = on ? 'Leave full screen (Escape)' : ENTER_TITLE;
    }

    /** Shows the view, or loads it again. */
    show(): void {
        if (!this.iframe) {
            this.iframe = el('iframe', {
                'data-testid': 'viser-frame',
                class: 'maa-viser-frame',
                title: 'Simulation (viser)',
                src: this.url,
            });
            this.placeholder.replaceWith(this.iframe);
            this.fullScreenBtn.hidden = false;
        } else {
            this.iframe.src = this.url;
        }
    }

    /** Loads a shown view again (nothing when none is shown). */
    reload(): void {
        if (this.iframe) this.iframe.src = this.url;
    }

    hide(): void {
        if (!this.iframe) return;
        this.iframe.replaceWith(this.placeholder);
        this.iframe = undefined;
        this.setFullScreen(false);
        this.fullScreenBtn.hidden = true;
    }

    dispose(): void {
        document.removeEventListener('keydown', this.onKey);
        this.hide();
    }
}
