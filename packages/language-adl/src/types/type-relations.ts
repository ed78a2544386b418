import { cdPackageOf } from '@maa/language-cd';
import type { CDClass, CDType, TypeParameter } from '../generated/ast.js';
import type { RootIndex } from '../scoping/root-index.js';
import { BOX_OF, UNBOX_OF } from './builtin-library.js';
import { typeOfMCType, bind } from './type-resolver.js';
import { ERROR_TYPE, substitute, type SymType } from './sym-type.js';

const NUMERIC_RANK: Readonly<Record<string, number>> = { byte: 1, short: 2, char: 2, int: 3, long: 4, float: 5, double: 6 };
const BUILTIN_ROOT = 'builtin:/';

/**
 * Subtyping, boxing/unboxing and assignability after Java's rules (JLS 5.1-5.2), as MontiArc
 * applies them to connectors, arguments and initializers. Raw generic types are accepted
 * (unchecked) against parameterized ones, as javac does.
 */
export class TypeRelations {
    constructor(private readonly index: RootIndex) {}

    /** The built-in class `java.lang.<name>` or `java.util.<name>`. */
    builtin(qualifiedName: string): CDType | undefined {
        return this.index.lookup(BUILTIN_ROOT, qualifiedName)[0]?.node as CDType | undefined;
    }

    objectType(qualifiedName: string, args: SymType[] = []): SymType {
        const decl = this.builtin(qualifiedName);
        return decl ? { kind: 'object', decl, args } : ERROR_TYPE;
    }

    box(t: SymType): SymType {
        if (t.kind !== 'primitive') return t;
        const box = BOX_OF.get(t.name);
        return box ? this.objectType(`java.lang.${box}`) : t;
    }

    /** The primitive a boxed type unboxes to, or the type itself. */
    unbox(t: SymType): SymType {
        if (t.kind === 'object' && isJavaLang(t.decl)) {
            const prim = UNBOX_OF.get(t.decl.name);
            if (prim) return { kind: 'primitive', name: prim as 'int' };
        }
        return t;
    }

    isNumeric(t: SymType): boolean {
        const u = this.unbox(t);
        return u.kind === 'primitive' && NUMERIC_RANK[u.name] !== undefined;
    }

    isIntegral(t: SymType): boolean {
        const u = this.unbox(t);
        return u.kind === 'primitive' && ['byte', 'short', 'char', 'int', 'long'].includes(u.name);
    }

    isBoolean(t: SymType): boolean {
        const u = this.unbox(t);
        return u.kind === 'primitive' && u.name === 'boolean';
    }

    isString(t: SymType): boolean {
        return t.kind === 'object' && isJavaLang(t.decl) && t.decl.name === 'String';
    }

    /** Binary numeric promotion. */
    promote(a: SymType, b: SymType): SymType {
        const ua = this.unbox(a);
        const ub = this.unbox(b);
        if (ua.kind !== 'primitive' || ub.kind !== 'primitive') return ERROR_TYPE;
        const rank = Math.max(NUMERIC_RANK[ua.name] ?? 0, NUMERIC_RANK[ub.name] ?? 0, NUMERIC_RANK.int!);
        const name = Object.entries(NUMERIC_RANK).find(([n, r]) => r === rank && n !== 'char')![0];
        return { kind: 'primitive', name: name as 'int' };
    }

    isAssignable(target: SymType, source: SymType): boolean {
        if (isLenient(target) || isLenient(source)) return true;
        if (source.kind === 'qualifier' || target.kind === 'qualifier') return false;
        if (source.kind === 'null') return target.kind !== 'primitive';
        if (target.kind === 'primitive') {
            const s = this.unbox(source);
            return s.kind === 'primitive' && widens(s.name, target.name);
        }
        if (source.kind === 'primitive') {
            return this.isSubtype(this.box(source), target);
        }
        return this.isSubtype(source, target);
    }

    isSubtype(sub: SymType, sup: SymType): boolean {
        if (isLenient(sub) || isLenient(sup)) return true;
        if (this.equal(sub, sup)) return true;
        if (sup.kind === 'object' && isJavaLang(sup.decl) && sup.decl.name === 'Object' && sub.kind !== 'primitive') return true;
        if (sub.kind === 'null') return sup.kind !== 'primitive';
        if (sub.kind === 'typevar') {
            if (sup.kind === 'typevar') return sub.decl === sup.decl;
            return sub.decl.bounds.some((b) => this.isSubtype(typeOfMCType(b), sup));
        }
        if (sub.kind === 'array' && sup.kind === 'array') {
            if (sub.component.kind === 'primitive' || sup.component.kind === 'primitive') return this.equal(sub.component, sup.component);
            return this.isSubtype(sub.component, sup.component);
        }
        if (sub.kind === 'object' && sup.kind === 'object') {
            const ancestor = this.ancestor(sub, sup.decl);
            if (ancestor?.kind !== 'object') return false;
            if (sup.args.length === 0 || ancestor.args.length === 0) return true;
            if (sup.args.length !== ancestor.args.length) return false;
            return sup.args.every((a, i) => this.containsArg(a, ancestor.args[i]!));
        }
        return false;
    }

    /** Whether a supertype's type argument admits the subtype's (wildcards are covariant/contravariant). */
    private containsArg(supArg: SymType, subArg: SymType): boolean {
        if (isLenient(supArg) || isLenient(subArg)) return true;
        if (supArg.kind === 'wildcard') {
            if (supArg.upper) return this.isSubtype(this.box(subArg), supArg.upper);
            if (supArg.lower) return this.isSubtype(supArg.lower, this.box(subArg));
            return true;
        }
        return this.equal(this.box(supArg), this.box(subArg));
    }

    /** The supertype of `t` whose declaration is `decl`, with type arguments substituted. */
    ancestor(t: SymType, decl: CDType, seen = new Set<CDType>()): SymType | undefined {
        if (t.kind !== 'object') return undefined;
        if (t.decl === decl) return t;
        if (seen.has(t.decl)) return undefined;
        seen.add(t.decl);
        for (const s of this.directSupertypes(t)) {
            const found = this.ancestor(s, decl, seen);
            if (found) return found;
        }
        return undefined;
    }

    directSupertypes(t: SymType): SymType[] {
        if (t.kind !== 'object') return [];
        const object = this.objectType('java.lang.Object');
        const isObject = object.kind === 'object' && object.decl === t.decl;
        if (t.decl.$type !== 'CDClass') return isObject ? [] : [object];
        const cls: CDClass = t.decl;
        const subst = bind(cls.typeParams, t.args);
        const declared = [...cls.superTypes, ...cls.interfaces].map((r) => substitute(typeOfMCType(r), subst));
        // Every class without a superclass extends Object (methods such as equals come from there).
        return cls.superTypes.length === 0 && !isObject ? [...declared, object] : declared;
    }

    equal(a: SymType, b: SymType): boolean {
        if (a === b) return true;
        if (a.kind !== b.kind) return false;
        switch (a.kind) {
            case 'primitive':
                return a.name === (b as typeof a).name;
            case 'typevar':
                return a.decl === (b as typeof a).decl;
            case 'array':
                return this.equal(a.component, (b as typeof a).component);
            case 'object': {
                const o = b as typeof a;
                return (
                    a.decl === o.decl &&
                    a.args.length === o.args.length &&
                    a.args.every((x, i) => this.equal(this.box(x), this.box(o.args[i]!)))
                );
            }
            case 'null':
                return true;
            default:
                return false;
        }
    }

    /** Whether `arg` satisfies the bounds of type parameter `param` under `subst`. */
    satisfiesBounds(param: TypeParameter, arg: SymType, subst: ReadonlyMap<TypeParameter, SymType>): boolean {
        return param.bounds.every((b) => this.isSubtype(this.box(arg), this.box(substitute(typeOfMCType(b), subst))));
    }
}

function isLenient(t: SymType): boolean {
    return t.kind === 'error' || t.kind === 'unknown';
}

function widens(from: string, to: string): boolean {
    if (from === to) return true;
    if (from === 'boolean' || to === 'boolean' || to === 'char') return false;
    if (from === 'char') return ['int', 'long', 'float', 'double'].includes(to);
    return (NUMERIC_RANK[from] ?? 99) < (NUMERIC_RANK[to] ?? 0);
}

function isJavaLang(decl: CDType): boolean {
    return cdPackageOf(decl) === 'java.lang';
}
