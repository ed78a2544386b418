import {
    AstUtils,
    CstUtils,
    DefaultReferences,
    DocumentState,
    GrammarUtils,
    isReference,
    stream,
    UriUtils,
    type AstNode,
    type CstNode,
    type FindReferencesOptions,
    type LangiumDocument,
    type ReferenceDescription,
    type Stream,
} from 'langium';
import type { AdlServices } from '../adl-module.js';
import { isFieldAccessExpression } from '../generated/ast.js';
import { documentOf, lastLeaf, resolveMember, rootDocuments } from './node-info.js';

/**
 * Resolves a name that is not a cross-reference (e.g. a member name after `.`) to the element
 * it denotes, given the leaf under the cursor; undefined when the contributor does not know it.
 */
export type NameResolverContribution = (leaf: CstNode) => AstNode[] | undefined;

/**
 * Finds further uses of an element that the index does not know (names that are not
 * cross-references), in the documents where it may be used (computed on first call).
 */
export type ReferenceFinderContribution = (
    target: AstNode,
    documents: () => readonly LangiumDocument[],
) => Iterable<{ document: LangiumDocument; node: AstNode; segment: CstNode }>;

/**
 * Cross-references as Langium indexes them, plus names that are not cross-references:
 * `Type.CONSTANT` and `value.attribute` resolve by the type of the receiver. Definition, hover,
 * highlight, references and rename all go through this service, so contributions made here
 * (`nameResolvers`, `referenceFinders`) reach every one of them.
 *
 * A declaration outside the model documents (a synthetic node of a scope, such as a generator
 * of an `.arcapp`: it has no document) has no declaration to include; its uses are the
 * cross-references that resolved to the same description (manifest URI and path).
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
        if (!documentOf(targetNode)) return stream(this.externalUses(targetNode, options));
        const indexed = super.findReferences(targetNode, options);
        if (this.referenceFinders.length === 0) return indexed;
        let docs: LangiumDocument[] | undefined;
        const documents = (): LangiumDocument[] =>
            (docs ??= options.documentUri
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
                    local: use.document === targetDoc,
                });
            }
        }
        return indexed.concat(stream(extra));
    }

    /**
     * The uses of a declaration without a document. Scopes may create a new node for the same
     * declaration after a rebuild, so uses are matched by the description they resolved through
     * (found from one use of this very node), not by node identity.
     */
    private externalUses(target: AstNode, options: FindReferencesOptions): ReferenceDescription[] {
        // Only linked documents: resolving references of a document being rebuilt would link it
        // against a stale index.
        const uses = this.documents.all
            .filter((d) => d.state >= DocumentState.Linked)
            .flatMap((document) => document.references.filter(isReference).map((ref) => ({ document, ref })))
            .toArray();
        const described = uses.find((u) => u.ref.ref === target)?.ref.$nodeDescription;
        if (!described) return [];
        const out: ReferenceDescription[] = [];
        for (const { document, ref } of uses) {
            const desc = ref.$nodeDescription;
            if (options.documentUri && !UriUtils.equals(document.uri, options.documentUri)) continue;
            if (!ref.$refNode || !desc || desc.path !== described.path || !UriUtils.equals(desc.documentUri, described.documentUri))
                continue;
            out.push({
                sourceUri: document.uri,
                sourcePath: this.nodeLocator.getAstNodePath(ref.$refNode.astNode),
                targetUri: desc.documentUri,
                targetPath: desc.path,
                segment: CstUtils.toDocumentSegment(ref.$refNode),
                local: false,
            });
        }
        return out;
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

    private *memberUses(
        target: AstNode,
        docs: () => readonly LangiumDocument[],
    ): Generator<{ document: LangiumDocument; node: AstNode; segment: CstNode }> {
        if (!['CDEnumConstant', 'CDAttribute', 'CDMethod'].includes(target.$type)) return;
        const name = (target as AstNode & { name?: string }).name;
        for (const document of docs()) {
            for (const node of AstUtils.streamAst(document.parseResult.value)) {
                if (!isFieldAccessExpression(node) || node.member !== name) continue;
                const segment = GrammarUtils.findNodeForProperty(node.$cstNode, 'member');
                if (!segment) continue;
                if (resolveMember(node, this.services.maa.ExpressionTyper, this.services.maa.TypeRelations) === target)
                    yield { document, node, segment };
            }
        }
    }
}
