import { stream, type AstNodeDescription, type Scope, type Stream } from 'langium';

/**
 * A scope that answers by lookup instead of enumerating candidates: names in this language
 * family resolve through imports, packages and inheritance, and enumerating every candidate for
 * every reference would be quadratic in large model roots. `all` serves completion only.
 */
export class LookupScope implements Scope {
    constructor(
        private readonly find: (name: string) => AstNodeDescription | undefined,
        private readonly all: () => Iterable<AstNodeDescription>,
    ) {}

    getElement(name: string): AstNodeDescription | undefined {
        return this.find(name);
    }

    getElements(name: string): Stream<AstNodeDescription> {
        const d = this.find(name);
        return stream(d ? [d] : []);
    }

    getAllElements(): Stream<AstNodeDescription> {
        return stream(this.all());
    }
}
