/** DOM helpers of the simulate panel. */

/** An element with attributes (`class` sets the class name) and children. */
export function el<K extends keyof HTMLElementTagNameMap>(
    tag: K,
    attrs: Record<string, string> = {},
    ...children: (Node | string)[]
): HTMLElementTagNameMap[K] {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) {
        if (k === 'class') e.className = v;
        else e.setAttribute(k, v);
    }
    e.append(...children);
    return e;
}

export const SVG_NS = 'http://www.w3.org/2000/svg';

export function errorText(e: unknown): string {
    return e instanceof Error ? e.message : String(e);
}
