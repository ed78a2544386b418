import { type AstNode, AstUtils } from 'langium';
import { type CDModel, type CDType, isCDClass, isCDEnum, isCDModel, isClassDiagram } from '../generated/ast.js';

// The functions below take the root of any document (`AstNode`): in a composed family the class
// diagrams are nodes of the family's AST, which has the same `$type`s and properties as this
// package's but is a different TypeScript type, so they are recognized by `isCDModel`.

/** The class diagram a document holds, or undefined for documents of other languages. */
export function cdModelOf(root: AstNode): CDModel | undefined {
    return isCDModel(root) && root.diagram ? root : undefined;
}

/** The named types (classes, interfaces, enums) a class diagram declares, in source order; associations have no name and are skipped. */
export function cdTypesOf(model: CDModel): CDType[] {
    return model.diagram.elements.filter((e): e is CDType => e.$type !== 'CDAssociation' && !!e.name);
}

/** The type named `name` declared in the class diagram of the document `root`, if any. */
export function cdTypeNamed(root: AstNode, name: string): CDType | undefined {
    const model = cdModelOf(root);
    return model ? cdTypesOf(model).find((t) => t.name === name) : undefined;
}

/**
 * The names under which a class-diagram type is exported to other files: `package.Diagram.Type`
 * and `package.Type` (MontiArc accepts both import forms), without the package when there is none.
 */
export function cdExportedNames(model: CDModel, type: CDType): [string, string] {
    const pkg = model.package ? `${model.package}.` : '';
    return [`${pkg}${model.diagram.name}.${type.name}`, `${pkg}${type.name}`];
}

/** The names under which a node is exported if it is a type declared in a class diagram (see cdExportedNames), else none. */
export function cdExportedNamesOf(node: AstNode): string[] {
    const diagram = node.$container;
    const model = isClassDiagram(diagram) ? cdModelOf(diagram.$container) : undefined;
    return model && (isCDClass(node) || isCDEnum(node)) ? cdExportedNames(model, node) : [];
}

/** The package of the class diagram that declares a node (e.g. `java.lang` for the built-in `String`), if it has one. */
export function cdPackageOf(node: AstNode): string | undefined {
    return AstUtils.getContainerOfType(node, isCDModel)?.package;
}
