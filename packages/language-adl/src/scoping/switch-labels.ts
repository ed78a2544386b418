import { AstUtils, type AstNode } from 'langium';
import type { CDEnum, Expression, NameExpression, SwitchExpression, SwitchStatement, YieldStatement } from '../generated/ast.js';
import { isSwitchArm, isSwitchExpression, isSwitchGroup, isSwitchLabel, isSwitchStatement, isYieldStatement } from '../generated/ast.js';

/** A switch statement or a switch expression (both have a selector and labels). */
export type AnySwitch = (SwitchStatement | SwitchExpression) & { selector: Expression };

/**
 * The switch whose case label `expr` is, directly (`case RED:`, `case RED, GREEN ->`), or
 * undefined for any other expression (also a part of a label such as `Color` in `case Color.RED:`).
 */
export function switchOfLabelValue(expr: AstNode): AnySwitch | undefined {
    const label = expr.$container;
    // A label holds expressions in `values` only (completion's synthetic node has no $containerProperty of it).
    if (!isSwitchLabel(label)) return undefined;
    const owner = label.$container;
    const sw = isSwitchGroup(owner) || isSwitchArm(owner) ? owner.$container : undefined;
    return (isSwitchStatement(sw) || isSwitchExpression(sw)) && sw.selector ? (sw as AnySwitch) : undefined;
}

/** The message for a bare label that names no constant of the selector's enum. */
export function notAConstantMessage(label: NameExpression, en: CDEnum): string {
    return `'${label.ref.$refText}' is not a constant of enum ${en.name}; the labels of a switch over ${en.name} are its constants: ${en.constants.map((c) => c.name).join(', ') || '(none)'}.`;
}

/** The `yield` statements that give a block arm of a switch expression its value (not those of nested switch expressions). */
export function yieldsOf(body: AstNode): YieldStatement[] {
    const found: YieldStatement[] = [];
    const visit = (n: AstNode): void => {
        for (const child of AstUtils.streamContents(n)) {
            if (isYieldStatement(child)) found.push(child);
            if (!isSwitchExpression(child)) visit(child);
        }
    };
    visit(body);
    return found;
}

/** The switch expression a `yield` gives its value to: the innermost one around it, if its block arm holds the yield. */
export function switchOfYield(y: YieldStatement): SwitchExpression | undefined {
    for (let n: AstNode | undefined = y.$container; n; n = n.$container) {
        if (isSwitchArm(n)) return isSwitchExpression(n.$container) ? n.$container : undefined;
        if (n.$type === 'ComponentType') return undefined;
    }
    return undefined;
}
