/** The diagram's own Sprotty commands. */
import { decorate, inject, injectable } from 'inversify';
import { HiddenCommand, SystemCommand, TYPES, type CommandExecutionContext, type SModelRootImpl } from 'sprotty';
import type { Action } from 'sprotty-protocol';

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
