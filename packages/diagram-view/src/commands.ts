/** The diagram's own Sprotty commands. */
import { decorate, inject, injectable } from 'inversify';
import {
    FadeAnimation,
    HiddenCommand,
    SChildElementImpl,
    SystemCommand,
    TYPES,
    UpdateModelCommand,
    type Animation,
    type CommandExecutionContext,
    type SModelRootImpl,
} from 'sprotty';
import type { Action, UpdateModelAction } from 'sprotty-protocol';

/** Re-renders the current model (live values and active states changed; the model did not). */
export class RedrawCommand extends SystemCommand {
    static readonly KIND = 'maaRedraw';
    constructor(readonly action: Action) {
        super();
    }
    execute(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
    undo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
    redo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
}
decorate(injectable(), RedrawCommand);
decorate(inject(TYPES.Action), RedrawCommand, 0);

/**
 * Empties Sprotty's hidden rendering (the export renders the diagram there, in `document.body`),
 * so that no second copy of the diagram's elements stays in the page.
 */
export class ClearHiddenCommand extends HiddenCommand {
    static readonly KIND = 'maaClearHidden';
    constructor(readonly action: Action) {
        super();
    }
    execute(context: CommandExecutionContext): SModelRootImpl {
        return context.modelFactory.createRoot({ type: 'NONE', id: 'EMPTY' });
    }
    override undo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
    override redo(context: CommandExecutionContext): SModelRootImpl {
        return context.root;
    }
}
decorate(injectable(), ClearHiddenCommand);
decorate(inject(TYPES.Action), ClearHiddenCommand, 0);

/**
 * A fade whose fade-out removes the faded copy only while it is still where the fade put it.
 * Sprotty's own FadeAnimation removes it unconditionally at t = 1; when that copy is no longer a
 * child of its parent then (seen when a connector is removed by one update and re-added by the
 * next, e.g. by a quick fix), `SParentElementImpl.remove` throws inside the animation frame, the
 * update's promise never settles and the command stack stops applying updates for good.
 */
export class GuardedFadeAnimation extends FadeAnimation {
    override tween(t: number, _context: CommandExecutionContext): SModelRootImpl {
        for (const { element, type } of this.elementFades) {
            if (type === 'in') {
                element.opacity = t;
                continue;
            }
            element.opacity = 1 - t;
            if (t === 1 && element instanceof SChildElementImpl && element.parent?.children.includes(element)) {
                element.parent.remove(element);
            }
        }
        return this.model;
    }
}

/**
 * Above this many elements an update is not animated: Sprotty renders the whole diagram in every
 * frame of an animation (250 ms, about 15 frames), and a frame of a diagram this large takes
 * longer than a frame (issue 18: the System of 200 components, 300 ms per frame while typing).
 */
export const ANIMATED_UPDATE_MAX_ELEMENTS = 600;

/** How many elements a model schema has, counting up to `limit` + 1 at most. */
export function countElements(root: { children?: readonly unknown[] } | undefined, limit: number): number {
    let count = 0;
    const stack: unknown[] = root ? [root] : [];
    while (stack.length > 0 && count <= limit) {
        const el = stack.pop() as { children?: readonly unknown[] };
        count++;
        for (const c of el.children ?? []) stack.push(c);
    }
    return count;
}

/**
 * Sprotty's model update, with its fades made safe against elements that are already gone, and
 * not animated for large models ({@link ANIMATED_UPDATE_MAX_ELEMENTS}).
 */
export class GuardedUpdateModelCommand extends UpdateModelCommand {
    constructor(action: UpdateModelAction) {
        const large = countElements(action.newRoot, ANIMATED_UPDATE_MAX_ELEMENTS) > ANIMATED_UPDATE_MAX_ELEMENTS;
        super(large && action.animate !== false ? { ...action, animate: false } : action);
    }
    protected override createAnimations(
        data: Parameters<UpdateModelCommand['createAnimations']>[0],
        root: SModelRootImpl,
        context: CommandExecutionContext,
    ): Animation[] {
        return super
            .createAnimations(data, root, context)
            .map((animation) =>
                animation instanceof FadeAnimation && !(animation instanceof GuardedFadeAnimation)
                    ? new GuardedFadeAnimation(root, animation.elementFades, context, true)
                    : animation,
            );
    }
}
decorate(injectable(), GuardedUpdateModelCommand);
decorate(inject(TYPES.Action), GuardedUpdateModelCommand, 0);
