import { type AstNode, type ValidationAcceptor, type ValidationChecks } from 'langium';
import type { AdlAstType, Expression, SwitchStatement } from '../../generated/ast.js';
import { isCDEnumConstant, isCDEnum, isFieldAccessExpression, isNameExpression } from '../../generated/ast.js';
import type { AdlServices } from '../../adl-module.js';
import type { ExpressionChecks } from './expression-checks.js';
import type { TypeRelations } from '../../types/type-relations.js';
import { BOOLEAN, isErroneous, printType, type SymType } from '../../types/sym-type.js';
import { Codes } from '../codes.js';

/** The selector types Java's switch accepts (JLS 14.11): char, byte, short, int, their boxes, String and enums. */
const SWITCH_PRIMITIVES = new Set(['char', 'byte', 'short', 'int']);

/**
 * Typing and context conditions of Java's control statements beyond if/while/for: `do`-`while`,
 * `switch` (selector and label types, duplicate labels, one default, no mixing of `:` and `->`
 * groups) and `break`/`continue` (only inside a loop, `break` also inside a switch).
 */
export class StatementChecks {
    private readonly rel: TypeRelations;

    constructor(services: AdlServices, private readonly expressions: ExpressionChecks) {
        this.rel = services.maa.TypeRelations;
    }

    readonly checks: ValidationChecks<AdlAstType> = {
        DoWhileStatement: (s, accept) => {
            this.expressions.expectType(s.condition, BOOLEAN, accept, Codes.ExprTypeMismatch, 'A condition');
        },
        SwitchStatement: (s, accept) => this.checkSwitch(s, accept),
        BreakStatement: (s, accept) => {
            if (!enclosingTarget(s, true)) {
                accept('error', "'break' is only allowed inside a loop (while, do, for) or a switch.", { node: s, code: Codes.BreakOutsideLoop });
            }
        },
        ContinueStatement: (s, accept) => {
            if (!enclosingTarget(s, false)) {
                accept('error', "'continue' is only allowed inside a loop (while, do, for).", { node: s, code: Codes.ContinueOutsideLoop });
            }
        }
    };

    private checkSwitch(s: SwitchStatement, accept: ValidationAcceptor): void {
        const selector = this.expressions.checkExpression(s.selector, accept);
        const selectorOk = isErroneous(selector) || this.isSwitchable(selector);
        if (!selectorOk) {
            accept('error', `A switch selector must be of type char, byte, short, int (or their boxes), String or an enum, but the expression is of type ${printType(selector)}.`, { node: s.selector, code: Codes.ExprTypeMismatch });
        }
        const selectorEnum = selector.kind === 'object' && isCDEnum(selector.decl) ? selector.decl : undefined;
        const seen = new Map<string, AstNode>();
        let defaults = 0;
        let arrows = 0;
        let colons = 0;
        for (const g of s.groups) {
            for (const label of g.labels) {
                if (label.arrow) arrows++;
                else colons++;
                if (label.default) {
                    defaults++;
                    if (defaults > 1) accept('error', 'A switch has at most one default label.', { node: label, code: Codes.DuplicateCaseLabel });
                }
                for (const v of label.values) {
                    if (selectorEnum && isNameExpression(v) && !v.ref.ref) {
                        // A bare label of an enum switch names a constant of the selector's enum (scoping).
                        accept('error', `'${v.ref.$refText}' is not a constant of enum ${selectorEnum.name}; the labels of a switch over ${printType(selector)} are its constants: ${selectorEnum.constants.map((c) => c.name).join(', ') || '(none)'}.`, { node: v, code: Codes.ExprUnresolvedName });
                        continue;
                    }
                    const t = this.expressions.checkExpression(v, accept);
                    if (selectorOk && !isErroneous(selector) && !isErroneous(t) && !this.rel.isAssignable(selector, t)) {
                        accept('error', `A case label of a switch over ${printType(selector)} must be of that type, but it is of type ${printType(t)}.`, { node: v, code: Codes.ExprTypeMismatch });
                    }
                    // `RED` and `Color.RED` label the same constant of an enum switch.
                    const key = (selectorEnum && t.kind === 'object' && t.decl === selectorEnum ? enumConstantName(v) : undefined) ?? v.$cstNode?.text.replace(/\s+/g, '') ?? '';
                    if (key && seen.has(key)) {
                        accept('error', `Duplicate case label '${key}': every value may label one case only.`, { node: v, code: Codes.DuplicateCaseLabel });
                    } else if (key) seen.set(key, v);
                }
            }
            if (g.labels.some((l) => l.arrow) && (g.labels.length > 1 || g.statements.length !== 1)) {
                accept('error', "A 'case ... ->' rule has one label and one statement (a block, an expression statement or a throw); list several values in one label: 'case 1, 2 -> ...'.", { node: g, code: Codes.MixedSwitchLabels });
            }
        }
        if (arrows > 0 && colons > 0) {
            accept('error', "A switch uses either 'case ...:' groups or 'case ... ->' rules, not both.", { node: s, property: 'selector', code: Codes.MixedSwitchLabels });
        }
    }

    private isSwitchable(t: SymType): boolean {
        const u = this.rel.unbox(t);
        if (u.kind === 'primitive') return SWITCH_PRIMITIVES.has(u.name);
        if (t.kind === 'object') return t.decl.$type === 'CDEnum' || (t.decl.name === 'String' && printType(t) === 'String');
        return false;
    }
}

/** The constant an enum label names, bare (`RED`) or qualified (`Color.RED`, `pkg.Color.RED`). */
function enumConstantName(v: Expression): string | undefined {
    if (isNameExpression(v)) return isCDEnumConstant(v.ref.ref) ? v.ref.ref.name : undefined;
    return isFieldAccessExpression(v) ? v.member : undefined;
}

/**
 * The statement a `break` (`switchToo`) or `continue` leaves: the innermost loop (or switch)
 * around it inside its component.
 */
function enclosingTarget(node: AstNode, switchToo: boolean): AstNode | undefined {
    for (let n = node.$container; n; n = n.$container) {
        switch (n.$type) {
            case 'WhileStatement':
            case 'DoWhileStatement':
            case 'ForStatement':
                return n;
            case 'SwitchStatement':
                if (switchToo) return n;
                break;
            case 'ComponentType':
                return undefined;
        }
    }
    return undefined;
}
