import type { AstNode } from 'langium';
import type {
    BinaryExpression,
    CallExpression,
    CDAttribute,
    CDClass,
    CDMethod,
    CDType,
    Expression,
    FieldAccessExpression,
    NameExpression,
    Port,
    SwitchExpression,
} from '../generated/ast.js';
import {
    isCDClass,
    isCDEnum,
    isFieldAccessExpression,
    isFieldDeclaration,
    isLocalVariableDeclaration,
    isNameExpression,
} from '../generated/ast.js';
import { notAConstantMessage, yieldsOf } from '../scoping/switch-labels.js';
import { portHeader } from '../components/component-model.js';
import { subcomponentFeature } from '../components/features.js';
import type { NameResolver } from '../scoping/name-resolver.js';
import { bind, typeOfMCType } from './type-resolver.js';
import type { TypeRelations } from './type-relations.js';
import {
    BOOLEAN,
    CHAR,
    DOUBLE,
    ERROR_TYPE,
    FLOAT,
    INT,
    LONG,
    NULL_TYPE,
    UNKNOWN_TYPE,
    isErroneous,
    printType,
    substitute,
    type SymType,
} from './sym-type.js';

export interface TypeProblem {
    readonly node: AstNode;
    readonly message: string;
    readonly code: 'expr/type-mismatch' | 'expr/unresolved-name';
}

/**
 * Computes the type of an expression and collects the problems found on the way, each on the
 * smallest offending sub-expression. Callers type a root expression once and report its problems.
 */
export class ExpressionTyper {
    constructor(
        private readonly rel: TypeRelations,
        private readonly resolver: NameResolver,
    ) {}

    typeOf(expr: Expression, problems: TypeProblem[] = []): SymType {
        return this.type(expr, problems);
    }

    /** The type of the element a name denotes (ports, fields, parameters, variables, constants). */
    typeOfNamed(node: AstNode): SymType {
        switch (node.$type) {
            case 'Port':
                return typeOfMCType(portHeader(node as Port).type);
            case 'Field':
                return isFieldDeclaration(node.$container) ? typeOfMCType(node.$container.type) : ERROR_TYPE;
            case 'Parameter':
            case 'CDAttribute':
                return typeOfMCType((node as CDAttribute).type);
            case 'LocalVariable':
                return isLocalVariableDeclaration(node.$container) ? typeOfMCType(node.$container.type) : ERROR_TYPE;
            case 'CDEnumConstant':
                return { kind: 'object', decl: node.$container as CDType, args: [] };
            case 'CDClass':
            case 'CDEnum':
                return { kind: 'qualifier', description: `type ${(node as CDType).name}`, typeDecl: node as CDType };
            case 'TypeParameter':
                return { kind: 'qualifier', description: `type parameter ${(node as unknown as { name: string }).name}` };
            case 'Feature':
                return BOOLEAN;
            case 'Subcomponent':
                return { kind: 'qualifier', description: `subcomponent ${(node as unknown as { name: string }).name}` };
            case 'ComponentType':
                return { kind: 'qualifier', description: `component ${(node as unknown as { name: string }).name}` };
            default:
                return ERROR_TYPE;
        }
    }

    private type(e: Expression | undefined, p: TypeProblem[]): SymType {
        if (!e) return ERROR_TYPE; // partially parsed: the syntax error is reported already
        switch (e.$type) {
            case 'BooleanLiteral':
                return BOOLEAN;
            case 'IntLiteral':
                return INT;
            case 'LongLiteral':
                return LONG;
            case 'FloatLiteral':
                return /[fF]$/.test(e.value) ? FLOAT : DOUBLE;
            case 'CharLiteral':
                return CHAR;
            case 'StringLiteral':
                return this.rel.objectType('java.lang.String');
            case 'NullLiteral':
                return NULL_TYPE;
            case 'NameExpression':
                return this.name(e, p);
            case 'FieldAccessExpression':
                return this.fieldAccess(e, p);
            case 'CallExpression':
                return this.call(e, p);
            case 'ArrayAccessExpression': {
                const r = this.value(e.receiver, p);
                const i = this.value(e.index, p);
                if (!isErroneous(i) && !this.rel.isIntegral(i))
                    p.push(mismatch(e.index, `an array index must be integral, not ${printType(i)}`));
                if (r.kind === 'array') return r.component;
                if (!isErroneous(r)) p.push(mismatch(e.receiver, `${printType(r)} is not an array`));
                return ERROR_TYPE;
            }
            case 'PrefixExpression': {
                const t = this.value(e.operand, p);
                if (isErroneous(t)) return t;
                if (e.op === '!') return this.expect(e.operand, t, 'boolean', p) ? BOOLEAN : ERROR_TYPE;
                if (e.op === '~')
                    return this.rel.isIntegral(t)
                        ? this.rel.promote(t, INT)
                        : fail(p, e.operand, `'~' needs an integral operand, not ${printType(t)}`);
                if (!this.rel.isNumeric(t)) return fail(p, e.operand, `'${e.op}' needs a numeric operand, not ${printType(t)}`);
                return e.op === '++' || e.op === '--' ? t : this.rel.promote(t, INT);
            }
            case 'CastExpression': {
                // Java's primitive casts (JLS 5.5): numeric to numeric (char included, boxes
                // unboxed first), boolean to boolean only.
                const target = typeOfMCType(e.type);
                const t = this.value(e.operand, p);
                if (isErroneous(t) || isErroneous(target)) return target;
                const source = this.rel.unbox(t);
                const ok =
                    target.kind === 'primitive' &&
                    source.kind === 'primitive' &&
                    (target.name === 'boolean') === (source.name === 'boolean') &&
                    target.name !== 'void' &&
                    source.name !== 'void';
                return ok ? target : fail(p, e, `a value of type ${printType(t)} cannot be cast to ${printType(target)}`);
            }
            case 'PostfixExpression': {
                const t = this.value(e.operand, p);
                if (!isErroneous(t) && !this.rel.isNumeric(t))
                    return fail(p, e.operand, `'${e.op}' needs a numeric operand, not ${printType(t)}`);
                return t;
            }
            case 'BinaryExpression':
                return this.binary(e, p);
            case 'SwitchExpression':
                return this.switchExpression(e, p);
            case 'ConditionalExpression': {
                const c = this.value(e.condition, p);
                this.expect(e.condition, c, 'boolean', p);
                const a = this.value(e.then, p);
                const b = this.value(e.else, p);
                if (isErroneous(a)) return b;
                if (isErroneous(b)) return a;
                if (this.rel.isNumeric(a) && this.rel.isNumeric(b)) return this.rel.promote(a, b);
                if (this.rel.isAssignable(a, b)) return a;
                if (this.rel.isAssignable(b, a)) return b;
                return fail(p, e, `the branches of '?:' have incompatible types ${printType(a)} and ${printType(b)}`);
            }
            case 'AssignmentExpression': {
                const l = this.value(e.left, p);
                const r = this.value(e.right, p);
                if (!isAssignable(e.left)) p.push(mismatch(e.left, 'the left side of an assignment must be a variable, a field or a port'));
                if (isErroneous(l) || isErroneous(r)) return l;
                if (e.op === '=') {
                    if (!this.rel.isAssignable(l, r)) p.push(mismatch(e.right, `cannot assign ${printType(r)} to ${printType(l)}`));
                } else if (e.op === '+=' && this.rel.isString(l)) {
                    // string concatenation
                } else if (!this.rel.isNumeric(l) || !this.rel.isNumeric(r)) {
                    if (!(['&=', '|=', '^='].includes(e.op) && this.rel.isBoolean(l) && this.rel.isBoolean(r))) {
                        p.push(mismatch(e, `'${e.op}' needs numeric operands, not ${printType(l)} and ${printType(r)}`));
                    }
                }
                return l;
            }
            default:
                // A node the parser's error recovery left without its expression type.
                return ERROR_TYPE;
        }
    }

    /** The type of a sub-expression that must denote a value. */
    /**
     * A switch expression: its selector and labels (reported here, as parts of the root
     * expression), and the common type of its arms, as for `?:` (numeric promotion, else the arm
     * the others are assignable to). The values of `yield` statements in block arms are typed
     * without reporting: their statements report them (statement-checks.ts).
     */
    private switchExpression(e: SwitchExpression, p: TypeProblem[]): SymType {
        const selector = this.value(e.selector, p);
        const en = selector.kind === 'object' && isCDEnum(selector.decl) ? selector.decl : undefined;
        for (const arm of e.arms) {
            for (const v of arm.label?.values ?? []) {
                if (en && isNameExpression(v) && !v.ref.ref) unresolved(p, v, notAConstantMessage(v, en));
                else this.value(v, p);
            }
        }
        const arms: Array<{ node: AstNode; t: SymType }> = [];
        for (const arm of e.arms) {
            if (arm.value) arms.push({ node: arm.value, t: this.value(arm.value, p) });
            else if (arm.body) for (const y of yieldsOf(arm.body)) arms.push({ node: y.value, t: this.value(y.value, []) });
        }
        let result: SymType | undefined;
        for (const { node, t } of arms) {
            if (isErroneous(t)) continue;
            if (!result) result = t;
            else if (this.rel.isNumeric(result) && this.rel.isNumeric(t)) result = this.rel.promote(result, t);
            else if (this.rel.isAssignable(t, result)) result = t;
            else if (!this.rel.isAssignable(result, t)) {
                return fail(p, node, `the arms of a switch expression have incompatible types ${printType(result)} and ${printType(t)}`);
            }
        }
        return result ?? ERROR_TYPE;
    }

    private value(e: Expression | undefined, p: TypeProblem[]): SymType {
        const t = this.type(e, p);
        if (t.kind === 'qualifier' && e) {
            p.push(mismatch(e, `${t.description} is not a value`));
            return ERROR_TYPE;
        }
        return t;
    }

    private expect(node: AstNode, t: SymType, what: 'boolean', p: TypeProblem[]): boolean {
        if (isErroneous(t) || this.rel.isBoolean(t)) return true;
        p.push(mismatch(node, `expected a ${what} expression, found ${printType(t)}`));
        return false;
    }

    private name(e: NameExpression, p: TypeProblem[]): SymType {
        const target = e.ref?.ref; // no reference: partially parsed
        if (target) return this.typeOfNamed(target);
        const name = e.ref?.$refText ?? '';
        if (isFieldAccessExpression(e.$container) && e.$container.receiver === e && this.resolver.isPackagePrefix(e, name)) {
            return { kind: 'qualifier', description: `package ${name}` };
        }
        p.push({
            node: e,
            code: 'expr/unresolved-name',
            message: `'${name}' is not a port, field, parameter, variable or type visible here`,
        });
        return ERROR_TYPE;
    }

    private fieldAccess(e: FieldAccessExpression, p: TypeProblem[]): SymType {
        const r = this.type(e.receiver, p);
        if (isErroneous(r)) return ERROR_TYPE;
        const member = e.member;
        if (r.kind === 'qualifier') {
            if (r.description.startsWith('package ')) {
                const qn = `${r.description.substring('package '.length)}.${member}`;
                const type = this.resolver.resolveType(e, qn);
                if (type?.node) return this.typeOfNamed(type.node);
                if (this.resolver.isPackagePrefix(e, qn)) return { kind: 'qualifier', description: `package ${qn}` };
                return unresolved(p, e, `'${qn}' is neither a type nor a package`);
            }
            if (r.typeDecl) {
                if (r.typeDecl.$type === 'CDEnum') {
                    if (r.typeDecl.constants.some((c) => c.name === member)) return { kind: 'object', decl: r.typeDecl, args: [] };
                    if (!isCallee(e) && !this.attribute(r.typeDecl, member))
                        return unresolved(p, e, `enum ${r.typeDecl.name} has no constant '${member}'`);
                }
                const attr = this.attribute(r.typeDecl, member);
                if (attr) return typeOfMCType(attr.type);
                if (isCallee(e)) return { kind: 'qualifier', description: `method ${member}`, typeDecl: r.typeDecl };
                return unresolved(p, e, `type ${r.typeDecl.name} has no static member '${member}'`);
            }
            // `sub.f`: a feature of a subcomponent (MontiArc's variable architectures).
            if (subcomponentFeature(e.receiver, member)) return BOOLEAN;
            return unresolved(p, e, `${r.description} has no member '${member}'`);
        }
        if (r.kind === 'array' && member === 'length') return INT;
        const obj = r.kind === 'typevar' ? this.boundOf(r) : this.rel.box(r);
        if (obj.kind === 'object') {
            for (let t: SymType | undefined = obj; t && t.kind === 'object'; t = this.rel.directSupertypes(t)[0]) {
                if (t.decl.$type !== 'CDClass') break;
                const attr = this.attribute(t.decl, member);
                if (attr) return substitute(typeOfMCType(attr.type), bind(t.decl.typeParams, t.args));
            }
            if (isCallee(e)) return { kind: 'qualifier', description: `method ${member}`, typeDecl: obj.decl };
        }
        return unresolved(p, e, `${printType(r)} has no member '${member}'`);
    }

    private call(e: CallExpression, p: TypeProblem[]): SymType {
        const argTypes = e.args.map((a) => this.value(a, p));
        if (!isFieldAccessExpression(e.receiver)) {
            this.type(e.receiver, p);
            return fail(p, e, 'only methods of types can be called (write `Type.method(...)` or `value.method(...)`)');
        }
        const fa = e.receiver;
        const recv = this.type(fa.receiver, p);
        if (isErroneous(recv)) return ERROR_TYPE;
        const name = fa.member;
        let decl: CDType | undefined;
        let args: readonly SymType[] = [];
        if (recv.kind === 'qualifier') {
            if (recv.description.startsWith('package ')) {
                const owner = this.fieldAccess(fa, p);
                return owner.kind === 'qualifier' ? fail(p, e, `${owner.description} cannot be called`) : ERROR_TYPE;
            }
            decl = recv.typeDecl;
        } else {
            const obj = recv.kind === 'typevar' ? this.boundOf(recv) : this.rel.box(recv);
            if (obj.kind === 'object') {
                decl = obj.decl;
                args = obj.args;
            }
        }
        if (!decl) return unresolved(p, fa, `${printType(recv)} has no method '${name}'`);
        const method = this.method({ kind: 'object', decl, args }, name, argTypes);
        if (method) {
            const { m, subst } = method;
            m.params.forEach((param, i) => {
                const at = argTypes[i];
                const pt = substitute(typeOfMCType(param.type), subst);
                if (at && !isErroneous(pt) && pt.kind !== 'typevar' && !this.rel.isAssignable(pt, at)) {
                    p.push(mismatch(e.args[i]!, `argument ${i + 1} of '${name}' must be ${printType(pt)}, not ${printType(at)}`));
                }
            });
            const ret = substitute(typeOfMCType(m.returnType), subst);
            return ret.kind === 'typevar' && m.typeParams.includes(ret.decl) ? UNKNOWN_TYPE : freeMethodVars(ret, m);
        }
        // A class diagram class without declared constructors is constructed MontiArc-style: `T.T(...)`.
        if (decl.name === name && isCDClass(decl)) return { kind: 'object', decl, args: [] };
        return unresolved(p, fa, `type ${decl.name} has no method '${name}' with ${argTypes.length} argument(s)`);
    }

    /** The method a call selects: the first declared overload whose parameters accept the arguments, else the first of that arity. */
    private method(
        t: SymType,
        name: string,
        argTypes: readonly SymType[],
    ): { m: CDMethod; subst: ReadonlyMap<never, SymType> } | undefined {
        const seen = new Set<CDType>();
        const queue: SymType[] = [t];
        let fallback: { m: CDMethod; subst: ReadonlyMap<never, SymType> } | undefined;
        while (queue.length > 0) {
            const cur = queue.shift()!;
            if (cur.kind !== 'object' || seen.has(cur.decl)) continue;
            seen.add(cur.decl);
            if (cur.decl.$type === 'CDClass' || cur.decl.$type === 'CDEnum') {
                const subst = bind(cur.decl.$type === 'CDClass' ? cur.decl.typeParams : [], cur.args) as ReadonlyMap<never, SymType>;
                const candidates = cur.decl.members.filter(
                    (x): x is CDMethod => x.$type === 'CDMethod' && x.name === name && x.params.length === argTypes.length,
                );
                const fitting = candidates.find((m) =>
                    m.params.every((p, i) => {
                        const pt = substitute(typeOfMCType(p.type), subst);
                        return pt.kind === 'typevar' || this.rel.isAssignable(pt, argTypes[i]!);
                    }),
                );
                if (fitting) return { m: fitting, subst };
                if (candidates[0]) fallback ??= { m: candidates[0], subst };
            }
            queue.push(...this.rel.directSupertypes(cur));
        }
        return fallback;
    }

    private attribute(decl: CDType, name: string): CDAttribute | undefined {
        return (decl as CDClass).members.find((m): m is CDAttribute => m.$type === 'CDAttribute' && m.name === name);
    }

    private boundOf(t: SymType): SymType {
        if (t.kind !== 'typevar') return t;
        const b = t.decl.bounds[0];
        return b ? typeOfMCType(b) : this.rel.objectType('java.lang.Object');
    }

    private binary(e: BinaryExpression, p: TypeProblem[]): SymType {
        const l = this.value(e.left, p);
        const r = this.value(e.right, p);
        const op = (e.op ?? '').replace(/\s+/g, ''); // no operator: partially parsed
        const lenient = isErroneous(l) || isErroneous(r);
        switch (op) {
            case '&&':
            case '||':
                this.expect(e.left, l, 'boolean', p);
                this.expect(e.right, r, 'boolean', p);
                return BOOLEAN;
            case '==':
            case '!=':
                if (!lenient && !this.comparable(l, r)) p.push(mismatch(e, `cannot compare ${printType(l)} with ${printType(r)}`));
                return BOOLEAN;
            case '<':
            case '<=':
            case '>':
            case '>=':
                if (!lenient && !(this.rel.isNumeric(l) && this.rel.isNumeric(r)))
                    p.push(mismatch(e, `'${op}' needs numeric operands, not ${printType(l)} and ${printType(r)}`));
                return BOOLEAN;
            // biome-ignore lint/suspicious/noFallthroughSwitchClause: '+' of two numbers is arithmetic, as below
            case '+':
                if (this.rel.isString(l) || this.rel.isString(r)) return this.rel.objectType('java.lang.String');
            case '-':
            case '*':
            case '/':
            case '%':
                if (lenient) return ERROR_TYPE;
                if (!(this.rel.isNumeric(l) && this.rel.isNumeric(r)))
                    return fail(p, e, `'${op}' needs numeric operands, not ${printType(l)} and ${printType(r)}`);
                return this.rel.promote(l, r);
            case '&':
            case '|':
            case '^':
                if (lenient) return ERROR_TYPE;
                if (this.rel.isBoolean(l) && this.rel.isBoolean(r)) return BOOLEAN;
                if (this.rel.isIntegral(l) && this.rel.isIntegral(r)) return this.rel.promote(l, r);
                return fail(p, e, `'${op}' needs two boolean or two integral operands, not ${printType(l)} and ${printType(r)}`);
            default: // shifts
                if (lenient) return ERROR_TYPE;
                if (!(this.rel.isIntegral(l) && this.rel.isIntegral(r)))
                    return fail(p, e, `'${op}' needs integral operands, not ${printType(l)} and ${printType(r)}`);
                return this.rel.promote(l, INT);
        }
    }

    private comparable(l: SymType, r: SymType): boolean {
        if (this.rel.isNumeric(l) && this.rel.isNumeric(r)) return true;
        if (this.rel.isBoolean(l) && this.rel.isBoolean(r)) return true;
        return this.rel.isAssignable(l, r) || this.rel.isAssignable(r, l);
    }
}

function isCallee(e: FieldAccessExpression): boolean {
    return e.$container.$type === 'CallExpression' && (e.$container as CallExpression).receiver === e;
}

function isAssignable(e: Expression): boolean {
    if (e.$type === 'NameExpression') {
        const t = e.ref?.ref?.$type;
        return t === undefined || ['Port', 'Field', 'LocalVariable', 'Parameter'].includes(t);
    }
    return e.$type === 'FieldAccessExpression' || e.$type === 'ArrayAccessExpression';
}

/** Type variables of a generic method that the call does not bind become unknown (inference is out of scope). */
function freeMethodVars(t: SymType, m: CDMethod): SymType {
    if (m.typeParams.length === 0) return t;
    const s = new Map(m.typeParams.map((tp) => [tp, UNKNOWN_TYPE] as const));
    return substitute(t, s);
}

function mismatch(node: AstNode, message: string): TypeProblem {
    return { node, message, code: 'expr/type-mismatch' };
}

function fail(p: TypeProblem[], node: AstNode, message: string): SymType {
    p.push(mismatch(node, message));
    return ERROR_TYPE;
}

function unresolved(p: TypeProblem[], node: AstNode, message: string): SymType {
    p.push({ node, message, code: 'expr/unresolved-name' });
    return ERROR_TYPE;
}
