import { Formatting } from 'langium/lsp';
import type { AdlFormatter } from '@maa/language-adl';
import type { Program, RobotArmModel } from '../generated/ast.js';

/**
 * RobotArm's formatting rules, in the family's style (AdlFormatter): two-space indentation, one
 * element (input, location, program) per line, single spaces between words, no space before
 * `;`. The steps of a program go one per line, except where the modeler wrote them in rows: a
 * program written on one line (`program Wave { open; close; }`) stays on one line, and steps
 * written on one line (Listing 1: `move top; open; move toaster; ...`) stay in that row, each
 * row on a line of its own, indented (as the host keeps statement blocks written on one line).
 * The inside of a measure (`120deg`, `100 mm`) is kept as written.
 */
export function registerRobotArmFormatting(formatter: AdlFormatter): void {
    const rules = formatter.rules;
    rules.set('RobotArmModel', (n, f) => {
        const m = n as RobotArmModel;
        const on = f.on(m);
        on.keywords('package').append(Formatting.oneSpace());
        f.semicolons(m);
        if (m.package && m.robot) f.blankLineBefore(m.robot);
    });
    rules.set('RobotArm', (n, f) => {
        f.on(n).keyword('robotarm').append(Formatting.oneSpace());
        f.elementBlock(n);
    });
    rules.set('RobotArmDefinition', (n, f) => {
        const on = f.on(n);
        on.keyword('robotarm').append(Formatting.oneSpace());
        on.keyword('{').prepend(Formatting.oneSpace());
        f.elementBlock(n);
    });
    rules.set('RobotArmInput', (n, f) => {
        f.keywordSpacing(n, { after: ['input'] });
        f.property(n, 'name').prepend(Formatting.oneSpace());
        f.semicolons(n);
    });
    rules.set('Location', (n, f) => {
        f.keywordSpacing(n, { after: ['location'] });
        f.property(n, 'angle').prepend(Formatting.oneSpace());
        f.property(n, 'height').prepend(Formatting.oneSpace());
        f.semicolons(n);
    });
    rules.set('Program', (n, f) => {
        const on = f.on(n);
        on.keyword('program').append(Formatting.oneSpace());
        on.keyword('{').prepend(Formatting.oneSpace());
        programBlock(n as Program, f);
    });
    rules.set('Move', (n, f) => {
        f.keywordSpacing(n, { after: ['move'] });
        f.property(n, 'arguments').prepend(Formatting.oneSpace());
        f.semicolons(n);
    });
    rules.set('GripperStep', (n, f) => f.semicolons(n));
}

/** The steps of a program: one line stays one line; else rows as written, one row per line. */
function programBlock(p: Program, f: AdlFormatter): void {
    const on = f.on(p);
    const open = on.keyword('{');
    const close = on.keyword('}');
    const o = open.nodes[0];
    const c = close.nodes[0];
    if (!o || !c) return;
    const hasComment = on.interior(open, close).nodes.some((x) => x.hidden);
    if (o.range.start.line === c.range.start.line && !hasComment) {
        // Written on one line: stays on one line (`{ open; close; }`, `{ }`).
        f.statementBlock(p, p.steps);
        return;
    }
    // Every step on a line of its own, except a step written on the line of the step before it
    // (a row such as `move top; open; move toaster;`): one space between the steps of a row.
    f.elementBlock(p);
    p.steps.forEach((s, i) => {
        const previous = p.steps[i - 1]?.$cstNode;
        const cst = s.$cstNode;
        if (previous && cst && previous.range.end.line === cst.range.start.line) on.node(s).prepend(Formatting.oneSpace());
    });
}
