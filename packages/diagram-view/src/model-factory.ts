/**
 * Sprotty's model factory with its property check cached. Building the model of every update
 * copies each schema property onto the new element unless the element's class reserves it (an
 * accessor such as `bounds`); Sprotty finds that out by walking the element's prototype chain for
 * every property of every element: about a fifth of the webview's work on an update of the System
 * diagram of 200 components (issue 18, a CPU profile of typing). The answer depends only on the
 * element's prototype and the property's name, unless the element has the property itself.
 */
import { decorate, injectable } from 'inversify';
import { SModelFactory, type SModelElementImpl } from 'sprotty';

export class CachedSModelFactory extends SModelFactory {
    private readonly reserved = new Map<object, Map<string, boolean>>();

    override isReserved(element: SModelElementImpl, propertyName: string): boolean {
        const own = Object.getOwnPropertyDescriptor(element, propertyName);
        if (own !== undefined)
            return propertyName === 'children' || propertyName === 'parent' || propertyName === 'index' || own.get !== undefined;
        const proto = Object.getPrototypeOf(element) as object | null;
        if (proto === null) return super.isReserved(element, propertyName);
        let names = this.reserved.get(proto);
        if (!names) {
            names = new Map();
            this.reserved.set(proto, names);
        }
        let answer = names.get(propertyName);
        if (answer === undefined) {
            answer = super.isReserved(element, propertyName);
            names.set(propertyName, answer);
        }
        return answer;
    }
}
decorate(injectable(), CachedSModelFactory);
