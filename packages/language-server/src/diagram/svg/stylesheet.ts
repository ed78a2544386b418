import { DIAGRAM_SVG_CSS } from '../../generated/diagram-svg-css.js';
/**
 * The rules of the diagram stylesheet (styles/diagram-svg.css, which the IDE imports too): the SVG
 * the CLI writes carries them, so it looks like the IDE's Export SVG.
 */
export const IDE_DIAGRAM_CSS: string = DIAGRAM_SVG_CSS;

/**
 * The stylesheet for a standalone SVG: every `var(--name, fallback)` resolved to its fallback.
 * The IDE's export gets that light palette too (it renders outside the dark `.maa-diagram`
 * container), and SVG rasterizers know no custom properties.
 */
export function standaloneStylesheet(css: string = IDE_DIAGRAM_CSS): string {
    return css.replace(/var\(--[\w-]+,\s*([^()]*?)\s*\)/g, '$1');
}
