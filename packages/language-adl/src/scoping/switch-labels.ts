import type { AstNode } from 'langium';
import type { Expression, SwitchStatement } from '../generated/ast.js';
import { isSwitchGroup, isSwitchLabel, isSwitchStatement } from '../generated/ast.js';

/**
 * The switch whose case label `expr` is, directly (`case RED:`, `case RED, GREEN ->`), or
 * undefined for any other expression (also a part of a label such as `Color` in `case Color.RED:`).
 */
export function switchOfLabelValue(expr: AstNode): (SwitchStatement & { selector: Expression }) | undefined {
    const label = expr.$container;
    // A label holds expressions in `values` only (completion's synthetic node has no $containerProperty of it).
    if (!isSwitchLabel(label)) return undefined;
    const group = label.$container;
    const sw = isSwitchGroup(group) ? group.$container : undefined;
    return isSwitchStatement(sw) && sw.selector ? sw as SwitchStatement & { selector: Expression } : undefined;
}
