import {
    Cancellation,
    DefaultReferenceDescriptionProvider,
    type LangiumDocument,
    type ReferenceDescription,
    type ReferenceInfo,
} from 'langium';
import { forEachReferenceBelow } from './ast-walk.js';

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
        await forEachReferenceBelow(document.parseResult.value, cancelToken, collect);
        return out;
    }
}
