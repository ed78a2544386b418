// CachingElk: a graph ELK has laid out before, up to ids and label texts, gets the remembered
// layout under its own ids (the layout ELK computes for it); any other change is laid out anew.
import { describe, expect, test } from 'vitest';
import type { ElkNode } from 'elkjs/lib/elk-api.js';
import { createElk } from '../src/diagram/layout.js';
import { CachingElk, layoutKey } from '../src/diagram/layout-cache.js';

/** Two nodes with a port each and an edge between, ids from `name`. */
function graph(name: string, width = 60): ElkNode {
    return {
        id: 'g',
        layoutOptions: { 'org.eclipse.elk.algorithm': 'org.eclipse.elk.layered', 'org.eclipse.elk.randomSeed': '1' },
        children: [
            { id: `${name}`, width, height: 40, ports: [{ id: `${name}:o`, width: 8, height: 8 }] },
            { id: 'b', width: 60, height: 40, ports: [{ id: 'b:i', width: 8, height: 8 }] },
            { id: 'c', width: 50, height: 30 },
        ],
        edges: [
            { id: `e:${name}`, sources: [`${name}:o`], targets: ['b:i'], labels: [{ id: `l:${name}`, text: name, width: 20, height: 10 }] },
            { id: 'e2', sources: ['b'], targets: ['c'] },
        ],
    };
}

/** Positions and routes by element id. */
function geometry(n: ElkNode): unknown {
    return JSON.parse(JSON.stringify(n, (k, v) => (k === 'layoutOptions' || k === '$H' ? undefined : v)));
}

describe('CachingElk', () => {
    test('a renamed graph gets the remembered layout under its own ids, as ELK lays it out', async () => {
        const cached = new CachingElk(createElk());
        await cached.layout(graph('a'));
        const hit = await cached.layout(graph('a2'));
        expect(cached.size).toBe(1);
        expect(hit.children?.[0]?.id).toBe('a2');
        expect(hit.edges?.[0]).toMatchObject({ id: 'e:a2', sources: ['a2:o'], targets: ['b:i'], labels: [{ id: 'l:a2', text: 'a2' }] });
        const fresh = await createElk().layout(graph('a2'));
        expect(geometry(hit)).toEqual(geometry(fresh));
    });

    test('a changed size, edge or order is laid out anew', async () => {
        const cached = new CachingElk(createElk());
        await cached.layout(graph('a'));
        await cached.layout(graph('a', 120));
        expect(cached.size).toBe(2);
        const rerouted = graph('a');
        rerouted.edges![1] = { id: 'e2', sources: ['c'], targets: ['b'] };
        expect(layoutKey(rerouted)).not.toBe(layoutKey(graph('a')));
        const reordered = graph('a');
        reordered.children!.reverse();
        expect(layoutKey(reordered)).not.toBe(layoutKey(graph('a')));
        const wide = await cached.layout(graph('a', 120));
        expect(wide.children?.[0]?.width).toBe(120);
        expect(cached.size).toBe(2);
    });

    test('keeps at most its capacity of layouts', async () => {
        const cached = new CachingElk(createElk(), 2);
        for (const w of [60, 70, 80]) await cached.layout(graph('a', w));
        expect(cached.size).toBe(2);
    });
});
