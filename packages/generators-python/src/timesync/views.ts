/**
 * View models of the timesync templates (templates/timesync), built by the generators in this
 * folder. Strings named `value`, `type`, `alias` or lines of statements are Python source already;
 * names are model names the templates quote (`| json`).
 */
import type { EntryView } from '../behavior/views.js';

/** The mode automaton of a mode component (maa_timesync.ModeComponent). */
export interface ModesView {
    readonly modes: readonly string[];
    readonly initial: string;
    readonly timing: string;
    readonly perMode: ReadonlyArray<{
        readonly name: string;
        readonly subcomponents: readonly string[];
        readonly connectors: readonly string[];
    }>;
    /** The statements of `mode_transition`. */
    readonly body: readonly string[];
}

/** The body of `mode_transition(mode, trigger, inputs, params)`. */
export interface ModeTransitionView {
    /** Arguments the body does not read (`del`). */
    readonly unused: readonly string[];
    /** In declaration order: `index` is the position, the automata table's and `/maa/transitions`' index. */
    readonly transitions: ReadonlyArray<{ readonly index: number; readonly conditions: readonly string[]; readonly target: string }>;
}

/** A subcomponent of a composed component: name, its type's Python name and its arguments. */
export interface SubcomponentView {
    readonly name: string;
    readonly alias: string;
    readonly args: readonly EntryView[];
}

/** The classes of a component module: its behavior (generated or loaded) and its component type. */
export interface ComponentClassesView {
    /** A generated behavior class (compute blocks, or the base of a handwritten behavior). */
    readonly behaviorClass: string | undefined;
    /** The loader of the handwritten behavior class. */
    readonly handwritten: { readonly base: string; readonly module: string; readonly cls: string } | undefined;
    readonly className: string;
    readonly base: 'AtomicComponent' | 'ComposedComponent' | 'ModeComponent';
    readonly qualifiedName: string;
    readonly inPorts: readonly string[];
    readonly outPorts: readonly string[];
    readonly portTypes: readonly EntryView[];
    readonly parameters: readonly string[];
    readonly typeParameters: readonly string[];
    readonly features: readonly EntryView[] | undefined;
    readonly atomic: { readonly behavior: string } | undefined;
    readonly composed:
        | {
              /** maa_timesync `Connector` tuples. */
              readonly connectors: readonly string[];
              readonly modes: ModesView | undefined;
              readonly usesParams: boolean;
              readonly subcomponents: readonly SubcomponentView[];
          }
        | undefined;
    /** Parameter defaults (`defaults` classmethod). */
    readonly defaults: ReadonlyArray<{ readonly name: string; readonly value: string }>;
}

/** The user file of a handwritten component, created once. */
export interface HandwrittenUserView {
    readonly qualifiedName: string;
    readonly module: string;
    readonly base: string;
    readonly className: string;
}

/** maa_app.py: root type, enums by name, lock-step topics and node names. */
export interface AppModuleView {
    readonly application: string;
    readonly rootQualifiedName: string;
    readonly imports: readonly string[];
    readonly rootAlias: string;
    readonly components: ReadonlyArray<{ readonly name: string; readonly alias: string }>;
    readonly enums: ReadonlyArray<{ readonly name: string; readonly type: string }>;
    readonly portTopics: ReadonlyArray<{ readonly key: string; readonly topic: string; readonly type: string }>;
    readonly nodeNames: ReadonlyArray<{ readonly path: string; readonly node: string }>;
    /** The automata table by instance path: each entry (@maa/protocol's AutomatonEntry) as JSON. */
    readonly automata: ReadonlyArray<{ readonly path: string; readonly json: string }>;
}

/** The head of a class diagram's module. */
export interface DataTypesModuleView {
    readonly diagrams: string;
    readonly imports: readonly string[];
}

/** A method a class diagram declares. */
export interface MethodView {
    readonly name: string;
    readonly isStatic: boolean;
    readonly args: readonly string[];
    readonly returns: string;
    /** `pkg.Type.name(int,String)`, the protected region's id. */
    readonly signature: string;
    readonly message: string;
}

/** One class-diagram type. */
export interface DataTypeView {
    readonly name: string;
    readonly qualifiedName: string;
    readonly enum: { readonly constants: readonly string[] } | undefined;
    readonly data:
        | {
              readonly kind: 'Class' | 'Interface';
              readonly typeParameters: readonly string[];
              readonly bases: readonly string[];
              readonly attributes: ReadonlyArray<{ readonly name: string; readonly annotation: string; readonly value: string }>;
          }
        | undefined;
    /** No members at all (`pass`). */
    readonly empty: boolean;
    readonly methods: readonly MethodView[];
}
