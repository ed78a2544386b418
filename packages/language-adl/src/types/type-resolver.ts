import type { MCType, TypeArgument, TypeParameter } from '../generated/ast.js';
import { ERROR_TYPE, EMPTY_SUBSTITUTION, substitute, type Substitution, type SymType } from './sym-type.js';

/** The semantic type an MCType denotes (unresolved names give the error type; linking reports them). */
export function typeOfMCType(t: MCType | TypeArgument | undefined, s: Substitution = EMPTY_SUBSTITUTION): SymType {
    if (!t) return ERROR_TYPE;
    switch (t.$type) {
        case 'PrimitiveType':
            return { kind: 'primitive', name: t.name };
        case 'ArrayType':
            return { kind: 'array', component: typeOfMCType(t.component, s) };
        case 'WildcardType':
            return {
                kind: 'wildcard',
                upper: t.upper ? typeOfMCType(t.upper, s) : undefined,
                lower: t.lower ? typeOfMCType(t.lower, s) : undefined,
            };
        case 'ReferenceType': {
            const decl = t.ref.ref;
            if (!decl) return ERROR_TYPE;
            if (decl.$type === 'TypeParameter') return substitute({ kind: 'typevar', decl }, s);
            return { kind: 'object', decl, args: t.typeArgs.map((a) => typeOfMCType(a, s)) };
        }
    }
}

/** Maps type parameters to the given arguments (missing arguments stay unbound). */
export function bind(params: readonly TypeParameter[], args: readonly SymType[]): Substitution {
    const m = new Map<TypeParameter, SymType>();
    params.forEach((p, i) => {
        const a = args[i];
        if (a) m.set(p, a);
    });
    return m;
}
