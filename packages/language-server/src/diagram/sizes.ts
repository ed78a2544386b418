import type { Dimension } from 'sprotty-protocol';
import { TYPES } from './model.js';

/**
 * Size estimates for texts, so ELK can lay out the diagram in the server (no client-side text
 * measuring round trip). The client (packages/ide-web, diagram.css) draws with a sans-serif
 * system font at 12px: names of components and states bold, component types italic, port and
 * transition labels at 10.5px, behavior badges at 9px in a pill. Widths come from per-character
 * advance widths of a wide sans-serif font: a label that is too wide only leaves space, one that
 * is too narrow overlaps.
 */
export const PORT_SIZE = 10;
export const LINE_HEIGHT = 16;

// Advance widths of ASCII 32..126 (space to tilde) in 1/1000 em, of DejaVu Sans and DejaVu Sans
// Bold (their hmtx tables): the sans-serif Linux browsers fall back to, and wider than
// Helvetica, Arial, Segoe UI and San Francisco, so labels fit in those too.
const REGULAR = [
    318, 401, 460, 838, 636, 950, 780, 275, 390, 390, 500, 838, 318, 361, 318, 337, 636, 636, 636, 636, 636, 636, 636, 636, 636, 636, 337,
    337, 838, 838, 838, 531, 1000, 684, 686, 698, 770, 632, 575, 775, 752, 295, 295, 656, 557, 863, 748, 787, 603, 787, 695, 635, 611, 732,
    684, 989, 685, 611, 685, 390, 337, 390, 838, 500, 500, 613, 635, 550, 635, 615, 352, 635, 634, 278, 278, 579, 278, 974, 634, 612, 635,
    635, 411, 521, 392, 634, 592, 818, 592, 592, 525, 636, 337, 636, 838,
];
const BOLD = [
    348, 456, 521, 838, 696, 1002, 872, 306, 457, 457, 523, 838, 380, 415, 380, 365, 696, 696, 696, 696, 696, 696, 696, 696, 696, 696, 400,
    400, 838, 838, 838, 580, 1000, 774, 762, 734, 830, 683, 683, 821, 837, 372, 372, 775, 637, 995, 837, 850, 733, 850, 770, 720, 682, 812,
    774, 1103, 771, 724, 725, 457, 365, 457, 838, 500, 500, 675, 716, 593, 716, 678, 435, 716, 712, 343, 343, 665, 343, 1042, 712, 687, 716,
    716, 493, 595, 478, 712, 652, 924, 645, 652, 582, 712, 365, 712, 838,
];

export interface Font {
    readonly size: number;
    readonly bold?: boolean;
}

/** The client's fonts per label type. */
export const FONTS = {
    name: { size: 12, bold: true },
    type: { size: 12 },
    badge: { size: 9 },
    port: { size: 10.5 },
    state: { size: 12, bold: true },
    transition: { size: 10.5 },
} as const satisfies Record<string, Font>;

/** The estimated advance width of a text in a font. */
export function textWidth(text: string, font: Font): number {
    const table = font.bold ? BOLD : REGULAR;
    let units = 0;
    for (const ch of text) {
        const code = ch.codePointAt(0)!;
        // Outside ASCII (the ellipsis, umlauts, CJK): a full em, to be safe.
        units += code >= 32 && code <= 126 ? table[code - 32]! : 1000;
    }
    return (units / 1000) * font.size;
}

/** The label box of a text: its width plus a little room, one line high. */
export function textSize(text: string, font: Font = FONTS.type): Dimension {
    return { width: Math.ceil(textWidth(text, font)) + 4, height: font.size <= 10.5 ? 14 : LINE_HEIGHT };
}

/** The label box of a label type (the badge's pill has room around its text). */
export function labelSize(type: string, text: string): Dimension {
    switch (type) {
        case TYPES.nameLabel:
            return textSize(text, FONTS.name);
        case TYPES.badgeLabel:
            return { width: Math.ceil(textWidth(badgeText(text), FONTS.badge)) + 14, height: 14 };
        case TYPES.portLabel:
            return textSize(text, FONTS.port);
        case TYPES.stateLabel:
            return textSize(text, FONTS.state);
        case TYPES.transitionLabel:
            return textSize(text, FONTS.transition);
        case TYPES.valueLabel:
            return { ...VALUE_SIZE };
        case TYPES.chipLabel:
            return chipSize(text);
        case TYPES.behaviorLabel:
            return textSize(text, FONTS.port);
        default:
            return textSize(text, FONTS.type);
    }
}

/**
 * The room of a live value beside a port: the client's value pill (monospace 10.5px, about 6.4px
 * a character) holds seven characters (`-12.345`, `GOLDEN`); a longer value is cut short there,
 * whole in its tooltip. Narrow, so that the example's architecture still fits a side pane.
 */
export const VALUE_SIZE: Dimension = { width: 52, height: 14 };

/** The text of the current-state chip the client draws during a run (`▶ ` and the state's path). */
export function chipText(state: string): string {
    return `▶ ${state}`;
}

/** The room of the current-state chip: the widest state's chip (`text` is that state's path), 10.5px with padding. */
export function chipSize(text: string): Dimension {
    return { width: Math.max(48, Math.ceil(textWidth(chipText(text), FONTS.transition)) + 12), height: 14 };
}

/** The text the client shows in a badge (its BADGE_TEXT). */
function badgeText(kind: string): string {
    return kind === 'robotarm' ? 'RobotArm' : kind;
}

/** The widest a transition label may get before it is shortened. */
export const MAX_TRANSITION_LABEL_WIDTH = 260;

/**
 * A transition label that fits `max` pixels: as written if it fits; else a block action loses
 * its braces (`/ { a = 1; }` becomes `/ a = 1;`), then the action is cut short with an ellipsis
 * (`[guard] / a = 1; b = …`), and if trigger and guard alone are too wide, the whole text is.
 */
export function shortenTransitionLabel(text: string, max = MAX_TRANSITION_LABEL_WIDTH): string {
    const fits = (t: string): boolean => textSize(t, FONTS.transition).width <= max;
    if (fits(text)) return text;
    const slash = text.indexOf(' / ', guardEnd(text));
    if (slash < 0) return cut(text, fits);
    const head = `${text.slice(0, slash)} / `;
    const action = text.slice(slash + 3).replace(/^\{\s*([\s\S]*?)\s*\}$/, '$1');
    if (fits(head + action)) return head + action;
    if (fits(`${head}…`)) return head + cut(action, (t) => fits(head + t));
    return cut(text, fits);
}

/** Where the guard (`[...]`, after an optional trigger) of a transition label ends, 0 without one. */
function guardEnd(text: string): number {
    const open = text.search(/^(\S+ )?\[/) === 0 ? text.indexOf('[') : -1;
    if (open < 0) return 0;
    let depth = 0;
    for (let i = open; i < text.length; i++) {
        if (text[i] === '[') depth++;
        else if (text[i] === ']' && --depth === 0) return i + 1;
    }
    return 0;
}

/** The longest prefix of `text` plus `…` that `fits`, cut after a word if that drops only a few characters. */
function cut(text: string, fits: (t: string) => boolean): string {
    let n = text.length;
    while (n > 0 && !fits(`${text.slice(0, n).trimEnd()}…`)) n--;
    const space = text.lastIndexOf(' ', n);
    const at = space > n / 2 && space >= n - 6 ? space : n;
    return `${text.slice(0, at).trimEnd()}…`;
}
