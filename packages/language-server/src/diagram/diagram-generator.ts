import { AstUtils, type AstNode, type LangiumDocuments } from 'langium';
import { LangiumDiagramGenerator, type GeneratorContext, type LangiumSprottyServices } from 'langium-sprotty';
import type { IModelLayoutEngine, SModelRoot } from 'sprotty-protocol';
import { allFeatures, ast, configurationSpace, withVariant, type VariantEnv } from '@maa/language-adl';
import { componentQualifiedName } from '@maa/generator-core';
import { buildAutomatonDiagram } from './automaton-diagram.js';
import { buildComponentDiagram } from './cc-diagram.js';
import { buildContext } from './context.js';
import { TYPES, type MaaDiagramOptions, type MaaGraph } from './model.js';

/**
 * Generates the diagram a client asks for (`diagramType` `maa-cc` or `maa-automaton`) from the
 * component named by the `component` option, else the component of the `sourceUri` document,
 * and lays it out. The component's subcomponent types, behaviors and data types may live in
 * other files of the family: the generator reads the built AST, not one document.
 */
export class MaaDiagramGenerator extends LangiumDiagramGenerator {
    private readonly documents: LangiumDocuments;

    constructor(
        services: LangiumSprottyServices,
        private readonly layoutEngine: IModelLayoutEngine,
    ) {
        super(services);
        this.documents = services.shared.workspace.LangiumDocuments;
    }

    protected override async generateRoot(args: GeneratorContext): Promise<SModelRoot> {
        const options = args.options as Partial<MaaDiagramOptions>;
        const component = this.findComponent(args.document.parseResult.value, options.component);
        const ctx = buildContext(args.idCache, this.traceProvider);
        let graph: MaaGraph;
        if (!component) {
            graph = { type: TYPES.graph, id: 'graph:none', component: options.component ?? '', children: [] };
        } else if (options.diagramType === 'maa-automaton') {
            graph = buildAutomatonDiagram(component, ctx);
        } else {
            const features = allFeatures(component).map((f) => f.name);
            const chosen = options.features && features.length > 0 ? chooseConfiguration(component, features, options.features) : undefined;
            graph = withVariant(chosen?.env, () => buildComponentDiagram(component, new Set(options.expanded ?? []), ctx));
            if (features.length > 0) graph.features = features;
            if (chosen?.env) graph.configuration = chosen.values;
            else if (chosen) graph.configurationRejected = true;
        }
        return this.layoutEngine.layout(graph);
    }

    /** The component with the qualified name, or the (first) component of the source document. */
    private findComponent(source: AstNode, qualifiedName: string | undefined): ast.ComponentType | undefined {
        if (!qualifiedName) return AstUtils.streamAst(source).find(ast.isComponentType);
        const matches = (root: AstNode): ast.ComponentType | undefined =>
            AstUtils.streamAst(root)
                .filter(ast.isComponentType)
                .find((c) => componentQualifiedName(c) === qualifiedName);
        return matches(source) ?? this.documents.all.map((d) => matches(d.parseResult.value)).find((c) => c !== undefined);
    }
}

/**
 * The first admitted configuration of `component` (configurationSpace: constraints, feature
 * bindings of its subcomponents) whose own features agree with `wanted`; `env` is undefined
 * when none does (or the space is too large to enumerate).
 */
export function chooseConfiguration(
    component: ast.ComponentType,
    features: readonly string[],
    wanted: Readonly<Record<string, boolean>>,
): { env: VariantEnv | undefined; values: Record<string, boolean> } {
    const space = configurationSpace(component);
    const asked = features.filter((f) => typeof wanted[f] === 'boolean');
    const match = space.configurations.find((a) => asked.every((f) => space.value(a, f) === wanted[f]));
    if (match === undefined) return { env: undefined, values: {} };
    return { env: space.env(match), values: Object.fromEntries(features.map((f) => [f, space.value(match, f)])) };
}
