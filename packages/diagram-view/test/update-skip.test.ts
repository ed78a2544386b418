import 'reflect-metadata';
import { describe, expect, it } from 'vitest';
import type { Action, ActionMessage } from 'sprotty-protocol';
import { ANIMATED_UPDATE_MAX_ELEMENTS, countElements, GuardedUpdateModelCommand } from '../src/commands.js';
import { MaaDiagramProxy } from '../src/proxy.js';
import type { SchemaElement } from '../src/schema.js';

/** A proxy whose Sprotty side records what it is handed (the injected dispatcher and logger). */
function proxy(): { proxy: MaaDiagramProxy; dispatched: Action[]; models: string[] } {
    const p = new MaaDiagramProxy();
    p.clientId = 'd1';
    const dispatched: Action[] = [];
    const models: string[] = [];
    const fields = p as unknown as Record<string, unknown>;
    fields['actionDispatcher'] = {
        dispatch: (a: Action) => {
            dispatched.push(a);
            return Promise.resolve();
        },
    };
    fields['logger'] = { log: () => undefined, error: () => undefined };
    p.modelListeners.add((_root, kind) => models.push(kind));
    return { proxy: p, dispatched, models };
}

const graph = (instance: string, revision: number): SchemaElement => ({
    type: 'graph',
    id: 'g',
    revision,
    children: [
        { type: 'node:component', id: `root.${instance}`, children: [{ type: 'label:text', id: `root.${instance}#name`, text: instance }] },
    ],
});

const message = (kind: 'setModel' | 'updateModel', root: SchemaElement, clientId = 'd1'): ActionMessage =>
    ({ clientId, action: { kind, newRoot: root } }) as unknown as ActionMessage;

const receive = (p: MaaDiagramProxy, m: ActionMessage): void => (p as unknown as { messageReceived(d: unknown): void }).messageReceived(m);

describe('model updates that change nothing (issue 18: typing)', () => {
    it('an update bringing the shown model again (another revision) is not handed to Sprotty; the listeners still hear of it', () => {
        const { proxy: p, dispatched, models } = proxy();
        receive(p, message('setModel', graph('a', 1)));
        receive(p, message('updateModel', graph('a', 2)));
        expect(dispatched.map((a) => a.kind)).toEqual(['setModel']);
        expect(p.skippedUpdates).toBe(1);
        expect(models).toEqual(['setModel', 'updateModel']);
    });

    it('an update that changes the model is applied, and so is a set model even when equal', () => {
        const { proxy: p, dispatched } = proxy();
        receive(p, message('setModel', graph('a', 1)));
        receive(p, message('updateModel', graph('aQ', 2)));
        receive(p, message('updateModel', graph('a', 3)));
        receive(p, message('setModel', graph('a', 4)));
        expect(dispatched.map((a) => a.kind)).toEqual(['setModel', 'updateModel', 'updateModel', 'setModel']);
        expect(p.skippedUpdates).toBe(0);
    });

    it("another client's model is neither applied nor remembered", () => {
        const { proxy: p, dispatched } = proxy();
        receive(p, message('setModel', graph('a', 1)));
        receive(p, message('updateModel', graph('b', 2), 'other'));
        receive(p, message('updateModel', graph('a', 3)));
        expect(dispatched.map((a) => a.kind)).toEqual(['setModel']);
    });
});

describe('animated updates (GuardedUpdateModelCommand)', () => {
    const wide = (n: number): SchemaElement => ({
        type: 'graph',
        id: 'g',
        children: Array.from({ length: n }, (_, i) => ({ type: 'node:component', id: `root.c${i}` })),
    });
    const animate = (root: SchemaElement, requested?: boolean): boolean | undefined =>
        (
            new GuardedUpdateModelCommand({ kind: 'updateModel', newRoot: root, animate: requested } as never) as unknown as {
                action: { animate?: boolean };
            }
        ).action.animate;

    it('counts elements up to the limit', () => {
        expect(countElements(wide(3), 100)).toBe(4);
        expect(countElements(wide(1000), 100)).toBe(101);
        expect(countElements(undefined, 100)).toBe(0);
    });

    it('a small model is animated as asked; a large one is not', () => {
        expect(animate(wide(10), true)).toBe(true);
        expect(animate(wide(10))).toBeUndefined();
        expect(animate(wide(ANIMATED_UPDATE_MAX_ELEMENTS), true)).toBe(false);
        expect(animate(wide(ANIMATED_UPDATE_MAX_ELEMENTS))).toBe(false);
        expect(animate(wide(ANIMATED_UPDATE_MAX_ELEMENTS), false)).toBe(false);
    });
});
