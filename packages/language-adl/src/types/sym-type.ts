import type { CDType, PrimitiveName, TypeParameter } from '../generated/ast.js';

/**
 * Semantic types of the family (MontiCore's SymTypeExpressions, trimmed): what an MCType
 * denotes and what an expression evaluates to.
 */
export type SymType =
    | { readonly kind: 'primitive'; readonly name: PrimitiveName }
    | { readonly kind: 'object'; readonly decl: CDType; readonly args: readonly SymType[] }
    | { readonly kind: 'typevar'; readonly decl: TypeParameter }
    | { readonly kind: 'array'; readonly component: SymType }
    | { readonly kind: 'wildcard'; readonly upper?: SymType; readonly lower?: SymType }
    | { readonly kind: 'null' }
    /** A type that is unknown because of an error reported elsewhere; fits everything. */
    | { readonly kind: 'error' }
    /** A free type variable of a generic method call (e.g. `Collections.emptyList()`); fits everything. */
    | { readonly kind: 'unknown' }
    /** A non-value: a package prefix, a type used as a qualifier, a subcomponent, a component. */
    | { readonly kind: 'qualifier'; readonly description: string; readonly typeDecl?: CDType };

export const ERROR_TYPE: SymType = { kind: 'error' };
export const UNKNOWN_TYPE: SymType = { kind: 'unknown' };
export const NULL_TYPE: SymType = { kind: 'null' };

export function primitive(name: PrimitiveName): SymType {
    return { kind: 'primitive', name };
}

export const BOOLEAN = primitive('boolean');
export const INT = primitive('int');
export const LONG = primitive('long');
export const FLOAT = primitive('float');
export const DOUBLE = primitive('double');
export const CHAR = primitive('char');

export function isErroneous(t: SymType): boolean {
    return t.kind === 'error' || t.kind === 'unknown';
}

export function isValue(t: SymType): boolean {
    return t.kind !== 'qualifier';
}

/** Substitution of type variables (a type parameter's declaration to its argument). */
export type Substitution = ReadonlyMap<TypeParameter, SymType>;

export const EMPTY_SUBSTITUTION: Substitution = new Map();

export function substitute(t: SymType, s: Substitution): SymType {
    if (s.size === 0) return t;
    switch (t.kind) {
        case 'typevar':
            return s.get(t.decl) ?? t;
        case 'object':
            return t.args.length === 0 ? t : { kind: 'object', decl: t.decl, args: t.args.map((a) => substitute(a, s)) };
        case 'array':
            return { kind: 'array', component: substitute(t.component, s) };
        case 'wildcard':
            return {
                kind: 'wildcard',
                upper: t.upper && substitute(t.upper, s),
                lower: t.lower && substitute(t.lower, s),
            };
        default:
            return t;
    }
}

export function printType(t: SymType): string {
    switch (t.kind) {
        case 'primitive':
            return t.name;
        case 'object': {
            const name = t.decl.name;
            return t.args.length === 0 ? name : `${name}<${t.args.map(printType).join(', ')}>`;
        }
        case 'typevar':
            return t.decl.name;
        case 'array':
            return `${printType(t.component)}[]`;
        case 'wildcard':
            return t.upper ? `? extends ${printType(t.upper)}` : t.lower ? `? super ${printType(t.lower)}` : '?';
        case 'null':
            return 'null';
        case 'error':
        case 'unknown':
            return '<unknown>';
        case 'qualifier':
            return t.description;
    }
}
