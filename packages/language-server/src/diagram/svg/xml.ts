/** A small SVG element tree and its serialization (no DOM: the renderer runs in Node and in workers). */

export type AttrValue = string | number | undefined;

export interface XmlElement {
    readonly name: string;
    readonly attrs: Readonly<Record<string, AttrValue>>;
    readonly children: readonly XmlNode[];
}

export type XmlNode = XmlElement | string;

/** An element; attributes whose value is undefined are left out, children that are undefined too. */
export function el(
    name: string,
    attrs: Readonly<Record<string, AttrValue>> = {},
    ...children: ReadonlyArray<XmlNode | undefined>
): XmlElement {
    return { name, attrs, children: children.filter((c): c is XmlNode => c !== undefined) };
}

/** A class attribute from the names whose flag is set, in the order given. */
export function classes(flags: Readonly<Record<string, boolean | undefined>>): string {
    return Object.keys(flags)
        .filter((k) => flags[k])
        .join(' ');
}

/** A coordinate as SVG text: at most three decimals, no trailing zeros. */
export function num(n: number): string {
    const rounded = Math.round(n * 1000) / 1000;
    return Object.is(rounded, -0) ? '0' : String(rounded);
}

function escapeText(text: string): string {
    return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
}

function escapeAttr(text: string): string {
    return escapeText(text).replace(/"/g, '&quot;');
}

/**
 * The element as XML text. Groups put each child on a line of its own (readable, and a text
 * element's content stays as it is: whitespace inside `<text>` would be drawn).
 */
export function serialize(node: XmlNode): string {
    if (typeof node === 'string') return escapeText(node);
    const attrs = Object.entries(node.attrs)
        .filter(([, v]) => v !== undefined)
        .map(([k, v]) => ` ${k}="${escapeAttr(typeof v === 'number' ? num(v) : String(v))}"`)
        .join('');
    if (node.children.length === 0) return `<${node.name}${attrs}/>`;
    const separator = node.name === 'g' || node.name === 'svg' ? '\n' : '';
    const inner = node.children.map(serialize).join(separator);
    return `<${node.name}${attrs}>${separator}${inner}${separator}</${node.name}>`;
}
