import { GrammarUtils, type AstNode } from 'langium';
import { sourceText } from '@maa/language-adl';
import type { Location, Move, Program, RobotArmInput } from '../generated/ast.js';
import {
    commandConstantName,
    enclosingRobotArm,
    enumConstants,
    formatSI,
    INPUT_UNITS,
    inputsOf,
    isEmbedded,
    locationsOf,
    moveTarget,
    parseMeasure,
    programForCommand,
    programsOf,
    protocolPorts,
    robotArmComponent,
    RobotArmProtocol,
    type Dimension,
    type JointSource,
    type RobotArmBody,
} from '../robotarm-model.js';

/** Hover texts (Markdown) of RobotArm's declarations. */

function code(language: string, text: string): string {
    return `\`\`\`${language}\n${text}\n\`\`\``;
}

/** `the robot arm ToastService` or `the robotarm block of component ArmController`. */
function owner(body: RobotArmBody | undefined): string {
    if (!body) return 'a robot arm';
    if (isEmbedded(body)) return `the robotarm block of component \`${robotArmComponent(body)?.name ?? '?'}\``;
    return `robot arm \`${body.name ?? '?'}\``;
}

function round(v: number, digits = 4): string {
    const f = 10 ** digits;
    return String(Math.round(v * f) / f);
}

/** A measure in source and SI units: `120deg` (2.0944 rad). */
export function measureInUnits(text: string | undefined, written: string): string {
    const m = parseMeasure(text);
    if (!m || m.si === undefined || !m.dimension) return `\`${written}\``;
    return `\`${written}\` = ${round(m.si)} ${m.dimension === 'angle' ? 'rad' : 'm'}`;
}

function writtenProperty(node: AstNode, property: string): string {
    const cst = GrammarUtils.findNodeForProperty(node.$cstNode, property);
    return cst ? sourceText(cst) : String((node as unknown as Record<string, unknown>)[property] ?? '');
}

export function describeRobotArm(body: RobotArmBody, language: string): string {
    const head = isEmbedded(body) ? 'robotarm' : `robotarm ${body.name}`;
    const lines = [code(language, head)];
    lines.push(
        isEmbedded(body)
            ? `RobotArm programs of component \`${robotArmComponent(body)?.name ?? '?'}\`: port \`${RobotArmProtocol.commandPort}\` selects the program, port \`${RobotArmProtocol.statusPort}\` reports ${RobotArmProtocol.statusValues.join(', ')}.`
            : `Robot arm \`${body.name}\` (a standalone RobotArm model).`,
    );
    const list = (title: string, items: string[]): void => {
        if (items.length) lines.push(`**${title}**: ${items.join(', ')}`);
    };
    list(
        'Inputs',
        inputsOf(body)
            .filter((i) => i.name)
            .map((i) => `\`${i.name}\``),
    );
    list(
        'Locations',
        locationsOf(body)
            .filter((l) => l.name)
            .map((l) => `\`${l.name}\``),
    );
    list(
        'Programs',
        programsOf(body)
            .filter((p) => p.name)
            .map((p) => `\`${p.name}\``),
    );
    return lines.join('\n\n');
}

export function describeLocation(l: Location, language: string): string {
    const angle = writtenProperty(l, 'angle');
    const height = writtenProperty(l, 'height');
    return [
        code(language, `location ${l.name} ${angle} ${height}`),
        `Location of ${owner(enclosingRobotArm(l))}, a target in joint space:`,
        `- joint angle ${measureInUnits(l.angle, angle)}\n- gripper height ${measureInUnits(l.height, height)}`,
    ].join('\n\n');
}

export function describeInput(i: RobotArmInput, language: string): string {
    const body = enclosingRobotArm(i);
    const lines = [code(language, `input ${sourceText(i.type) || '?'} ${i.name}`)];
    if (body && isEmbedded(body)) {
        lines.push(`Not allowed in an embedded robotarm block: \`move ${i.name}\` names an incoming port of the component there.`);
    } else {
        lines.push(
            `Input of ${owner(body)}: its latest value is read when a move starts, in ${unitName('angle')} as a joint angle, in ${unitName('height')} as a gripper height.`,
        );
    }
    return lines.join('\n\n');
}

function unitName(dimension: Dimension): string {
    return INPUT_UNITS[dimension] === 'deg' ? 'degrees' : INPUT_UNITS[dimension] === 'cm' ? 'centimeters' : INPUT_UNITS[dimension];
}

export function describeProgram(p: Program, language: string): string {
    const body = enclosingRobotArm(p);
    const lines = [code(language, `program ${p.name}`)];
    let role = `Program of ${owner(body)}`;
    if (body && isEmbedded(body)) {
        const cmd = protocolPorts(body).cmd;
        const constant = (enumConstants(cmd?.type) ?? []).find((c) => c !== RobotArmProtocol.noCommand && programForCommand(body, c) === p);
        role += constant
            ? `, started by the command \`${constant}\` on port \`${RobotArmProtocol.commandPort}\``
            : ` (a command \`${commandConstantName(p.name)}\` on port \`${RobotArmProtocol.commandPort}\` would start it)`;
    }
    lines.push(`${role}.`);
    if (p.steps.length === 0) lines.push('No steps: the program completes as soon as it starts.');
    else lines.push(`**Steps**\n\n${p.steps.map((s, i) => `${i + 1}. \`${sourceText(s)}\`${stepMeaning(s)}`).join('\n')}`);
    return lines.join('\n\n');
}

/** What a step does, after its source text (` — ...`). */
function stepMeaning(step: Program['steps'][number]): string {
    if (step.$type === 'GripperStep') return step.action === 'open' ? ' — open the gripper' : ' — close the gripper';
    const t = moveTarget(step as Move);
    if (!t) return '';
    const joint = (s: JointSource, d: Dimension): string => {
        switch (s.kind) {
            case 'fixed':
                return formatSI(d, s.si);
            case 'keep':
                return 'unchanged';
            case 'input':
                return `input \`${s.name}\` (${s.unit})`;
            case 'port':
                return `port \`${s.name}\` (${s.unit})`;
        }
    };
    const where = `angle ${joint(t.angle, 'angle')}, height ${joint(t.height, 'height')}`;
    if (t.target?.kind === 'constant') return ` — lift to \`${t.target.name}\` (${where})`;
    if (t.target?.kind === 'location') return ` — to location \`${t.target.name}\` (${where})`;
    return ` — ${where}`;
}
