import { AstUtils, CstUtils, GrammarUtils, URI, UriUtils, type AstNode, type LangiumDocument, type LangiumDocuments } from 'langium';
import { DefaultRenameProvider, type LangiumSharedServices } from 'langium/lsp';
import {
    ErrorCodes,
    LSPErrorCodes,
    ResponseError,
    type Position,
    type PrepareRenameParams,
    type RenameParams,
    type TextDocumentPositionParams,
} from 'vscode-languageserver-protocol';
import type { Range, TextEdit, WorkspaceEdit } from 'vscode-languageserver-types';
import type { AdlSharedServices } from '../adl-module.js';
import type { AdlLspServices } from './lsp-module.js';
import { isArcModel, isCDModel, isComponentType } from '../generated/ast.js';
import { nameProblem } from './names.js';
import { documentOf, exportedNames, isBuiltinNode, rootDocuments } from './node-info.js';

/**
 * Rename across the language family and the files of a model root: the declaration, every
 * cross-reference to it (connectors, expressions in guards and actions, transition events,
 * blocks of other behavior languages), member accesses such as `Type.CONSTANT`, and imports of
 * renamed components and types. A qualified reference (`toast.Controller`) keeps its qualifier.
 * Renaming a top-level component also renames its file when the file is named after it and the
 * client supports file renames in workspace edits.
 *
 * Refusals are LSP errors with a message for the user, never internal errors: a new name that
 * is not a name in every language the edit touches (InvalidParams), and declarations outside the
 * model files, such as the generators an `.arcapp` names (RequestFailed; prepareRename answers
 * null there, so editors do not offer the rename at all).
 */
export class AdlRenameProvider extends DefaultRenameProvider {
    private readonly shared: AdlSharedServices;
    private readonly documents: LangiumDocuments;
    private canRenameFiles = false;

    constructor(services: AdlLspServices) {
        super(services);
        this.shared = services.shared;
        this.documents = services.shared.workspace.LangiumDocuments;
        const server = (services.shared as unknown as LangiumSharedServices).lsp?.LanguageServer;
        server?.onInitialize((params) => {
            const edit = params.capabilities.workspace?.workspaceEdit;
            this.canRenameFiles = Boolean(edit?.documentChanges && edit.resourceOperations?.includes('rename'));
        });
    }

    /**
     * The element a rename at a position would rename: a declaration in a model file, never
     * one of the built-in library nor one outside the model files.
     */
    targetAt(document: LangiumDocument, position: Position): AstNode | undefined {
        const target = this.declarationAt(document, position);
        return target && documentOf(target) && !isBuiltinNode(this.shared, target) ? target : undefined;
    }

    private declarationAt(document: LangiumDocument, position: Position): AstNode | undefined {
        const root = document.parseResult.value.$cstNode;
        if (!root) return undefined;
        const leaf = CstUtils.findDeclarationNodeAtOffset(root, document.textDocument.offsetAt(position), this.grammarConfig.nameRegexp);
        return leaf ? this.references.findDeclarations(leaf)[0] : undefined;
    }

    override async rename(document: LangiumDocument, params: RenameParams): Promise<WorkspaceEdit | undefined> {
        const target = this.targetAt(document, params.position);
        if (!target) {
            const outside = this.declarationAt(document, params.position);
            if (outside && !documentOf(outside)) {
                const name = this.nameProvider.getName(outside) ?? 'this name';
                throw new ResponseError(
                    LSPErrorCodes.RequestFailed,
                    `'${name}' is not declared in a model file (it names an installed generator or another external declaration) and cannot be renamed.`,
                );
            }
            return undefined;
        }
        this.checkName(document, params.newName);
        const edit = this.renameElement(target, params.newName);
        for (const uri of editedUris(edit)) {
            const doc = this.documents.getDocument(URI.parse(uri));
            if (doc) this.checkName(doc, params.newName);
        }
        return edit;
    }

    /** Refuses a new name that is not a name in the language of a document the rename edits. */
    private checkName(document: LangiumDocument, newName: string): void {
        const services = this.shared.ServiceRegistry.getServices(document.uri);
        const problem = nameProblem(services, newName);
        if (problem) throw new ResponseError(ErrorCodes.InvalidParams, `'${newName}' is not a valid name: ${problem}.`);
    }

    override prepareRename(document: LangiumDocument, params: PrepareRenameParams | TextDocumentPositionParams): Range | undefined {
        const target = this.targetAt(document, params.position);
        if (!target) return undefined;
        const root = document.parseResult.value.$cstNode!;
        const leaf = CstUtils.findDeclarationNodeAtOffset(
            root,
            document.textDocument.offsetAt(params.position),
            this.grammarConfig.nameRegexp,
        );
        if (!leaf) return undefined;
        // In a qualified name (`toast.Controller`, an import) the name is the last segment.
        const name = this.nameProvider.getName(target);
        const whole = CstUtils.getDatatypeNode(leaf);
        if (whole && name && whole.text.endsWith(name)) {
            const end = whole.range.end;
            return { start: document.textDocument.positionAt(whole.end - name.length), end };
        }
        return this.renameNodeRange(document, params.position);
    }

    /** The workspace edit that renames an element and all its uses. */
    renameElement(target: AstNode, newName: string): WorkspaceEdit {
        const oldName = this.nameProvider.getName(target);
        const changes: Record<string, TextEdit[]> = {};
        const add = (uri: string, range: Range): void => {
            const list = (changes[uri] ??= []);
            if (!list.some((e) => sameRange(e.range, range))) list.push({ range, newText: newName });
        };
        for (const ref of this.references.findReferences(target, { includeDeclaration: true })) {
            const doc = this.documents.getDocument(ref.sourceUri);
            const range = doc && oldName ? lastSegment(doc, ref.segment.range, oldName) : ref.segment.range;
            add(ref.sourceUri.toString(), range);
        }
        const qualified = exportedNames(target);
        if (qualified.length > 0 && oldName) {
            for (const doc of rootDocuments(this.shared, AstUtils.getDocument(target).uri)) {
                const root = doc.parseResult.value;
                if (!isArcModel(root) && !isCDModel(root)) continue;
                for (const imp of root.imports) {
                    if (!qualified.includes(imp.importedNamespace)) continue;
                    const cst = GrammarUtils.findNodeForProperty(imp.$cstNode, 'importedNamespace');
                    if (cst) add(doc.uri.toString(), lastSegment(doc, cst.range, oldName));
                }
            }
        }
        const targetDoc = AstUtils.getDocument(target);
        const fileName = UriUtils.basename(targetDoc.uri);
        if (this.canRenameFiles && isComponentType(target) && isArcModel(target.$container) && fileName === `${oldName}.arc`) {
            const newUri = UriUtils.joinPath(UriUtils.dirname(targetDoc.uri), `${newName}.arc`).toString();
            return {
                documentChanges: [
                    ...Object.entries(changes).map(([uri, edits]) => ({ textDocument: { uri, version: null }, edits })),
                    { kind: 'rename', oldUri: targetDoc.uri.toString(), newUri },
                ],
            };
        }
        return { changes };
    }
}

/** The documents a workspace edit changes. */
function editedUris(edit: WorkspaceEdit): string[] {
    const uris = Object.keys(edit.changes ?? {});
    for (const change of edit.documentChanges ?? []) if ('textDocument' in change) uris.push(change.textDocument.uri);
    return uris;
}

/** The range of the last segment of a (possibly qualified) name that ends with `name`. */
function lastSegment(doc: LangiumDocument, range: Range, name: string): Range {
    const text = doc.textDocument.getText(range);
    if (text === name || !text.endsWith(name)) return range;
    const end = doc.textDocument.offsetAt(range.end);
    return { start: doc.textDocument.positionAt(end - name.length), end: range.end };
}

function sameRange(a: Range, b: Range): boolean {
    return (
        a.start.line === b.start.line &&
        a.start.character === b.start.character &&
        a.end.line === b.end.line &&
        a.end.character === b.end.character
    );
}
