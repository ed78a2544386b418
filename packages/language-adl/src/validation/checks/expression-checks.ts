import { AstUtils, type ValidationAcceptor, type ValidationChecks } from 'langium';
import type { AdlAstType, Expression, Field, Parameter } from '../../generated/ast.js';
import { isNameExpression, isPort } from '../../generated/ast.js';
import type { AdlServices } from '../../adl-module.js';
import type { ExpressionTyper } from '../../types/expression-typer.js';
import type { TypeRelations } from '../../types/type-relations.js';
import { typeOfMCType } from '../../types/type-resolver.js';
import { BOOLEAN, isErroneous, printType, type SymType } from '../../types/sym-type.js';
import { Codes } from '../codes.js';

/**
 * Typing of expressions and statements: the checks every behavior language reuses for its
 * guards and actions (through `checkExpression`/`expectType`), and the host's own initializers.
 */
export class ExpressionChecks {
    private readonly typer: ExpressionTyper;
    private readonly rel: TypeRelations;

    constructor(services: AdlServices) {
        this.typer = services.maa.ExpressionTyper;
        this.rel = services.maa.TypeRelations;
    }

    /** Types a root expression, reports its problems, and returns its type. */
    checkExpression(expr: Expression, accept: ValidationAcceptor): SymType {
        const problems: Parameters<ExpressionTyper['typeOf']>[1] = [];
        const t = this.typer.typeOf(expr, problems);
        for (const p of problems) accept('error', p.message, { node: p.node, code: p.code });
        if (t.kind === 'qualifier') {
            accept('error', `${t.description} is not a value`, { node: expr, code: Codes.ExprTypeMismatch });
            return { kind: 'error' };
        }
        return t;
    }

    /** Types a root expression and reports `code` when it does not fit `expected`. */
    expectType(expr: Expression, expected: SymType, accept: ValidationAcceptor, code: string, what: string): void {
        const t = this.checkExpression(expr, accept);
        if (!isErroneous(t) && !isErroneous(expected) && !this.rel.isAssignable(expected, t)) {
            accept('error', `${what} must be of type ${printType(expected)}, but the expression is of type ${printType(t)}.`, {
                node: expr,
                code,
            });
        }
    }

    /** Ports are values of a time slice; they cannot configure or initialize a component. */
    checkStaticContext(expr: Expression, accept: ValidationAcceptor, where: string): void {
        for (const n of [expr, ...AstUtils.streamAllContents(expr)]) {
            if (isNameExpression(n) && isPort(n.ref?.ref)) {
                accept(
                    'error',
                    `Port '${n.ref?.$refText ?? ''}' cannot be used in ${where}: ports carry values only while the component runs.`,
                    { node: n, code: Codes.PortInStaticContext },
                );
            }
        }
    }

    readonly checks: ValidationChecks<AdlAstType> = {
        Field: (f: Field, accept) => {
            if (!f.init) return;
            const decl = f.$container;
            if (!decl?.type) return;
            this.checkStaticContext(f.init, accept, `the initializer of field '${f.name}'`);
            this.expectType(f.init, typeOfMCType(decl.type), accept, Codes.FieldInitTypeMismatch, `The initial value of field '${f.name}'`);
        },
        Parameter: (p: Parameter, accept) => {
            if (!p.default || !p.type) return;
            this.checkStaticContext(p.default, accept, `the default value of parameter '${p.name}'`);
            this.expectType(
                p.default,
                typeOfMCType(p.type),
                accept,
                Codes.ParamDefaultTypeMismatch,
                `The default value of parameter '${p.name}'`,
            );
        },
        ExpressionStatement: (s, accept) => {
            this.checkExpression(s.expression, accept);
        },
        LocalVariableDeclaration: (d, accept) => {
            const t = typeOfMCType(d.type);
            for (const v of d.variables) {
                if (v.init) this.expectType(v.init, t, accept, Codes.ExprTypeMismatch, `The initial value of '${v.name}'`);
            }
        },
        IfStatement: (s, accept) => this.condition(s.condition, accept),
        WhileStatement: (s, accept) => this.condition(s.condition, accept),
        ForStatement: (s, accept) => {
            if (s.condition) this.condition(s.condition, accept);
            for (const u of s.updates) this.checkExpression(u, accept);
        },
    };

    private condition(e: Expression, accept: ValidationAcceptor): void {
        this.expectType(e, BOOLEAN, accept, Codes.ExprTypeMismatch, 'A condition');
    }
}
