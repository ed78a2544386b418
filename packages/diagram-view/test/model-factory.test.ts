import 'reflect-metadata';
import { describe, expect, it } from 'vitest';
import { SEdgeImpl, SGraphImpl, SLabelImpl, SModelFactory, SModelRegistry, SNodeImpl, SPortImpl, type SModelElementImpl } from 'sprotty';
import { CachedSModelFactory } from '../src/model-factory.js';
import { ComponentNode, MaaPort } from '../src/model.js';

/** A factory over a registry of the given element classes (the container injects the registry). */
function factory<F extends SModelFactory>(make: () => F): F {
    const f = make();
    const registry = new SModelRegistry([]);
    registry.register('graph', () => new SGraphImpl());
    registry.register('node:component', () => new ComponentNode());
    registry.register('port', () => new MaaPort());
    registry.register('edge:connector', () => new SEdgeImpl());
    registry.register('label:text', () => new SLabelImpl());
    (f as unknown as { registry: SModelRegistry }).registry = registry;
    return f;
}

const reserved = (f: SModelFactory, e: SModelElementImpl, name: string): boolean =>
    (f as unknown as { isReserved(e: SModelElementImpl, n: string): boolean }).isReserved(e, name);

const schema = {
    type: 'graph',
    id: 'g',
    revision: 2,
    children: [
        {
            type: 'node:component',
            id: 'root.a',
            name: 'a',
            position: { x: 1, y: 2 },
            size: { width: 30, height: 20 },
            bounds: { x: 99, y: 99, width: 1, height: 1 },
            children: [
                { type: 'port', id: 'root.a:i', name: 'i', direction: 'in', position: { x: 0, y: 5 } },
                { type: 'label:text', id: 'root.a#name', text: 'a' },
            ],
        },
        { type: 'edge:connector', id: 'conn:root:a.o->b.i', sourceId: 'root.a:o', targetId: 'root.b:i', routingPoints: [{ x: 1, y: 1 }] },
    ],
};

describe("the model factory's cached property check (issue 18)", () => {
    it('reserves what Sprotty reserves, for every element class and property, asked once or again', () => {
        const sprotty = factory(() => new SModelFactory());
        const cached = factory(() => new CachedSModelFactory());
        const names = [
            'children',
            'parent',
            'index',
            'bounds',
            'position',
            'size',
            'id',
            'type',
            'text',
            'name',
            'opacity',
            'anchorKind',
            'routingPoints',
            'x',
        ];
        for (const make of [
            () => new SGraphImpl(),
            () => new SNodeImpl(),
            () => new ComponentNode(),
            () => new SPortImpl(),
            () => new MaaPort(),
            () => new SEdgeImpl(),
            () => new SLabelImpl(),
        ]) {
            for (const round of [1, 2]) {
                for (const name of names) {
                    const e = make();
                    expect(reserved(cached, e, name), `${e.constructor.name}.${name}, round ${round}`).toBe(reserved(sprotty, e, name));
                }
            }
        }
        // an accessor of the class (bounds) is reserved, a plain property not, children always
        expect(reserved(cached, new SNodeImpl(), 'bounds')).toBe(true);
        expect(reserved(cached, new SNodeImpl(), 'position')).toBe(false);
        expect(reserved(cached, new SNodeImpl(), 'children')).toBe(true);
    });

    it('builds the same model as Sprotty does', () => {
        const a = factory(() => new SModelFactory()).createRoot(structuredClone(schema));
        const b = factory(() => new CachedSModelFactory()).createRoot(structuredClone(schema));
        const asSchema = (f: SModelFactory, r: typeof a) => JSON.stringify(f.createSchema(r));
        expect(
            asSchema(
                factory(() => new SModelFactory()),
                b,
            ),
        ).toBe(
            asSchema(
                factory(() => new SModelFactory()),
                a,
            ),
        );
        const node = b.index.getById('root.a') as SNodeImpl;
        expect(node).toBeInstanceOf(ComponentNode);
        expect(node.bounds).toEqual({ x: 1, y: 2, width: 30, height: 20 });
        expect(b.index.getById('root.a:i')?.parent).toBe(node);
    });
});
