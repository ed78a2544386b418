import type { ELK, ElkExtendedEdge, ElkLabel, ElkNode, ElkPort, ElkPrimitiveEdge, LayoutOptions } from 'elkjs/lib/elk-api.js';

/**
 * ELK with a memory of its last layouts (issue 18: keystroke → diagram). ELK's layered layout of
 * a large diagram takes most of an update's time, while most edits (an expression, a name that
 * keeps the boxes' sizes, a comment) leave the graph ELK sees as it was. The key of a layout is
 * that graph with its ids replaced by their positions in the graph (element order, sizes,
 * options, ports, edges with their ends, edge label sizes; no label texts), so a renamed
 * instance whose box keeps its size hits too; a hit gets the remembered positions, mapped onto
 * the new graph's ids element by element. ELK is deterministic, so a hit is the layout ELK
 * would compute (ids do not steer ELK's layered layout: model order and sizes do).
 */
export class CachingElk {
    private readonly cache = new Map<string, ElkNode>();

    constructor(
        private readonly elk: ELK,
        private readonly capacity = 8,
    ) {}

    async layout(graph: ElkNode): Promise<ElkNode> {
        const key = layoutKey(graph);
        const known = this.cache.get(key);
        if (known) {
            // Most recently used last.
            this.cache.delete(key);
            this.cache.set(key, known);
            return renamed(structuredClone(known), graph);
        }
        const result = await this.elk.layout(graph);
        this.cache.set(key, structuredClone(result));
        while (this.cache.size > this.capacity) this.cache.delete(this.cache.keys().next().value as string);
        return result;
    }

    /** How many layouts are remembered (for tests). */
    get size(): number {
        return this.cache.size;
    }
}

type Edge = ElkExtendedEdge & Partial<Pick<ElkPrimitiveEdge, 'source' | 'target' | 'sourcePort' | 'targetPort'>>;

/** The graph as a string, ids replaced by their order of appearance, label texts left out. */
export function layoutKey(graph: ElkNode): string {
    const ids = new Map<string, number>();
    const number = (id: string | undefined): number | string => {
        if (id === undefined) return '';
        let n = ids.get(id);
        if (n === undefined) {
            n = ids.size;
            ids.set(id, n);
        }
        return n;
    };
    // First every element's id in tree order, so edges name their ends by those numbers.
    const collect = (node: ElkNode): void => {
        number(node.id);
        for (const p of node.ports ?? []) number(p.id);
        for (const c of node.children ?? []) collect(c);
    };
    collect(graph);
    const options = (o: LayoutOptions | undefined): string => (o ? JSON.stringify(o) : '');
    const box = (e: { width?: number; height?: number; x?: number; y?: number }): string =>
        `${e.width ?? ''},${e.height ?? ''},${e.x ?? ''},${e.y ?? ''}`;
    const labels = (ls: ElkLabel[] | undefined): string => (ls ?? []).map((l) => `L${box(l)}${options(l.layoutOptions)}`).join('');
    const ports = (ps: ElkPort[] | undefined): string =>
        (ps ?? []).map((p) => `P${number(p.id)}${box(p)}${options(p.layoutOptions)}${labels(p.labels)}`).join('');
    const edges = (es: Edge[] | undefined): string =>
        (es ?? [])
            .map((e) => {
                const ends = [...(e.sources ?? []), e.source, e.sourcePort, '>', ...(e.targets ?? []), e.target, e.targetPort];
                return `E${ends.map((id) => (id === '>' ? '>' : number(id))).join(',')}${options(e.layoutOptions)}${labels(e.labels)}`;
            })
            .join('');
    const node = (n: ElkNode): string =>
        `N${number(n.id)}${box(n)}${options(n.layoutOptions)}${labels(n.labels)}${ports(n.ports)}[${(n.children ?? []).map(node).join('')}]${edges(n.edges as Edge[] | undefined)}`;
    return node(graph);
}

type Section = { id?: string; incomingShape?: string; outgoingShape?: string; incomingSections?: string[]; outgoingSections?: string[] };
type LaidOutEdge = Edge & { container?: string; sections?: Section[] };

/**
 * The remembered layout with the ids (and label texts) of `graph`, which has the same structure:
 * element by element, then the references to ids ELK adds (edge containers, section ends, sections).
 */
function renamed(layout: ElkNode, graph: ElkNode): ElkNode {
    const ids = new Map<string, string>();
    const rename = (to: { id?: string }, from: { id?: string } | undefined): void => {
        if (to.id !== undefined && from?.id !== undefined) ids.set(to.id, from.id);
        if (from?.id !== undefined) to.id = from.id;
    };
    const labels = (to: ElkLabel[] | undefined, from: ElkLabel[] | undefined): void => {
        (to ?? []).forEach((l, i) => {
            rename(l, from?.[i]);
            if (from?.[i]) l.text = from[i].text;
        });
    };
    const edges: LaidOutEdge[] = [];
    const node = (to: ElkNode, from: ElkNode): void => {
        rename(to, from);
        labels(to.labels, from.labels);
        (to.ports ?? []).forEach((p, i) => {
            rename(p, from.ports?.[i]);
            labels(p.labels, from.ports?.[i]?.labels);
        });
        (to.children ?? []).forEach((c, i) => {
            const f = from.children?.[i];
            if (f) node(c, f);
        });
        ((to.edges ?? []) as LaidOutEdge[]).forEach((e, i) => {
            const f = (from.edges as Edge[] | undefined)?.[i];
            if (!f) return;
            const old = e.id;
            rename(e, f);
            Object.assign(e, { sources: f.sources, targets: f.targets });
            for (const k of ['source', 'target', 'sourcePort', 'targetPort'] as const) if (f[k] !== undefined) e[k] = f[k];
            labels(e.labels, f.labels);
            // ELK names sections after their edge.
            for (const section of e.sections ?? []) {
                if (section.id?.startsWith(old)) {
                    const id = f.id + section.id.slice(old.length);
                    ids.set(section.id, id);
                    section.id = id;
                }
            }
            edges.push(e);
        });
    };
    node(layout, graph);
    const map = (id: string | undefined): string | undefined => (id === undefined ? undefined : (ids.get(id) ?? id));
    for (const e of edges) {
        if (e.container !== undefined) e.container = map(e.container);
        for (const section of e.sections ?? []) {
            if (section.incomingShape !== undefined) section.incomingShape = map(section.incomingShape);
            if (section.outgoingShape !== undefined) section.outgoingShape = map(section.outgoingShape);
            if (section.incomingSections) section.incomingSections = section.incomingSections.map((s) => map(s) ?? s);
            if (section.outgoingSections) section.outgoingSections = section.outgoingSections.map((s) => map(s) ?? s);
        }
    }
    return layout;
}
