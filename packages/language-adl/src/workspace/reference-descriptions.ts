import {
    Cancellation,
    DefaultReferenceDescriptionProvider,
    type AstNode,
    type LangiumDocument,
    type ReferenceDescription,
    type ReferenceInfo,
} from 'langium';
import { betweenNodes, forEachReference, pushChildren } from './ast-walk.js';

/** Langium's index of a document's references (what find-references reads), without its per-node streams and promises. */
export class AdlReferenceDescriptionProvider extends DefaultReferenceDescriptionProvider {
    override async createDescriptions(
        document: LangiumDocument,
        cancelToken = Cancellation.CancellationToken.None,
    ): Promise<ReferenceDescription[]> {
        const out: ReferenceDescription[] = [];
        const collect = (refInfo: ReferenceInfo): void => {
            if (!refInfo.reference.error) out.push(...this.createInfoDescriptions(refInfo));
        };
        const stack: AstNode[] = [document.parseResult.value];
        while (stack.length > 0) {
            const wait = betweenNodes(cancelToken);
            if (wait) await wait;
            const node = stack.pop()!;
            forEachReference(node, collect);
            pushChildren(node, stack);
        }
        return out;
    }
}
