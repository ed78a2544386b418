import { describe, expect, test } from 'vitest';
import { chainSource, feedingSource, type ChainFeed, type ChainGraph, type PortEnd } from '../src/index.js';

/** A component type for the walk: its subcomponents (name -> type name), connectors and relay points. */
interface Type {
    readonly subs?: Readonly<Record<string, string>>;
    readonly connectors?: ReadonlyArray<{ source: PortEnd; targets: PortEnd[] }>;
    /** Targets the client stops at (say, the connectors of modes). */
    readonly stops?: readonly PortEnd[];
}

/** Instances are paths; the root's type is `Root`. */
function graph(types: Readonly<Record<string, Type>>): ChainGraph<string[], string> {
    const typeOf = (path: readonly string[]): Type | undefined => {
        let name = 'Root';
        for (const p of path) {
            const next = types[name]?.subs?.[p];
            if (!next) return undefined;
            name = next;
        }
        return types[name];
    };
    return {
        child: (scope, sub) => (typeOf([...scope, sub]) ? [...scope, sub] : undefined),
        parent: (scope) => (scope.length === 0 ? undefined : { scope: scope.slice(0, -1), name: scope[scope.length - 1]! }),
        isAtomic: (scope) => Object.keys(typeOf(scope)?.subs ?? {}).length === 0,
        feeder(scope, target): ChainFeed<string> | undefined {
            const t = typeOf(scope)!;
            if (t.stops?.some((s) => s.sub === target.sub && s.port === target.port))
                return { stop: `${scope.join('.')}:${target.sub ?? ''}.${target.port}` };
            const source = feedingSource(t.connectors ?? [], target);
            return source ? { source } : undefined;
        },
    };
}

const ATOM: Type = {};
const TYPES: Record<string, Type> = {
    Atom: ATOM,
    // Unit passes its in port x to its inner atom and exposes the inner atom's out port y.
    Unit: {
        subs: { inner: 'Atom' },
        connectors: [
            { source: { port: 'x' }, targets: [{ sub: 'inner', port: 'i' }] },
            { source: { sub: 'inner', port: 'o' }, targets: [{ port: 'y' }] },
        ],
    },
    Root: {
        subs: { sensor: 'Atom', unit: 'Unit', sink: 'Atom', loop: 'Loop', gated: 'Atom' },
        connectors: [
            { source: { sub: 'sensor', port: 'o' }, targets: [{ sub: 'unit', port: 'x' }] },
            { source: { sub: 'unit', port: 'y' }, targets: [{ sub: 'sink', port: 'i' }, { port: 'out' }] },
            { source: { port: 'in' }, targets: [{ sub: 'sensor', port: 'i' }] },
            { source: { sub: 'loop', port: 'b' }, targets: [{ sub: 'loop', port: 'a' }] },
        ],
        stops: [{ sub: 'gated', port: 'i' }],
    },
    // a composed component whose out port b is fed by its own in port a (a cycle through Root)
    Loop: { subs: { dummy: 'Atom' }, connectors: [{ source: { port: 'a' }, targets: [{ port: 'b' }] }] },
};

describe('connector chains', () => {
    const g = graph(TYPES);

    test('an in port of an atomic instance in a composed one: out of it and into a sibling', () => {
        expect(chainSource(g, ['unit', 'inner'], { port: 'i' })).toEqual({ kind: 'atomic', scope: ['sensor'], port: 'o' });
    });

    test('through a composed subcomponent to the atomic instance that feeds its out port', () => {
        expect(chainSource(g, ['sink'], { port: 'i' })).toEqual({ kind: 'atomic', scope: ['unit', 'inner'], port: 'o' });
        expect(chainSource(g, [], { sub: 'unit', port: 'y' })).toEqual({ kind: 'atomic', scope: ['unit', 'inner'], port: 'o' });
    });

    test('an in port of the outermost scope is the boundary', () => {
        expect(chainSource(g, ['sensor'], { port: 'i' })).toEqual({ kind: 'boundary', scope: [], port: 'in' });
        expect(chainSource(g, [], { port: 'in' })).toEqual({ kind: 'boundary', scope: [], port: 'in' });
    });

    test('the client stops the walk where its feeder says so', () => {
        expect(chainSource(g, ['gated'], { port: 'i' })).toEqual({ kind: 'stop', stop: ':gated.i' });
    });

    test('no connector, an unknown subcomponent and a cycle end nowhere', () => {
        expect(chainSource(g, ['sink'], { port: 'other' })).toBeUndefined();
        expect(chainSource(g, [], { sub: 'nobody', port: 'o' })).toBeUndefined();
        expect(chainSource(g, ['loop'], { port: 'a' })).toBeUndefined();
    });

    test('feedingSource: the first connector with the target', () => {
        const connectors = [
            { source: { sub: 'a', port: 'o' }, targets: [{ sub: 'b', port: 'i' }] },
            { source: { port: 'x' }, targets: [{ port: 'y' }, { sub: 'b', port: 'j' }] },
        ];
        expect(feedingSource(connectors, { sub: 'b', port: 'j' })).toEqual({ port: 'x' });
        expect(feedingSource(connectors, { port: 'i' })).toBeUndefined();
    });
});
