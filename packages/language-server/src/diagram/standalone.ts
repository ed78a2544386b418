import { AstUtils, type LangiumDocuments } from 'langium';
import { ast, subcomponentType, subcomponentsOf } from '@maa/language-adl';
import { componentQualifiedName, modeSubcomponentsOf } from '@maa/generator-core';
import type { DiagramType, MaaDiagramOptions, MaaGraph } from './model.js';
import type { MaaDiagramServices } from './services.js';

/**
 * Diagrams outside a diagram session (`maa-gen diagram`): the model the IDE's diagram server
 * sends for the same request, from the same generator and ELK layout, for a loaded and built
 * workspace.
 */

export interface StandaloneDiagramRequest {
    readonly component: ast.ComponentType;
    readonly diagramType: DiagramType;
    /** C&C view: instance paths of composed subcomponents to show opened (see expandedToDepth). */
    readonly expanded?: readonly string[];
}

export async function standaloneDiagram(services: MaaDiagramServices, request: StandaloneDiagramRequest): Promise<MaaGraph> {
    const document = AstUtils.getDocument(request.component);
    // The options of the IDE's model request (mounted-diagram.ts), as JSON.
    const options = {
        diagramType: request.diagramType,
        sourceUri: document.uri.toString(),
        component: componentQualifiedName(request.component),
        expanded: [...(request.expanded ?? [])].sort(),
        needsClientLayout: false,
    } satisfies MaaDiagramOptions;
    const state = { options: { ...options }, currentRoot: { type: 'NONE', id: 'EMPTY' }, revision: 0 };
    return (await services.diagram.DiagramGenerator.generate({ document, options: { ...options }, state })) as MaaGraph;
}

/**
 * The instance paths to open so that the C&C view shows `depth` levels of subcomponents: 1 shows
 * the component's subcomponents closed (as the IDE opens a diagram), 2 opens those among them
 * that are composed, and so on. Subcomponents of every variation point and mode are included
 * (a path the diagram does not show is ignored).
 */
export function expandedToDepth(component: ast.ComponentType, depth: number): string[] {
    const paths: string[] = [];
    // `above`: the types on the way down; a model that contains itself (an error) is opened once.
    const walk = (type: ast.ComponentType, path: readonly string[], level: number, above: ReadonlySet<ast.ComponentType>): void => {
        for (const sub of [...subcomponentsOf(type), ...modeSubcomponentsOf(type)]) {
            const subType = subcomponentType(sub).decl;
            // Level of this subcomponent: the component's own are level 1.
            if (!subType || level + 1 >= depth || above.has(subType)) continue;
            const subPath = [...path, sub.name];
            paths.push(subPath.join('.'));
            walk(subType, subPath, level + 1, new Set([...above, subType]));
        }
    };
    walk(component, [], 0, new Set([component]));
    return [...new Set(paths)].sort();
}

export interface WorkspaceComponent {
    /** The qualified name (`toast.ToastServiceRobot`). */
    readonly name: string;
    /** The URI of the document that declares it. */
    readonly uri: string;
    readonly node: ast.ComponentType;
}

/** Every component type of the workspace's documents, in document order. */
export function workspaceComponents(documents: LangiumDocuments): WorkspaceComponent[] {
    return documents.all
        .flatMap((d) =>
            AstUtils.streamAst(d.parseResult.value)
                .filter(ast.isComponentType)
                .map((node) => ({ name: componentQualifiedName(node), uri: d.uri.toString(), node })),
        )
        .toArray();
}
