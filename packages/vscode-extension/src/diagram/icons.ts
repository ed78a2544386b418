/**
 * File icons of the family's languages (`contributes.languages[].icon`), drawn here as small
 * SVGs: a component with ports for `.arc`, a class box for `.cd`, a launch triangle for
 * `.arcapp`, a jointed arm for `.ra`, and for a language added to the family later a page with
 * its file extension. Each in a light and a dark theme variant; bin/build.mjs writes them into
 * `icons/` from the language facts (contributions.ts), and the diagram panel's own icon.
 */

/** The colours of one theme variant. */
interface Palette {
    readonly stroke: string;
    readonly fill: string;
    readonly accent: string;
}

const PALETTES: Readonly<Record<'light' | 'dark', Palette>> = {
    light: { stroke: '#2b5d8c', fill: '#dbe9f6', accent: '#2f7d3b' },
    dark: { stroke: '#8cbcf0', fill: '#23364a', accent: '#79c887' },
};

/** The glyph of a language, as SVG elements on a 16×16 canvas. */
type Glyph = (p: Palette, extension: string) => string;

const GLYPHS: Readonly<Record<string, Glyph>> = {
    // A component: a box with an input port on the left and an output port on the right.
    arc: (p) =>
        `<rect x="3.5" y="3.5" width="9" height="9" rx="1" fill="${p.fill}" stroke="${p.stroke}"/>` +
        `<rect x="1.5" y="6.5" width="3" height="3" fill="${p.accent}"/>` +
        `<rect x="11.5" y="6.5" width="3" height="3" fill="${p.stroke}"/>`,
    // A class: a box with a name, an attribute and a method compartment.
    cd: (p) =>
        `<rect x="2.5" y="1.5" width="11" height="13" rx="1" fill="${p.fill}" stroke="${p.stroke}"/>` +
        `<path d="M2.5 5.5h11M2.5 10h11" stroke="${p.stroke}"/>`,
    // An application configuration: what is launched on a platform.
    arcapp: (p) =>
        `<rect x="1.5" y="2.5" width="13" height="11" rx="2" fill="${p.fill}" stroke="${p.stroke}"/>` +
        `<path d="M6 5.5v5l4.5-2.5z" fill="${p.accent}"/>`,
    // A robot arm: base, two links, a gripper.
    ra: (p) =>
        `<path d="M2 14.5h7" stroke="${p.stroke}" stroke-width="1.5"/>` +
        `<path d="M5.5 14V9.5L10 5l3 2.5" fill="none" stroke="${p.stroke}" stroke-width="1.5" stroke-linejoin="round"/>` +
        `<circle cx="5.5" cy="9.5" r="1.6" fill="${p.accent}"/><circle cx="10" cy="5" r="1.6" fill="${p.accent}"/>`,
};

/** A page with a folded corner and the file extension: the icon of a language without a glyph of its own. */
const PAGE: Glyph = (p, extension) =>
    `<path d="M3.5 1.5h6l3 3v10h-9z" fill="${p.fill}" stroke="${p.stroke}"/>` +
    `<text x="8" y="12" font-family="sans-serif" font-size="${extension.length > 3 ? 3.5 : 4.5}" text-anchor="middle" fill="${p.stroke}">${escapeXml(extension)}</text>`;

/** The diagram panel's icon: two components and a connector. */
const DIAGRAM: Glyph = (p) =>
    `<rect x="1.5" y="4.5" width="5" height="7" rx="1" fill="${p.fill}" stroke="${p.stroke}"/>` +
    `<rect x="9.5" y="4.5" width="5" height="7" rx="1" fill="${p.fill}" stroke="${p.stroke}"/>` +
    `<path d="M6.5 8h3" stroke="${p.accent}" stroke-width="1.5"/>`;

function escapeXml(text: string): string {
    return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

function svg(body: string): string {
    return `<svg xmlns="http://www.w3.org/2000/svg" width="16" height="16" viewBox="0 0 16 16">${body}</svg>\n`;
}

/** An icon file to write and its path relative to the extension folder. */
export interface IconFile {
    readonly path: string;
    readonly content: string;
}

/** A language's icon variants as the manifest names them. */
export interface LanguageIcon {
    readonly light: string;
    readonly dark: string;
}

function variants(name: string, glyph: Glyph, label: string): { icon: LanguageIcon; files: IconFile[] } {
    const files = (['light', 'dark'] as const).map((theme) => ({
        path: `icons/${name}-${theme}.svg`,
        content: svg(glyph(PALETTES[theme], label)),
    }));
    return { icon: { light: `./${files[0]?.path}`, dark: `./${files[1]?.path}` }, files };
}

/** The icon files of a language (`id`, first file extension `.x`) and the manifest's `icon` entry. */
export function languageIcon(id: string, extension: string): { icon: LanguageIcon; files: IconFile[] } {
    return variants(id, GLYPHS[id] ?? PAGE, extension.replace(/^\./, ''));
}

/** The diagram panel's icon (`icons/diagram-light.svg`, `icons/diagram-dark.svg`). */
export function diagramIcon(): { icon: LanguageIcon; files: IconFile[] } {
    return variants('diagram', DIAGRAM, '');
}
