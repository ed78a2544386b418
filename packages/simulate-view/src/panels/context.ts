/**
 * What every panel shares: the session's timeline store, the time window the time-based panels
 * draw, the transitions index, the run's automata table and node names, and the selected
 * transition. Selecting moves the cursor there and reveals the transition in the model.
 */
import { type AutomatonInfo, instanceLabel } from '../timeline/automata.js';
import type { TimelineStore } from '../timeline/store.js';
import type { ProgramStep, TakenTransition, TransitionIndex } from '../timeline/transitions.js';
import type { TimeWindow } from '../timeline/window.js';

export interface PanelContext {
    readonly store: TimelineStore;
    readonly window: TimeWindow;
    readonly index: TransitionIndex;
    /** The run's automata table (empty when the generated code has none). */
    automata(): readonly AutomatonInfo[];
    /** A node's instance path (`/toast_service_robot/ctrl` → `ctrl`), `undefined` when unknown. */
    instanceOf(node: string): string | undefined;
    /** The selected transition. */
    readonly selected: TakenTransition | undefined;
    /** Selects a transition: the cursor moves to its time and the model shows it. */
    select(t: TakenTransition): void;
    /**
     * A click at time `t` (a plot, a state row): the cursor moves there, and the transition taken
     * last by then (of `node`, else of the selected transition's component, else of any) is
     * selected and shown in the model; the cursor stays at `t`.
     */
    pointAt(t: number, node?: string): void;
    /** Moves the cursor to a program step and shows its line when known. */
    selectStep(step: ProgramStep): void;
    /** Something the panels show changed (zoom, pan, selection): draw again. */
    redraw(): void;
}

/** A panel of the dock: its element, drawn again when the store, cursor, window or selection change while it shows. */
export interface Panel {
    readonly id: string;
    readonly title: string;
    readonly element: HTMLElement;
    render(): void;
}

/** How a panel names a node: its instance path, else the node. */
export function nodeLabel(ctx: PanelContext, node: string): string {
    const inst = ctx.instanceOf(node) ?? ctx.automata().find((a) => a.node === node)?.instancePath;
    return inst === undefined ? node : instanceLabel(inst);
}
