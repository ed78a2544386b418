/**
 * View models of the behavior templates (templates/behavior): what each template renders,
 * built by the emitters in this folder. Strings named `value`, `type`, `default` or lines of
 * statements are Python source already (from the expression/statement translator); names are
 * model names the templates quote (`| json`).
 */

/** A Python module: docstring, sorted import lines (groups separated by ''), then its classes. */
export interface ModuleView {
    readonly doc: string;
    readonly imports: readonly string[];
    readonly body: string;
}

/** One `self.<name>: <type> = <value>` of a behavior's `__init__`. */
export interface AttributeView {
    readonly name: string;
    readonly type: string;
    readonly value: string;
    /** Adds `# type: ignore[assignment]` (parameters read from the untyped mapping). */
    readonly ignoreType: boolean;
}

/** The class header, class variables, `__init__` and `_emit` of a behavior class. */
export interface PrologueView {
    readonly className: string;
    readonly doc: string;
    readonly timing: string;
    readonly inPorts: readonly string[];
    readonly outPorts: readonly string[];
    readonly delayed: readonly string[];
    readonly attributes: readonly AttributeView[];
    /** Further statements of `__init__`. */
    readonly extraInit: readonly string[];
}

/** A behavior class of compute/init blocks. */
export interface ComputeClassView {
    readonly prologue: PrologueView;
    /** The statements of `init`, or undefined without an init block. */
    readonly init: readonly string[] | undefined;
    /** The statements of `step` (empty: `del inputs`). */
    readonly step: readonly string[];
}

/** A Python dict entry (both sides Python source). */
export interface EntryView {
    readonly key: string;
    readonly value: string;
}

/** `_entry`, `_exit` or `_do`: the statements per state that has such actions. */
export interface StateActionsView {
    readonly kind: 'entry' | 'exit' | 'do';
    readonly cases: ReadonlyArray<{ readonly state: string; readonly body: readonly string[] }>;
}

/** A transition of `_fire`. */
export interface TransitionView {
    /** Its 0-based position in allTransitions (the `index` of `/maa/transitions`). */
    readonly index: number;
    /** Python conditions joined by `and`. */
    readonly conditions: readonly string[];
    /** An internal transition runs its action only. */
    readonly internal: boolean;
    /** The state whose substates are left (`_exit_until`), null for the top level. */
    readonly exitUntil: string | null;
    readonly action: readonly string[];
    /** States entered, outermost first; the last is the new state. */
    readonly entered: readonly string[];
}

/** An in port as the event-driven handlers reset it. */
export interface InPortResetView {
    readonly name: string;
    readonly attr: string;
    /** Java's default of its primitive type, else None. */
    readonly default: string;
}

/** The behavior class of an automaton. */
export interface AutomatonClassView {
    readonly prologue: PrologueView;
    readonly parents: readonly EntryView[];
    /** The initial action of the top-level initial state. */
    readonly initialAction: readonly string[];
    /** The chain of initial states, outermost first. */
    readonly initialStates: readonly string[];
    readonly stateActions: readonly StateActionsView[];
    readonly transitions: readonly TransitionView[];
    readonly sync: boolean;
    /** `step` of a sync automaton: the statements that read the slice's inputs. */
    readonly readInputs: readonly string[];
    readonly inPorts: readonly InPortResetView[];
}

/** The program executor of an embedded robot arm. */
export interface RobotArmClassView {
    readonly className: string;
    readonly qualifiedName: string;
    /** The programs' file relative to the model root (`/maa/program_steps`). */
    readonly file: string;
    readonly inPorts: readonly string[];
    readonly outPorts: readonly string[];
    readonly delayed: readonly string[];
    /** The status enum's Python name, or None. */
    readonly statusType: string;
    /**
     * Programs by name, each step a Python expression (`Move(...)`, `Gripper(...)`), and each
     * step's source as a Python tuple `(line, "text")`.
     */
    readonly programs: ReadonlyArray<{ readonly name: string; readonly steps: readonly string[]; readonly sources: readonly string[] }>;
    /** Command constant -> program name. */
    readonly commands: ReadonlyArray<{ readonly constant: string; readonly program: string }>;
}
