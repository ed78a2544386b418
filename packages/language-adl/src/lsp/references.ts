import {
    AstUtils, CstUtils, DefaultReferences, GrammarUtils, stream, type AstNode, type CstNode, type FindReferencesOptions,
    type LangiumDocument, type ReferenceDescription, type Stream
} from 'langium';
import type { AdlServices } from '../adl-module.js';
import { isFieldAccessExpression } from '../generated/ast.js';
import { lastLeaf, resolveMember, rootDocuments } from './node-info.js';

/**
 * Resolves a name that is not a cross-reference (e.g. a member name after `.`) to the element
 * it denotes, given the leaf under the cursor; undefined when the contributor does not know it.
 */
export type NameResolverContribution = (leaf: CstNode) => AstNode[] | undefined;

/**
 * Finds further uses of an element that the index does not know (names that are not
 * cross-references), in the documents where it may be used (computed on first call).
 */
export type ReferenceFinderContribution = (target: AstNode, documents: () => readonly LangiumDocument[]) => Iterable<{ document: LangiumDocument; node: AstNode; segment: CstNode }>;

/**
 * Cross-references as Langium indexes them, plus names that are not cross-references:
 * `Type.CONSTANT` and `value.attribute` resolve by the type of the receiver. Definition, hover,
 * highlight, references and rename all go through this service, so contributions made here
 * (`nameResolvers`, `referenceFinders`) reach every one of them.
 */
export class AdlReferences extends DefaultReferences {
    readonly nameResolvers: NameResolverContribution[] = [];
    readonly referenceFinders: ReferenceFinderContribution[] = [];
    private readonly services: AdlServices;

    constructor(services: AdlServices) {
        super(services);
        this.services = services;
        this.nameResolvers.push((leaf) => this.memberTarget(leaf));
        this.nameResolvers.push((leaf) => this.importTarget(leaf));
        this.referenceFinders.push((target, docs) => this.memberUses(target, docs));
    }

    override findDeclarations(sourceCstNode: CstNode): AstNode[] {
        const found = super.findDeclarations(sourceCstNode);
        if (found.length > 0) return found;
        for (const resolve of this.nameResolvers) {
            const r = resolve(sourceCstNode);
            if (r && r.length > 0) return r;
        }
        return [];
    }

    override findReferences(targetNode: AstNode, options: FindReferencesOptions): Stream<ReferenceDescription> {
        const indexed = super.findReferences(targetNode, options);
        if (this.referenceFinders.length === 0) return indexed;
        let docs: LangiumDocument[] | undefined;
        const documents = (): LangiumDocument[] => (docs ??= options.documentUri
            ? this.documents.all.filter((d) => d.uri.toString() === options.documentUri!.toString()).toArray()
            : rootDocuments(this.services.shared, AstUtils.getDocument(targetNode).uri));
        const targetDoc = AstUtils.getDocument(targetNode);
        const targetPath = this.nodeLocator.getAstNodePath(targetNode);
        const extra: ReferenceDescription[] = [];
        for (const find of this.referenceFinders) {
            for (const use of find(targetNode, documents)) {
                extra.push({
                    sourceUri: use.document.uri,
                    sourcePath: this.nodeLocator.getAstNodePath(use.node),
                    targetUri: targetDoc.uri,
                    targetPath,
                    segment: CstUtils.toDocumentSegment(use.segment),
                    local: use.document === targetDoc
                });
            }
        }
        return indexed.concat(stream(extra));
    }

    /** The member named at a leaf, e.g. `STOP` in `ToasterCmd.STOP`. */
    private memberTarget(leaf: CstNode): AstNode[] | undefined {
        const fa = leaf.astNode;
        const member = isFieldAccessExpression(fa) ? GrammarUtils.findNodeForProperty(fa.$cstNode, 'member') : undefined;
        if (!isFieldAccessExpression(fa) || !member || (member !== leaf && !CstUtils.isChildNode(leaf, member))) return undefined;
        const target = resolveMember(fa, this.services.maa.ExpressionTyper, this.services.maa.TypeRelations);
        return target ? [target] : undefined;
    }

    /** The element a single-type import names (`import toast.types.ToastColor;`), from its last segment. */
    private importTarget(leaf: CstNode): AstNode[] | undefined {
        const imp = leaf.astNode;
        if (imp.$type !== 'ArcImport' && imp.$type !== 'CDImport') return undefined;
        const qn = (imp as unknown as { importedNamespace?: string }).importedNamespace;
        const cst = GrammarUtils.findNodeForProperty(imp.$cstNode, 'importedNamespace');
        if (!qn || qn.endsWith('.*') || !cst || lastLeaf(cst) !== leaf) return undefined;
        const shared = this.services.shared.maa;
        const uri = AstUtils.getDocument(imp).uri;
        const found = shared.RootIndex.lookup(shared.ModelRoots.rootOf(uri), qn).find((d) => d.node);
        return found?.node ? [found.node] : undefined;
    }

    private *memberUses(target: AstNode, docs: () => readonly LangiumDocument[]): Generator<{ document: LangiumDocument; node: AstNode; segment: CstNode }> {
        if (!['CDEnumConstant', 'CDAttribute', 'CDMethod'].includes(target.$type)) return;
        const name = (target as AstNode & { name?: string }).name;
        for (const document of docs()) {
            for (const node of AstUtils.streamAst(document.parseResult.value)) {
                if (!isFieldAccessExpression(node) || node.member !== name) continue;
                const segment = GrammarUtils.findNodeForProperty(node.$cstNode, 'member');
                if (!segment) continue;
                if (resolveMember(node, this.services.maa.ExpressionTyper, this.services.maa.TypeRelations) === target) yield { document, node, segment };
            }
        }
    }
}
