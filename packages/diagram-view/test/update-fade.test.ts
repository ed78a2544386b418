import 'reflect-metadata';
import { describe, expect, it } from 'vitest';
import { SChildElementImpl, SModelRootImpl, type SParentElementImpl, type CommandExecutionContext } from 'sprotty';
import { GuardedFadeAnimation } from '../src/commands.js';

// The faded-out copy of a removed connector, as Sprotty's UpdateModelCommand adds it to the new model.
function fadingOut(): { root: SModelRootImpl; copy: SChildElementImpl & { opacity: number } } {
    const root = new SModelRootImpl();
    root.id = 'g';
    // A component node: a child of the root that has children itself.
    const parent = new SChildElementImpl();
    parent.id = 'root';
    root.add(parent);
    const copy = Object.assign(new SChildElementImpl(), { opacity: 1 });
    copy.id = 'conn:root:ctrl.arm->arm.cmd';
    parent.add(copy);
    return { root, copy };
}

// tween ignores its context; the animation only passes it on to start().
const context = {} as CommandExecutionContext;

describe('the diagram update fade-out (GuardedFadeAnimation)', () => {
    it('removes the faded copy at the end of the fade-out', () => {
        const { root, copy } = fadingOut();
        const fade = new GuardedFadeAnimation(root, [{ element: copy, type: 'out' }], context, true);
        fade.tween(0.5, context);
        expect(copy.opacity).toBe(0.5);
        expect(root.index.getById(copy.id)).toBe(copy);
        fade.tween(1, context);
        expect(root.index.getById(copy.id)).toBeUndefined();
        expect((copy.parent as SParentElementImpl | undefined)?.children ?? []).not.toContain(copy);
    });

    it('does not throw when the copy is already gone (the connector came back, or a second final frame)', () => {
        const { root, copy } = fadingOut();
        const parent = copy.parent;
        parent.remove(copy);
        const fade = new GuardedFadeAnimation(root, [{ element: copy, type: 'out' }], context, true);
        expect(() => fade.tween(1, context)).not.toThrow();
        expect(copy.opacity).toBe(0);
        // Sprotty's own removal throws here: this is the failure the guarded fade avoids.
        expect(() => parent.remove(copy)).toThrow(/No such child/);
    });
});
