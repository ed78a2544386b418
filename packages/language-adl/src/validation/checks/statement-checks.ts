import type { AstNode, ValidationAcceptor, ValidationChecks } from 'langium';
import type { AdlAstType, CDEnum, Expression, Statement, SwitchExpression, SwitchLabel, SwitchStatement } from '../../generated/ast.js';
import {
    isBlock,
    isCDEnumConstant,
    isCDEnum,
    isFieldAccessExpression,
    isIfStatement,
    isNameExpression,
    isYieldStatement,
} from '../../generated/ast.js';
import type { AdlServices } from '../../adl-module.js';
import type { ExpressionChecks } from './expression-checks.js';
import type { ExpressionTyper } from '../../types/expression-typer.js';
import type { TypeRelations } from '../../types/type-relations.js';
import { notAConstantMessage, switchOfYield } from '../../scoping/switch-labels.js';
import { BOOLEAN, isErroneous, printType, type SymType } from '../../types/sym-type.js';
import { Codes } from '../codes.js';

/** The selector types Java's switch accepts (JLS 14.11): char, byte, short, int, their boxes, String and enums. */
const SWITCH_PRIMITIVES = new Set(['char', 'byte', 'short', 'int']);

/**
 * Typing and context conditions of Java's control statements beyond if/while/for: `do`-`while`,
 * `switch` (selector and label types, duplicate labels, one default, no mixing of `:` and `->`
 * groups), the switch expression (`->` arms only, exhaustive, block arms ending in `yield`),
 * `yield` (only in a switch expression's block arm) and `break`/`continue` (only inside a loop,
 * `break` also inside a switch; neither leaves a switch expression).
 */
export class StatementChecks {
    private readonly rel: TypeRelations;
    private readonly typer: ExpressionTyper;

    constructor(
        services: AdlServices,
        private readonly expressions: ExpressionChecks,
    ) {
        this.rel = services.maa.TypeRelations;
        this.typer = services.maa.ExpressionTyper;
    }

    readonly checks: ValidationChecks<AdlAstType> = {
        DoWhileStatement: (s, accept) => {
            this.expressions.expectType(s.condition, BOOLEAN, accept, Codes.ExprTypeMismatch, 'A condition');
        },
        SwitchStatement: (s, accept) => this.checkSwitch(s, accept),
        SwitchExpression: (s, accept) => this.checkSwitchExpression(s, accept),
        YieldStatement: (s, accept) => {
            // The value is typed here (the switch expression's type takes it without reporting).
            this.expressions.checkExpression(s.value, accept);
            if (!switchOfYield(s)) {
                accept(
                    'error',
                    "'yield' gives a block arm of a switch expression its value ('case 1 -> { ...; yield v; }'); it is not allowed elsewhere.",
                    { node: s, code: Codes.YieldOutsideSwitchExpression },
                );
            }
        },
        BreakStatement: (s, accept) => {
            const target = jumpTarget(s, true);
            if (target === 'switch-expression') {
                accept('error', "'break' cannot leave a switch expression; give the arm its value with 'yield'.", {
                    node: s,
                    code: Codes.JumpOutOfSwitchExpression,
                });
            } else if (!target) {
                accept('error', "'break' is only allowed inside a loop (while, do, for) or a switch.", {
                    node: s,
                    code: Codes.BreakOutsideLoop,
                });
            }
        },
        ContinueStatement: (s, accept) => {
            const target = jumpTarget(s, false);
            if (target === 'switch-expression') {
                accept('error', "'continue' cannot leave a switch expression; give the arm its value with 'yield'.", {
                    node: s,
                    code: Codes.JumpOutOfSwitchExpression,
                });
            } else if (!target) {
                accept('error', "'continue' is only allowed inside a loop (while, do, for).", { node: s, code: Codes.ContinueOutsideLoop });
            }
        },
    };

    private checkSwitch(s: SwitchStatement, accept: ValidationAcceptor): void {
        const selector = this.expressions.checkExpression(s.selector, accept);
        const labels = s.groups.flatMap((g) => g.labels);
        this.checkLabels(s.selector, selector, labels, accept, true);
        let arrows = 0;
        let colons = 0;
        for (const g of s.groups) {
            for (const label of g.labels) {
                if (label.arrow) arrows++;
                else colons++;
            }
            if (g.labels.some((l) => l.arrow) && (g.labels.length > 1 || g.statements.length !== 1)) {
                accept(
                    'error',
                    "A 'case ... ->' rule has one label and one statement (a block, an expression statement or a throw); list several values in one label: 'case 1, 2 -> ...'.",
                    { node: g, code: Codes.MixedSwitchLabels },
                );
            }
        }
        if (arrows > 0 && colons > 0) {
            accept('error', "A switch uses either 'case ...:' groups or 'case ... ->' rules, not both.", {
                node: s,
                property: 'selector',
                code: Codes.MixedSwitchLabels,
            });
        }
    }

    /**
     * A switch expression: the typer reports the problems of its selector, labels and arms with
     * the root expression; here its label rules, `->` arms, block arms that end in `yield`, and
     * exhaustiveness (a `default`, or every constant of the selector's enum).
     */
    private checkSwitchExpression(s: SwitchExpression, accept: ValidationAcceptor): void {
        if (!s.selector) return; // partially parsed
        const selector = this.typer.typeOf(s.selector, []);
        const labels = s.arms.flatMap((a) => (a.label ? [a.label] : []));
        const covered = this.checkLabels(s.selector, selector, labels, accept, false);
        for (const arm of s.arms) {
            if (arm.label && !arm.label.arrow) {
                accept(
                    'error',
                    "The arms of a switch expression are 'case ... -> value;' or 'case ... -> { ... yield value; }', not 'case ...:'.",
                    { node: arm.label, code: Codes.MixedSwitchLabels },
                );
            }
            if (arm.body && !completesAbruptly(arm.body)) {
                accept('error', "A block arm of a switch expression must end with 'yield value;' (on every path).", {
                    node: arm.body,
                    code: Codes.MissingYield,
                });
            }
        }
        const en = enumOf(selector);
        const hasDefault = labels.some((l) => l.default);
        if (hasDefault || isErroneous(selector)) return;
        const missing = en ? en.constants.filter((c) => !covered.has(c.name)).map((c) => c.name) : undefined;
        if (missing && missing.length === 0) return;
        accept(
            'error',
            missing
                ? `A switch expression must be exhaustive: add a 'default' arm or arms for ${missing.join(', ')}.`
                : `A switch expression over ${printType(selector)} must be exhaustive: add a 'default' arm.`,
            { node: s, property: 'selector', code: Codes.SwitchNotExhaustive },
        );
    }

    /**
     * The labels of a switch: their types fit the selector's, they are distinct, at most one
     * `default`. `report`: type the labels here and report their problems (a statement; a switch
     * expression's labels are reported with its root expression). Returns the enum constants labelled.
     */
    private checkLabels(
        selectorNode: Expression,
        selector: SymType,
        labels: readonly SwitchLabel[],
        accept: ValidationAcceptor,
        report: boolean,
    ): Set<string> {
        const selectorOk = isErroneous(selector) || this.isSwitchable(selector);
        if (!selectorOk) {
            accept(
                'error',
                `A switch selector must be of type char, byte, short, int (or their boxes), String or an enum, but the expression is of type ${printType(selector)}.`,
                { node: selectorNode, code: Codes.ExprTypeMismatch },
            );
        }
        const selectorEnum = enumOf(selector);
        const seen = new Map<string, AstNode>();
        const constants = new Set<string>();
        let defaults = 0;
        for (const label of labels) {
            if (label.default) {
                defaults++;
                if (defaults > 1)
                    accept('error', 'A switch has at most one default label.', { node: label, code: Codes.DuplicateCaseLabel });
            }
            for (const v of label.values) {
                if (selectorEnum && isNameExpression(v) && !v.ref.ref) {
                    // A bare label of an enum switch names a constant of the selector's enum (scoping).
                    if (report) accept('error', notAConstantMessage(v, selectorEnum), { node: v, code: Codes.ExprUnresolvedName });
                    continue;
                }
                const t = report ? this.expressions.checkExpression(v, accept) : this.typer.typeOf(v, []);
                if (selectorOk && !isErroneous(selector) && !isErroneous(t) && !this.rel.isAssignable(selector, t)) {
                    accept(
                        'error',
                        `A case label of a switch over ${printType(selector)} must be of that type, but it is of type ${printType(t)}.`,
                        { node: v, code: Codes.ExprTypeMismatch },
                    );
                }
                // `RED` and `Color.RED` label the same constant of an enum switch.
                const constant = selectorEnum && t.kind === 'object' && t.decl === selectorEnum ? enumConstantName(v) : undefined;
                if (constant) constants.add(constant);
                const key = constant ?? v.$cstNode?.text.replace(/\s+/g, '') ?? '';
                if (key && seen.has(key)) {
                    accept('error', `Duplicate case label '${key}': every value may label one case only.`, {
                        node: v,
                        code: Codes.DuplicateCaseLabel,
                    });
                } else if (key) seen.set(key, v);
            }
        }
        return constants;
    }

    private isSwitchable(t: SymType): boolean {
        const u = this.rel.unbox(t);
        if (u.kind === 'primitive') return SWITCH_PRIMITIVES.has(u.name);
        if (t.kind === 'object') return t.decl.$type === 'CDEnum' || (t.decl.name === 'String' && printType(t) === 'String');
        return false;
    }
}

function enumOf(t: SymType): CDEnum | undefined {
    return t.kind === 'object' && isCDEnum(t.decl) ? t.decl : undefined;
}

/** The constant an enum label names, bare (`RED`) or qualified (`Color.RED`, `pkg.Color.RED`). */
function enumConstantName(v: Expression): string | undefined {
    if (isNameExpression(v)) return isCDEnumConstant(v.ref.ref) ? v.ref.ref.name : undefined;
    return isFieldAccessExpression(v) ? v.member : undefined;
}

/**
 * Whether a statement never completes normally because it yields on every path (JLS 14.22, for
 * yield; a `break`/`continue` counts too: it is reported as leaving the switch expression).
 */
function completesAbruptly(s: Statement | undefined): boolean {
    if (!s) return false;
    if (isYieldStatement(s) || s.$type === 'BreakStatement' || s.$type === 'ContinueStatement') return true;
    if (isBlock(s)) return completesAbruptly(s.statements[s.statements.length - 1]);
    if (isIfStatement(s)) return !!s.else && completesAbruptly(s.then) && completesAbruptly(s.else);
    return false;
}

/**
 * What a `break` (`switchToo`) or `continue` leaves: the innermost loop (or switch statement)
 * around it inside its component, 'switch-expression' when a switch expression lies in between
 * (a jump may not leave one), or undefined when there is none.
 */
function jumpTarget(node: AstNode, switchToo: boolean): AstNode | 'switch-expression' | undefined {
    for (let n = node.$container; n; n = n.$container) {
        switch (n.$type) {
            case 'WhileStatement':
            case 'DoWhileStatement':
            case 'ForStatement':
                return n;
            case 'SwitchStatement':
                if (switchToo) return n;
                break;
            case 'SwitchExpression':
                return 'switch-expression';
            case 'ComponentType':
                return undefined;
        }
    }
    return undefined;
}
