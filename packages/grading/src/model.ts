/**
 * A submission's model loaded with the language family's services the way `maa-gen check` loads a
 * model root (every model file built and validated in one workspace): its diagnostics, its
 * component types by qualified name, the application's root component, and links to elements
 * (file relative to the model root + line) for feedback.
 */
import path from 'node:path';
import { AstUtils, type AstNode } from 'langium';
import { NodeFileSystem } from 'langium/node';
import { componentQualifiedName } from '@maa/generator-core';
import { type CheckDiagnostic, checkRoots, type ast } from '@maa/language-adl';
import { createMaaServices } from '@maa/language-server';
import type { FeedbackElement } from '@maa/protocol/grading';

export interface SubmissionModel {
    /** The model root (absolute). */
    readonly root: string;
    /** Every diagnostic of the model root, as `maa-gen check` reports them. */
    readonly diagnostics: readonly CheckDiagnostic[];
    /** The component types declared in the model root, by qualified name. */
    readonly components: ReadonlyMap<string, ast.ComponentType>;
    /** The component the application configuration is for (undefined when the app does not name one that resolves). */
    readonly appRoot: ast.ComponentType | undefined;
}

/** Loads and checks a submission's model root; `appFile` is its application configuration (absolute). */
export async function loadSubmissionModel(root: string, appFile: string): Promise<SubmissionModel> {
    const services = createMaaServices(NodeFileSystem);
    const absRoot = path.resolve(root);
    const diagnostics = await checkRoots(services, [{ root: absRoot }]);
    const components = new Map<string, ast.ComponentType>();
    let appRoot: ast.ComponentType | undefined;
    for (const doc of services.shared.workspace.LangiumDocuments.all) {
        if (doc.uri.scheme !== 'file' || !isInside(absRoot, doc.uri.fsPath)) continue;
        const top = doc.parseResult.value as AstNode & { application?: { component?: { ref?: ast.ComponentType } } };
        if (path.resolve(doc.uri.fsPath) === path.resolve(appFile)) appRoot = top.application?.component?.ref;
        for (const node of AstUtils.streamAst(top)) {
            if (node.$type !== 'ComponentType') continue;
            const component = node as ast.ComponentType;
            if (!components.has(componentQualifiedName(component))) components.set(componentQualifiedName(component), component);
        }
    }
    return { root: absRoot, diagnostics, components, appRoot };
}

function isInside(root: string, file: string): boolean {
    const rel = path.relative(root, file);
    return rel !== '' && !rel.startsWith('..') && !path.isAbsolute(rel);
}

/** The model-root relative file (with `/`) and 1-based line of a model element. */
export function elementOf(model: Pick<SubmissionModel, 'root'>, node: AstNode, qualifiedName: string): FeedbackElement {
    const file = path.relative(model.root, AstUtils.getDocument(node).uri.fsPath).split(path.sep).join('/');
    const line = (node.$cstNode?.range.start.line ?? 0) + 1;
    return { qualifiedName, file, line };
}

/** `toast/Controller.arc:22`: how feedback text names a place in the model. */
export function where(element: FeedbackElement): string {
    return `${element.file}:${element.line}`;
}
