/**
 * A small XML reader for the SVG documents the tests check (elements, attributes, text; the
 * prolog, comments and CDATA skipped): it fails on a tag that is not closed in order, so a
 * document it reads is well formed in the ways the checks rely on.
 */

export interface SvgNode {
    name: string;
    attrs: Record<string, string>;
    children: SvgNode[];
    /** The element's own text (not that of its children), entities decoded. */
    text: string;
    parent?: SvgNode;
}

const TOKEN =
    /<\?[\s\S]*?\?>|<!--[\s\S]*?-->|<!\[CDATA\[[\s\S]*?\]\]>|<\/([\w:.-]+)\s*>|<([\w:.-]+)((?:\s+[\w:.-]+\s*=\s*"[^"]*")*)\s*(\/?)>|([^<]+)/g;
const ATTR = /([\w:.-]+)\s*=\s*"([^"]*)"/g;

function decode(text: string): string {
    return text
        .replace(/&lt;/g, '<')
        .replace(/&gt;/g, '>')
        .replace(/&quot;/g, '"')
        .replace(/&#39;|&apos;/g, "'")
        .replace(/&#(\d+);/g, (_, n: string) => String.fromCodePoint(Number(n)))
        .replace(/&amp;/g, '&');
}

export function parseSvg(xml: string): SvgNode {
    const document: SvgNode = { name: '#document', attrs: {}, children: [], text: '' };
    let current = document;
    let consumed = 0;
    for (const m of xml.matchAll(TOKEN)) {
        if (m.index !== consumed) throw new Error(`unreadable XML at ${consumed}: ${xml.slice(consumed, consumed + 40)}`);
        consumed = m.index + m[0].length;
        const [, close, open, attrText, selfClosing, text] = m;
        if (close) {
            if (close !== current.name) throw new Error(`</${close}> closes <${current.name}>`);
            current = current.parent!;
        } else if (open) {
            const attrs: Record<string, string> = {};
            for (const a of (attrText ?? '').matchAll(ATTR)) attrs[a[1]!] = decode(a[2]!);
            const node: SvgNode = { name: open, attrs, children: [], text: '', parent: current };
            current.children.push(node);
            if (!selfClosing) current = node;
        } else if (text !== undefined) {
            current.text += decode(text);
        }
    }
    if (consumed !== xml.length || current !== document) throw new Error(`unclosed <${current.name}>`);
    const root = document.children.find((c) => c.name === 'svg');
    if (!root) throw new Error('no <svg> element');
    return root;
}

export function* descendants(node: SvgNode): Generator<SvgNode> {
    for (const child of node.children) {
        yield child;
        yield* descendants(child);
    }
}

/** The elements with a class. */
export function withClass(root: SvgNode, cls: string): SvgNode[] {
    return [...descendants(root)].filter((n) => (n.attrs['class'] ?? '').split(/\s+/).includes(cls));
}

/** The model element ids of a diagram SVG: each element id after its prefix (`<baseDiv>_`). */
export function modelIds(root: SvgNode): string[] {
    return [root, ...descendants(root)]
        .map((n) => n.attrs['id'])
        .filter((id): id is string => id?.includes('_') === true)
        .map((id) => id.slice(id.indexOf('_') + 1));
}
