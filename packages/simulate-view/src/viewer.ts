/** The simulator's 3D view: viser in an iframe during a run, a placeholder otherwise. */
import { el } from './dom.js';

export class Viewer {
    readonly element = el('div', { class: 'maa-sim-viewer' });
    private readonly placeholder = el('div', { class: 'maa-sim-placeholder' }, 'The 3D view appears here once the simulation runs.');
    private iframe: HTMLIFrameElement | undefined;

    /** @param url the viser page (endpoints.ts) */
    constructor(private readonly url: string) {
        this.element.append(this.placeholder);
    }

    get shown(): boolean {
        return this.iframe !== undefined;
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
            this.element.replaceChildren(this.iframe);
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
        this.iframe.remove();
        this.iframe = undefined;
        this.element.replaceChildren(this.placeholder);
    }
}
