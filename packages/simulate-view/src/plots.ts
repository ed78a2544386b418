/** The live plot of a watched port: a sparkline of its recent numeric values (data in plot.ts). */
import { SVG_NS, el } from './dom.js';
import { SampleWindow, sparklinePath } from './plot.js';

const WIDTH = 120;
const HEIGHT = 24;
const CAPACITY = 200;

export class Sparkline {
    readonly element = el('div', { class: 'maa-port-plot' });
    readonly samples = new SampleWindow(CAPACITY);
    private readonly path = document.createElementNS(SVG_NS, 'path');

    constructor() {
        const svg = document.createElementNS(SVG_NS, 'svg');
        svg.setAttribute('width', String(WIDTH));
        svg.setAttribute('height', String(HEIGHT));
        svg.setAttribute('class', 'maa-sparkline');
        svg.appendChild(this.path);
        this.element.appendChild(svg);
    }

    /** Draws the samples. */
    draw(): void {
        this.path.setAttribute('d', sparklinePath(this.samples.samples(), WIDTH, HEIGHT));
    }

    /** Removes the drawing (the samples stay). */
    erase(): void {
        if (this.path.getAttribute('d')) this.path.removeAttribute('d');
    }
}
