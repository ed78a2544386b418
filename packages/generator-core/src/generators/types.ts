import type { AstNode } from 'langium';
import type {
    ArchitectureModel,
    BehaviorView,
    ComponentView,
    DataTypeView,
    FieldView,
    ParameterView,
    PortView,
} from '../model/architecture.js';
import type {
    BehaviorGeneratorManifest,
    ComponentGeneratorManifest,
    DataTypeGeneratorManifest,
    GeneratorKind,
    GeneratorManifest,
} from '../manifest/manifest.js';

/**
 * The generator types of a generator family (ARCHITECTURE.md section 6, after the paper's
 * section 6). A generator package's entry module (manifest `entry`, export `export` or
 * `default`) exports either a generator object or a function creating one from a
 * GeneratorInstantiation. The orchestrator checks that the object's kind matches the manifest.
 */

/** The selected application and platform. */
export interface PlatformInfo {
    /** The application's name (`application TR for ...`). */
    readonly application: string;
    /** The platform's name in the configuration (`platform rospython { ... }`). */
    readonly platform: string;
    /** Qualified name of the application's root component type. */
    readonly rootComponent: string;
}

/** Renders the templates of one generator (its manifest's `templates` folder) with the shared environment. */
export interface TemplateRenderer {
    /** Renders a template file to a string (trace markers are left for a FileBuilder to resolve). */
    render(template: string, context: Record<string, unknown>): string;
    /** Renders a template given as a string. */
    renderString(source: string, context: Record<string, unknown>): string;
}

/**
 * One output file under construction. Text written while an element is traced (`traced`,
 * `write(text, element)`, or `{% trace element %}...{% endtrace %}` in a template) is recorded in
 * the trace file as the element's line range.
 */
export interface FileBuilder {
    readonly path: string;
    /** Appends text; lines it produces are traced to `element` when given. */
    write(text: string, element?: AstNode): this;
    /** Appends a line (a newline is added). */
    line(text?: string, element?: AstNode): this;
    /** Runs `body`; everything written meanwhile is traced to `element`. */
    traced<T>(element: AstNode, body: () => T): T;
    /** Renders a template of the generator and appends the result (traced to `element` when given). */
    render(template: string, context: Record<string, unknown>, element?: AstNode): this;
}

export interface FileOptions {
    /**
     * A user file: created once with the generated content and never overwritten (e.g. the
     * implementation stub of a `<<handwritten>>` component).
     */
    readonly userFile?: boolean;
}

/**
 * Where a generator puts its files. Paths are relative to the output folder, with `/`;
 * two generators (or one, twice) may not produce the same path. Protected regions inside a
 * generated file (lines between `PROTECTED REGION BEGIN <id>` and `PROTECTED REGION END <id>`,
 * in any comment syntax) keep the user's content of the existing file.
 */
export interface OutputSink {
    file(path: string, options?: FileOptions): FileBuilder;
}

/** How the output of a data type generator refers to one class-diagram type. */
export type TypeMapping = Readonly<Record<string, string>>;

/** What a data type generator tells the other generators (e.g. module and class name per type). */
export interface DataTypeResult {
    /** By qualified class-diagram type name (`toast.types.Types.ToastColor`). */
    readonly types?: Readonly<Record<string, TypeMapping>>;
    readonly [key: string]: unknown;
}

/** What a behavior generator tells the component generator that wraps it (e.g. module and class). */
export type BehaviorResult = Readonly<Record<string, unknown>>;

/** Common context of every generator run. */
export interface GenerationContextBase {
    readonly architecture: ArchitectureModel;
    readonly platform: PlatformInfo;
    readonly out: OutputSink;
    /** The generator's own templates (empty renderer when the manifest names no folder). */
    readonly templates: TemplateRenderer;
}

export interface DataTypeGenerationContext extends GenerationContextBase {
    /** The class-diagram types the architecture uses (sorted by qualified name). */
    readonly dataTypes: readonly DataTypeView[];
}

/**
 * The context a behavior generator gets: its output sink and templates, plus exactly what its
 * manifest's `requires` declares (behavior generators are free of C&C details otherwise).
 */
export interface BehaviorGenerationContext {
    readonly out: OutputSink;
    readonly templates: TemplateRenderer;
    readonly ports?: readonly PortView[];
    readonly parameters?: readonly ParameterView[];
    readonly fields?: readonly FieldView[];
    readonly component?: ComponentView;
    readonly packageName?: string;
    readonly platform?: PlatformInfo;
    readonly datatypes?: DataTypeResult;
}

/** The result of handing a component's behavior on (see ComponentGenerationContext.behavior). */
export type DelegatedBehavior =
    /** Translated by the behavior generator `generator`, which returned `result`. */
    | {
          readonly handledBy: 'behavior-generator';
          readonly generator: string;
          readonly language: string;
          readonly behavior: BehaviorView;
          readonly result: BehaviorResult;
      }
    /** A language the component generator declares in `supports`: it translates the block itself. */
    | { readonly handledBy: 'component-generator'; readonly language: string; readonly behavior: BehaviorView };

export interface ComponentGenerationContext extends GenerationContextBase {
    /** What the data type generator returned (it always runs first). */
    readonly datatypes: DataTypeResult;
    /**
     * Hands the behavior of a component to the behavior generator registered for its language
     * (once per component; later calls return the same result). Undefined for components
     * without a behavior.
     */
    behavior(component: ComponentView): Promise<DelegatedBehavior | undefined>;
}

/** A violation of a generator's well-formedness rule, on the model element that violates it. */
export interface RuleViolation {
    readonly node: AstNode;
    readonly message: string;
}

/** The models a rule checks: what the declaring generator will translate. */
export interface RuleScope {
    readonly architecture: ArchitectureModel;
    readonly components: readonly ComponentView[];
    /** For a behavior generator: the blocks of its language; otherwise all behavior blocks. */
    readonly behaviors: readonly BehaviorView[];
    readonly dataTypes: readonly DataTypeView[];
}

/**
 * A named generator well-formedness rule (manifest `checks`). generator-core ships a standard
 * library (STANDARD_RULES); a generator may implement further rules in its `rules`.
 */
export interface WellFormednessRule {
    readonly name: string;
    readonly description: string;
    check(scope: RuleScope): Iterable<RuleViolation>;
}

interface GeneratorObject {
    /** When present, must equal the manifest's kind. */
    readonly kind?: GeneratorKind;
    /** Rules named in the manifest's `checks` that the standard library does not define. */
    readonly rules?: readonly WellFormednessRule[];
}

export interface DataTypeGenerator extends GeneratorObject {
    generate(ctx: DataTypeGenerationContext): DataTypeResult | void | Promise<DataTypeResult | void>;
}

export interface BehaviorGenerator extends GeneratorObject {
    generate(behavior: BehaviorView, ctx: BehaviorGenerationContext): BehaviorResult | void | Promise<BehaviorResult | void>;
}

export interface ComponentGenerator extends GeneratorObject {
    generate(ctx: ComponentGenerationContext): void | Promise<void>;
}

export type Generator = DataTypeGenerator | BehaviorGenerator | ComponentGenerator;

/** What a generator factory gets. */
export interface GeneratorInstantiation<M extends GeneratorManifest = GeneratorManifest> {
    readonly manifest: M;
    /** Absolute folder of the generator's package. */
    readonly packageDir: string;
    readonly templates: TemplateRenderer;
}

export type GeneratorFactory = (instantiation: GeneratorInstantiation) => Generator | Promise<Generator>;

/** Convenience for generator authors: typed factories. */
export type ComponentGeneratorFactory = (
    i: GeneratorInstantiation<ComponentGeneratorManifest>,
) => ComponentGenerator | Promise<ComponentGenerator>;
export type BehaviorGeneratorFactory = (
    i: GeneratorInstantiation<BehaviorGeneratorManifest>,
) => BehaviorGenerator | Promise<BehaviorGenerator>;
export type DataTypeGeneratorFactory = (
    i: GeneratorInstantiation<DataTypeGeneratorManifest>,
) => DataTypeGenerator | Promise<DataTypeGenerator>;
