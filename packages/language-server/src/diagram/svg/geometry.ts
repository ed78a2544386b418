import type { Bounds, Point, SEdge, SModelElement, SModelRoot } from 'sprotty-protocol';

/**
 * Coordinates of a laid-out diagram model, as Sprotty's client computes them: every element's
 * position is relative to its parent (the graph's children to the graph), an edge's routing
 * points and its labels are in the coordinates of the edge's parent.
 */

interface Entry {
    readonly element: SModelElement;
    readonly parent: SModelElement | undefined;
    /** Where the element's own coordinate system starts, in the graph's coordinates. */
    readonly origin: Point;
}

export class DiagramGeometry {
    private readonly entries = new Map<string, Entry>();

    constructor(root: SModelRoot) {
        this.index(root, undefined, { x: 0, y: 0 });
    }

    private index(element: SModelElement, parent: SModelElement | undefined, parentOrigin: Point): void {
        const position = parent && !isEdge(element) ? ((element as { position?: Point }).position ?? { x: 0, y: 0 }) : { x: 0, y: 0 };
        const origin = { x: parentOrigin.x + position.x, y: parentOrigin.y + position.y };
        this.entries.set(element.id, { element, parent, origin });
        for (const child of element.children ?? []) this.index(child, element, origin);
    }

    element(id: string): SModelElement | undefined {
        return this.entries.get(id)?.element;
    }

    /** The origin of an element's coordinate system in the graph's (an edge shares its parent's). */
    origin(id: string | undefined): Point {
        return (id !== undefined ? this.entries.get(id)?.origin : undefined) ?? { x: 0, y: 0 };
    }

    parentId(id: string): string | undefined {
        return this.entries.get(id)?.parent?.id;
    }

    /** The bounds of a node, port or label in its parent's coordinates. */
    localBounds(id: string): Bounds | undefined {
        const e = this.entries.get(id)?.element as { position?: Point; size?: { width: number; height: number } } | undefined;
        if (!e?.size) return undefined;
        const p = e.position ?? { x: 0, y: 0 };
        return { x: p.x, y: p.y, width: e.size.width, height: e.size.height };
    }

    /** The bounds of a node, port or label in the graph's coordinates. */
    absoluteBounds(id: string): Bounds | undefined {
        const local = this.localBounds(id);
        if (!local) return undefined;
        const o = this.origin(this.parentId(id));
        return { x: local.x + o.x, y: local.y + o.y, width: local.width, height: local.height };
    }

    /**
     * The drawn route of an edge in its parent's coordinates, as Sprotty's PolylineEdgeRouter
     * draws it: from an anchor on the border of its source (towards the first routing point)
     * through the routing points (the first and last left out when they lie within 2 px of the
     * anchors) to an anchor on its target. Empty when an end is missing.
     */
    route(edge: SEdge): Point[] {
        const frame = this.parentId(edge.id);
        const points = edge.routingPoints ?? [];
        const sourceRef = points[0] ?? this.centreIn(edge.targetId, frame);
        const targetRef = points[points.length - 1] ?? this.centreIn(edge.sourceId, frame);
        if (!sourceRef || !targetRef) return [];
        const source = this.anchor(edge.sourceId, sourceRef, frame);
        const target = this.anchor(edge.targetId, targetRef, frame);
        if (!source || !target) return [];
        const inner = points.filter(
            (p, i) =>
                (i > 0 && i < points.length - 1) ||
                (i === 0 && maxDistance(source, p) >= MINIMAL_POINT_DISTANCE) ||
                (i === points.length - 1 && maxDistance(p, target) >= MINIMAL_POINT_DISTANCE),
        );
        return [source, ...inner, target];
    }

    /** The centre of an element, in the coordinates of `frame`. */
    private centreIn(id: string, frame: string | undefined): Point | undefined {
        const b = this.absoluteBounds(id);
        const o = this.origin(frame);
        return b && { x: b.x + b.width / 2 - o.x, y: b.y + b.height / 2 - o.y };
    }

    /** Sprotty's rectangular anchor: where the line from the element's centre to `ref` leaves its bounds (coordinates of `frame`). */
    private anchor(id: string, ref: Point, frame: string | undefined): Point | undefined {
        const b = this.absoluteBounds(id);
        if (!b) return undefined;
        const o = this.origin(frame);
        const bounds = { x: b.x - o.x, y: b.y - o.y, width: b.width, height: b.height };
        return rectangleAnchor(bounds, ref);
    }
}

/** Sprotty's PolylineEdgeRouter option `minimalPointDistance`. */
const MINIMAL_POINT_DISTANCE = 2;

function isEdge(element: SModelElement): boolean {
    return 'sourceId' in element && 'targetId' in element;
}

function maxDistance(a: Point, b: Point): number {
    return Math.max(Math.abs(a.x - b.x), Math.abs(a.y - b.y));
}

const almostEquals = (a: number, b: number): boolean => Math.abs(a - b) < 1e-3;

/** The point of the bounds' border on the line from their centre to `ref` nearest to `ref` (the centre if none). */
export function rectangleAnchor(bounds: Bounds, ref: Point): Point {
    const c = { x: bounds.x + bounds.width / 2, y: bounds.y + bounds.height / 2 };
    let best: Point | undefined;
    let bestDistance = -1;
    const candidate = (x: number, y: number): void => {
        const d = (ref.x - x) ** 2 + (ref.y - y) ** 2;
        if (bestDistance < 0 || d < bestDistance) {
            best = { x, y };
            bestDistance = d;
        }
    };
    const within = (v: number, from: number, size: number): boolean => v >= from && v <= from + size;
    if (!almostEquals(c.y, ref.y)) {
        for (const y of [bounds.y, bounds.y + bounds.height]) {
            const x = (ref.x - c.x) * ((y - c.y) / (ref.y - c.y)) + c.x;
            if (within(x, bounds.x, bounds.width)) candidate(x, y);
        }
    }
    if (!almostEquals(c.x, ref.x)) {
        for (const x of [bounds.x, bounds.x + bounds.width]) {
            const y = (ref.y - c.y) * ((x - c.x) / (ref.x - c.x)) + c.y;
            if (within(y, bounds.y, bounds.height)) candidate(x, y);
        }
    }
    return best ?? c;
}

/** The smallest bounds holding all the given ones (undefined for none). */
export function union(all: ReadonlyArray<Bounds | undefined>): Bounds | undefined {
    const present = all.filter((b): b is Bounds => b !== undefined);
    if (present.length === 0) return undefined;
    const x = Math.min(...present.map((b) => b.x));
    const y = Math.min(...present.map((b) => b.y));
    const right = Math.max(...present.map((b) => b.x + b.width));
    const bottom = Math.max(...present.map((b) => b.y + b.height));
    return { x, y, width: right - x, height: bottom - y };
}
