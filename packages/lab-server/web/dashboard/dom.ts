// The dashboard page's one DOM helper: an element with properties and children (text stays text, never HTML).

/** An element with properties (className, href, type, ...) and children (text is text, never HTML). */
export function el<K extends keyof HTMLElementTagNameMap>(
    tag: K,
    props: Record<string, string | boolean | number> = {},
    ...children: (Node | string)[]
): HTMLElementTagNameMap[K] {
    const node: HTMLElementTagNameMap[K] = document.createElement(tag);
    Object.assign(node, props);
    node.append(...children);
    return node;
}
