import { AstUtils, type AstNode, type ValidationAcceptor, type ValidationChecks } from 'langium';
import type {
    AdlAstType,
    ComponentType,
    ComponentTypeRef,
    Expression,
    Parameter,
    ParentComponent,
    ReferenceType,
    Subcomponent,
} from '../../generated/ast.js';
import {
    isAssignmentExpression,
    isNameExpression,
    isParentComponent,
    isPostfixExpression,
    isPrefixExpression,
} from '../../generated/ast.js';
import type { AdlServices } from '../../adl-module.js';
import { allPorts, ownPorts, parentsOf, substitutionFor } from '../../components/component-model.js';
import type { TypeRelations } from '../../types/type-relations.js';
import { bind, typeOfMCType } from '../../types/type-resolver.js';
import { BOOLEAN, isErroneous, printType, substitute, type Substitution } from '../../types/sym-type.js';
import { Codes } from '../codes.js';
import { ExpressionChecks } from './expression-checks.js';

/**
 * Context conditions of instantiation: configuration arguments of subcomponents and parents
 * (arity, keys, types, no side effects, no ports), type arguments (arity, bounds, raw use),
 * and ports redeclared from a parent.
 */
export class InstantiationChecks {
    private readonly rel: TypeRelations;
    private readonly expressions: ExpressionChecks;

    constructor(services: AdlServices) {
        this.rel = services.maa.TypeRelations;
        this.expressions = new ExpressionChecks(services);
    }

    readonly checks: ValidationChecks<AdlAstType> = {
        Subcomponent: (s, accept) => {
            const container = s.$container;
            if (container.$type === 'ComponentType') {
                this.checkArguments(s, container, new Map(), s.args, accept);
            } else {
                const decl = container.type?.ref?.ref;
                if (decl) this.checkArguments(s, decl, substitutionFor(container.type), s.args, accept);
            }
        },
        ParentComponent: (p, accept) => {
            const decl = p.type?.ref?.ref;
            if (decl) this.checkArguments(p, decl, substitutionFor(p.type), p.args, accept);
        },
        ComponentTypeRef: (r, accept) => this.checkTypeArguments(r, accept),
        ReferenceType: (r, accept) => this.checkDataTypeArguments(r, accept),
        ComponentType: (c, accept) => this.checkInheritedPorts(c, accept),
    };

    /** The configuration arguments of a subcomponent or parent against the parameters (and features) of `decl`. */
    private checkArguments(
        owner: Subcomponent | ParentComponent,
        decl: ComponentType,
        subst: Substitution,
        args: readonly Expression[],
        accept: ValidationAcceptor,
    ): void {
        const binding: ArgumentBinding = {
            what: isParentComponent(owner) ? `parent '${decl.name}'` : `subcomponent '${owner.name}'`,
            decl,
            subst,
            bound: new Map(),
            boundFeatures: new Set(),
            sawKey: false,
        };
        for (const [index, arg] of args.entries()) this.checkArgument(binding, arg, index, accept);
        this.checkArgumentCount(owner, binding, args, accept);
    }

    /** One argument: no side effects, static, then bound to a feature, a parameter by key, or a parameter by position. */
    private checkArgument(b: ArgumentBinding, arg: Expression, index: number, accept: ValidationAcceptor): void {
        const key = keyOf(arg);
        const value = key ? (arg as { right?: Expression }).right : arg;
        if (!value) return; // `key =` without a value: partially parsed, the syntax error is reported
        this.checkSideEffects(arg, key !== undefined, accept);
        this.expressions.checkStaticContext(value, accept, `the arguments of ${b.what}`);
        let param: Parameter | undefined;
        if (key) {
            b.sawKey = true;
            const target = key.ref?.ref;
            if (target?.$type === 'Feature') {
                this.checkFeatureBinding(b, arg, key, value, accept);
                return;
            }
            param = target as Parameter | undefined;
            if (!param) return; // unknown key, reported by linking as arc/unknown-argument-key
        } else {
            if (b.sawKey) {
                accept('error', `Positional argument ${index + 1} of ${b.what} follows a key argument; positional arguments come first.`, {
                    node: arg,
                    code: Codes.PositionalAfterKey,
                });
                return;
            }
            if (index >= b.decl.params.length) {
                // too many, reported by checkArgumentCount; still type the value
                this.expressions.checkExpression(value, accept);
                return;
            }
            param = b.decl.params[index];
        }
        if (param) this.checkParameterValue(b, param, arg, value, accept);
    }

    /** A feature binding (`sub(f = true)`): a boolean, once per feature. */
    private checkFeatureBinding(
        b: ArgumentBinding,
        arg: Expression,
        key: Expression & { $type: 'NameExpression' },
        value: Expression,
        accept: ValidationAcceptor,
    ): void {
        const target = key.ref?.ref;
        this.expressions.expectType(
            value,
            BOOLEAN,
            accept,
            Codes.ArgumentTypeMismatch,
            `The binding of feature '${key.ref?.$refText ?? ''}'`,
        );
        if (b.boundFeatures.has(target))
            accept('error', `Feature '${key.ref?.$refText ?? ''}' of ${b.decl.name} gets more than one value.`, {
                node: arg,
                code: Codes.ArgumentMultipleValues,
            });
        b.boundFeatures.add(target);
    }

    /** The value of a parameter: given once, of a type assignable to the parameter's. */
    private checkParameterValue(
        b: ArgumentBinding,
        param: Parameter,
        arg: Expression,
        value: Expression,
        accept: ValidationAcceptor,
    ): void {
        if (b.bound.has(param)) {
            accept('error', `Parameter '${param.name}' of ${b.decl.name} gets more than one value.`, {
                node: arg,
                code: Codes.ArgumentMultipleValues,
            });
            return;
        }
        b.bound.set(param, arg);
        const expected = typeOfMCType(param.type, b.subst);
        const actual = this.expressions.checkExpression(value, accept);
        if (!isErroneous(expected) && !isErroneous(actual) && !this.rel.isAssignable(expected, actual)) {
            accept(
                'error',
                `Argument for parameter '${param.name}' of ${b.decl.name} must be of type ${printType(expected)}, but is of type ${printType(actual)}.`,
                { node: value, code: Codes.ArgumentTypeMismatch },
            );
        }
    }

    /** Not more values than parameters (feature bindings aside), and a value for each parameter without a default. */
    private checkArgumentCount(
        owner: Subcomponent | ParentComponent,
        b: ArgumentBinding,
        args: readonly Expression[],
        accept: ValidationAcceptor,
    ): void {
        const { decl, what } = b;
        const valueArgs = args.filter((a) => keyOf(a)?.ref?.ref?.$type !== 'Feature');
        if (valueArgs.length > decl.params.length) {
            accept('error', `${cap(what)} gets ${valueArgs.length} argument(s), but ${decl.name} has ${decl.params.length} parameter(s).`, {
                node: valueArgs[decl.params.length]!,
                code: Codes.TooManyArguments,
            });
        }
        const missing = decl.params.filter((p) => !p.default && !b.bound.has(p));
        if (missing.length > 0) {
            const msg = `${cap(what)} lacks a value for parameter${missing.length > 1 ? 's' : ''} ${missing.map((p) => `'${p.name}'`).join(', ')} of ${decl.name}.`;
            if (isParentComponent(owner)) accept('error', msg, { node: owner, code: Codes.TooFewArguments });
            else accept('error', msg, { node: owner, property: 'name', code: Codes.TooFewArguments });
        }
    }

    /** Arguments configure a component once: no assignments, increments or decrements in them. */
    private checkSideEffects(arg: Expression, isKey: boolean, accept: ValidationAcceptor): void {
        if (isAssignmentExpression(arg) && !isKey) {
            accept('error', `An argument cannot contain the assignment '${arg.op}'; write 'key = value' to name a parameter.`, {
                node: arg,
                code: Codes.AssignmentInArgument,
            });
            return;
        }
        const start: AstNode | undefined = isKey ? (arg as { right?: Expression }).right : arg;
        if (!start) return; // `key =` without a value: partially parsed
        for (const n of [start, ...AstUtils.streamAllContents(start)]) {
            if (isAssignmentExpression(n) || ((isPrefixExpression(n) || isPostfixExpression(n)) && (n.op === '++' || n.op === '--'))) {
                accept(
                    'error',
                    `An argument cannot ${isAssignmentExpression(n) ? `contain the assignment '${n.op}'` : `use '${(n as { op: string }).op}'`}: arguments must not have side effects.`,
                    { node: n, code: Codes.AssignmentInArgument },
                );
                return;
            }
        }
    }

    private checkTypeArguments(r: ComponentTypeRef, accept: ValidationAcceptor): void {
        const decl = r.ref?.ref;
        if (!decl) return;
        const params = decl.typeParams;
        if (r.typeArgs.length === 0) {
            if (params.length > 0) {
                accept(
                    'warning',
                    `Generic component type '${decl.name}' is used without type arguments; give ${params.map((p) => p.name).join(', ')}.`,
                    { node: r, code: Codes.RawGeneric },
                );
            }
            return;
        }
        this.checkArity(r, decl.name, params.length, r.typeArgs.length, accept);
        const args = r.typeArgs.map((a) => typeOfMCType(a));
        const subst = bind(params, args);
        params.forEach((p, i) => {
            const a = args[i];
            if (a && !isErroneous(a) && !this.rel.satisfiesBounds(p, a, subst)) {
                accept(
                    'error',
                    `Type argument ${printType(a)} does not satisfy the bound of type parameter '${p.name}' of ${decl.name} (${p.bounds.map((b) => printType(substitute(typeOfMCType(b), subst))).join(' & ')}).`,
                    { node: r.typeArgs[i]!, code: Codes.TypeArgBound },
                );
            }
        });
    }

    private checkDataTypeArguments(r: ReferenceType, accept: ValidationAcceptor): void {
        const decl = r.ref?.ref;
        if (!decl || r.typeArgs.length === 0) return;
        const params = decl.$type === 'CDClass' ? decl.typeParams : [];
        this.checkArity(r, decl.name, params.length, r.typeArgs.length, accept);
        const args = r.typeArgs.map((a) => typeOfMCType(a));
        const subst = bind(params, args);
        params.forEach((p, i) => {
            const a = args[i];
            if (a && a.kind !== 'wildcard' && !isErroneous(a) && !this.rel.satisfiesBounds(p, a, subst)) {
                accept('error', `Type argument ${printType(a)} does not satisfy the bound of type parameter '${p.name}' of ${decl.name}.`, {
                    node: r.typeArgs[i]!,
                    code: Codes.TypeArgBound,
                });
            }
        });
    }

    private checkArity(node: AstNode, name: string, expected: number, actual: number, accept: ValidationAcceptor): void {
        if (actual > expected) {
            accept('error', `${name} has ${expected} type parameter(s) but gets ${actual} type argument(s).`, {
                node,
                code: Codes.TooManyTypeArgs,
            });
        } else if (actual < expected) {
            accept('error', `${name} has ${expected} type parameter(s) but gets only ${actual} type argument(s).`, {
                node,
                code: Codes.TooFewTypeArgs,
            });
        }
    }

    /** A redeclared inherited port keeps the direction; incoming ports may narrow the type, outgoing ports widen it. */
    private checkInheritedPorts(c: ComponentType, accept: ValidationAcceptor): void {
        if (c.parents.length === 0) return;
        const inherited = parentsOf(c).flatMap((p) => allPorts(p.decl, p.subst));
        for (const own of ownPorts(c)) {
            for (const sup of inherited.filter((p) => p.name === own.name)) {
                if (sup.direction !== own.direction) {
                    accept(
                        'error',
                        `Port '${own.name}' is ${own.direction === 'in' ? 'incoming' : 'outgoing'} but redeclares the ${sup.direction === 'in' ? 'incoming' : 'outgoing'} port '${sup.name}' of '${sup.owner.name}'.`,
                        { node: own.port, property: 'name', code: Codes.InheritedPortDirectionMismatch },
                    );
                    continue;
                }
                if (isErroneous(own.type) || isErroneous(sup.type)) continue;
                const ok = own.direction === 'in' ? this.rel.isAssignable(sup.type, own.type) : this.rel.isAssignable(own.type, sup.type);
                if (!ok) {
                    accept(
                        'error',
                        `Port '${own.name}' of type ${printType(own.type)} redeclares port '${sup.name}' of '${sup.owner.name}' of type ${printType(sup.type)}; ${own.direction === 'in' ? 'an incoming port may only narrow' : 'an outgoing port may only widen'} the inherited type.`,
                        { node: own.port, property: 'name', code: Codes.InheritedPortTypeMismatch },
                    );
                }
            }
        }
    }
}

/** What the arguments of one instantiation have bound so far. */
interface ArgumentBinding {
    /** How messages name the instantiation: `subcomponent 's'` or `parent 'P'`. */
    readonly what: string;
    readonly decl: ComponentType;
    readonly subst: Substitution;
    readonly bound: Map<Parameter, Expression>;
    readonly boundFeatures: Set<unknown>;
    /** A key argument came before: positional ones may no longer follow. */
    sawKey: boolean;
}

/** The key of a key argument `p = value`, if the argument is one. */
function keyOf(arg: Expression): (Expression & { $type: 'NameExpression' }) | undefined {
    if (isAssignmentExpression(arg) && arg.op === '=' && isNameExpression(arg.left)) return arg.left as never;
    return undefined;
}

function cap(s: string): string {
    return s.charAt(0).toUpperCase() + s.slice(1);
}
