/** Tiny DOM helpers. */
export function h<K extends keyof HTMLElementTagNameMap>(
    tag: K,
    props: Partial<Record<string, string>> = {},
    ...children: (Node | string | undefined)[]
): HTMLElementTagNameMap[K] {
    const element = document.createElement(tag);
    for (const [key, value] of Object.entries(props)) {
        if (value === undefined) continue;
        if (key === 'class') element.className = value;
        else element.setAttribute(key, value);
    }
    for (const child of children) if (child !== undefined) element.append(child);
    return element;
}

export function byId<T extends HTMLElement = HTMLElement>(id: string): T {
    const element = document.getElementById(id);
    if (!element) throw new Error(`missing element #${id}`);
    return element as T;
}

export function basename(path: string): string {
    return path.slice(path.lastIndexOf('/') + 1);
}
