import { AstUtils, CstUtils, GrammarUtils, UriUtils, type AstNode, type LangiumDocument, type LangiumDocuments } from 'langium';
import { DefaultRenameProvider, type LangiumSharedServices } from 'langium/lsp';
import type { Position, PrepareRenameParams, RenameParams, TextDocumentPositionParams } from 'vscode-languageserver-protocol';
import type { Range, TextEdit, WorkspaceEdit } from 'vscode-languageserver-types';
import type { AdlSharedServices } from '../adl-module.js';
import type { AdlLspServices } from './lsp-module.js';
import { isArcModel, isCDModel, isComponentType } from '../generated/ast.js';
import { exportedNames, isBuiltinNode, isIdentifier, rootDocuments } from './node-info.js';

/**
 * Rename across the language family and the files of a model root: the declaration, every
 * cross-reference to it (connectors, expressions in guards and actions, transition events,
 * blocks of other behavior languages), member accesses such as `Type.CONSTANT`, and imports of
 * renamed components and types. A qualified reference (`toast.Controller`) keeps its qualifier.
 * Renaming a top-level component also renames its file when the file is named after it and the
 * client supports file renames in workspace edits.
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

    /** The element a rename at a position would rename (never one of the built-in library). */
    targetAt(document: LangiumDocument, position: Position): AstNode | undefined {
        const root = document.parseResult.value.$cstNode;
        if (!root) return undefined;
        const leaf = CstUtils.findDeclarationNodeAtOffset(root, document.textDocument.offsetAt(position), this.grammarConfig.nameRegexp);
        if (!leaf) return undefined;
        const target = this.references.findDeclarations(leaf)[0];
        return target && !isBuiltinNode(this.shared, target) ? target : undefined;
    }

    override async rename(document: LangiumDocument, params: RenameParams): Promise<WorkspaceEdit | undefined> {
        const target = this.targetAt(document, params.position);
        if (!target) return undefined;
        if (!isIdentifier(params.newName)) throw new Error(`'${params.newName}' is not a valid name.`);
        return this.renameElement(target, params.newName);
    }

    override prepareRename(document: LangiumDocument, params: PrepareRenameParams | TextDocumentPositionParams): Range | undefined {
        const target = this.targetAt(document, params.position);
        if (!target) return undefined;
        const root = document.parseResult.value.$cstNode!;
        const leaf = CstUtils.findDeclarationNodeAtOffset(root, document.textDocument.offsetAt(params.position), this.grammarConfig.nameRegexp);
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
                    { kind: 'rename', oldUri: targetDoc.uri.toString(), newUri }
                ]
            };
        }
        return { changes };
    }
}

/** The range of the last segment of a (possibly qualified) name that ends with `name`. */
function lastSegment(doc: LangiumDocument, range: Range, name: string): Range {
    const text = doc.textDocument.getText(range);
    if (text === name || !text.endsWith(name)) return range;
    const end = doc.textDocument.offsetAt(range.end);
    return { start: doc.textDocument.positionAt(end - name.length), end: range.end };
}

function sameRange(a: Range, b: Range): boolean {
    return a.start.line === b.start.line && a.start.character === b.start.character && a.end.line === b.end.line && a.end.character === b.end.character;
}
