import { GrammarUtils, type AstNode, type ValidationAcceptor, type ValidationChecks } from 'langium';
import { isErroneous, printType, type AdlServices, type ModelRoots, type TypeRelations } from '@maa/language-adl';
import type { Location, Move, Program, RobotArm, RobotArmAstType, RobotArmInput, RobotArmModel } from './generated/ast.js';
import {
    commandConstantName,
    enumConstants,
    feederType,
    formatSI,
    incomingPortsOf,
    inputsOf,
    isEmbedded,
    locationsOf,
    moveForm,
    parseMeasure,
    programForCommand,
    programsOf,
    protocolPorts,
    robotArmComponent,
    RobotArmProtocol,
    ROBOT_ARM_PROFILE,
    withinLimits,
    type Dimension,
    type JointOperand,
    type RobotArmBody,
} from './robotarm-model.js';
import { RobotArmCodes } from './codes.js';

/**
 * The context conditions of RobotArm, in `.ra` files and in embedded `robotarm { }` blocks
 * (docs/robotarm.md). Registered by both registration objects (robotarm-language.ts), each into
 * the services of its language.
 */
export class RobotArmChecks {
    private readonly rel: TypeRelations;
    private readonly roots: ModelRoots;

    constructor(services: AdlServices) {
        this.rel = services.maa.TypeRelations;
        this.roots = services.shared.maa.ModelRoots;
    }

    readonly checks: ValidationChecks<RobotArmAstType> = {
        RobotArmModel: (m, accept) => this.checkFile(m, accept),
        RobotArmDefinition: (d, accept) => {
            if (d.name && /^[a-z]/.test(d.name)) {
                accept('warning', `The robot arm name '${d.name}' should start with an upper-case letter.`, {
                    node: d,
                    property: 'name',
                    code: RobotArmCodes.NamingConvention,
                });
            }
            this.checkBody(d, accept);
        },
        RobotArm: (b, accept) => {
            this.checkBody(b, accept);
            this.checkProtocol(b, accept);
        },
        RobotArmInput: (i, accept) => {
            const body = i.$container;
            if (body && isEmbedded(body)) {
                accept(
                    'error',
                    `Input '${i.name}' cannot be declared in an embedded robotarm block: there the names after 'move' denote incoming ports of the component; declare 'port in ${i.type?.$cstNode?.text ?? 'int'} ${i.name};' instead.`,
                    { node: i, code: RobotArmCodes.InputInEmbedded },
                );
            }
        },
        Location: (l, accept) => {
            this.checkMeasure(l, 'angle', l.angle, accept);
            this.checkMeasure(l, 'height', l.height, accept);
        },
        Program: (p, accept) => {
            if (p.name && /^[a-z]/.test(p.name)) {
                accept(
                    'warning',
                    `The program name '${p.name}' should start with an upper-case letter (programs are selected by command constants such as '${commandConstantName(p.name)}').`,
                    { node: p, property: 'name', code: RobotArmCodes.NamingConvention },
                );
            }
            if (p.name && p.steps.length === 0) {
                accept('warning', `Program '${p.name}' has no steps: it completes as soon as it starts.`, {
                    node: p,
                    property: 'name',
                    code: RobotArmCodes.EmptyProgram,
                });
            }
        },
        Move: (m, accept) => this.checkMove(m, accept),
    };

    // ---- files ----

    private checkFile(m: RobotArmModel, accept: ValidationAcceptor): void {
        const doc = m.$document;
        const r = m.robot;
        if (!doc || !r?.name || this.roots.isBuiltin(doc.uri)) return;
        const file = doc.uri.path.substring(doc.uri.path.lastIndexOf('/') + 1).replace(/\.ra$/, '');
        if (r.name !== file) {
            accept('error', `Robot arm '${r.name}' must be declared in a file named '${r.name}.ra', not '${file}.ra'.`, {
                node: r,
                property: 'name',
                code: RobotArmCodes.FileNameMismatch,
            });
        }
        const expected = this.roots.expectedPackage(doc.uri);
        if ((m.package ?? '') !== expected) {
            const msg = `The package of '${file}.ra' must be '${expected || '(the default package)'}' to match its folder, not '${m.package ?? '(the default package)'}'.`;
            if (m.package) accept('error', msg, { node: m, property: 'package', code: RobotArmCodes.PackageMismatch });
            else accept('error', msg, { node: r, property: 'name', code: RobotArmCodes.PackageMismatch });
        }
    }

    // ---- names ----

    private checkBody(body: RobotArmBody, accept: ValidationAcceptor): void {
        // Inputs and locations are both named after `move`: one namespace. Programs have their own.
        const targets = new Map<string, RobotArmInput | Location>();
        const embedded = isEmbedded(body);
        for (const e of [...(embedded ? [] : inputsOf(body)), ...locationsOf(body)]) {
            if (!e.name) continue;
            const first = targets.get(e.name);
            if (first) {
                const clash =
                    first.$type === e.$type ? 'is already declared' : `has the name of the ${kindOf(first).toLowerCase()} declared`;
                accept(
                    'error',
                    `${kindOf(e)} '${e.name}' ${clash} on line ${line(first)}: inputs and locations share one namespace, the names after 'move'.`,
                    { node: e, property: 'name', code: RobotArmCodes.DuplicateName },
                );
            } else targets.set(e.name, e);
        }
        if (embedded) {
            const ports = new Map(incomingPortsOf(body).map((p) => [p.name, p]));
            for (const l of locationsOf(body)) {
                if (l.name && ports.has(l.name)) {
                    accept(
                        'error',
                        `Location '${l.name}' has the name of an incoming port of the component: 'move ${l.name}' would be ambiguous; rename the location.`,
                        { node: l, property: 'name', code: RobotArmCodes.DuplicateName },
                    );
                }
            }
        }
        const programs = new Map<string, Program>();
        for (const p of programsOf(body)) {
            if (!p.name) continue;
            const first = programs.get(p.name);
            if (first) {
                accept('error', `Program '${p.name}' is already declared on line ${line(first)}.`, {
                    node: p,
                    property: 'name',
                    code: RobotArmCodes.DuplicateName,
                });
            } else programs.set(p.name, p);
        }
        for (const e of [...inputsOf(body), ...locationsOf(body)]) {
            if (e.name && e.name in ROBOT_ARM_PROFILE.constants) {
                accept(
                    'error',
                    `'${e.name}' is a RobotArm constant ('move ${e.name};' always moves the lift to its ${e.name} position): choose another name for this ${kindOf(e).toLowerCase()}.`,
                    { node: e, property: 'name', code: RobotArmCodes.ReservedName },
                );
            } else if (e.name && /^[A-Z]/.test(e.name)) {
                accept('warning', `The ${kindOf(e).toLowerCase()} name '${e.name}' should start with a lower-case letter.`, {
                    node: e,
                    property: 'name',
                    code: RobotArmCodes.NamingConvention,
                });
            }
        }
    }

    // ---- values ----

    /** A measure in a location or a move: a known unit of the expected dimension, within the joint limits. */
    private checkMeasure(
        node: AstNode,
        property: string,
        text: string | undefined,
        accept: ValidationAcceptor,
        expected: Dimension = property as Dimension,
    ): void {
        if (!this.checkUnit(node, property, text, accept, expected)) return;
        const m = parseMeasure(text)!;
        const shown = written(node, property, text);
        const what = expected === 'angle' ? 'joint angle' : 'gripper height';
        if (m.dimension !== expected) {
            accept(
                'error',
                `'${shown}' is ${m.dimension === 'angle' ? 'an angle' : 'a height'}, but a ${what} is expected here (${UNIT_NAMES[expected]}).`,
                { node, property, code: RobotArmCodes.UnitMismatch },
            );
            return;
        }
        if (m.si !== undefined && !withinLimits(expected, m.si)) {
            const { min, max } = ROBOT_ARM_PROFILE[expected];
            accept('error', `The ${what} '${shown}' is outside the arm's range ${formatSI(expected, min)} .. ${formatSI(expected, max)}.`, {
                node,
                property,
                code: RobotArmCodes.JointLimit,
            });
        }
    }

    /** Reports a missing or unknown unit; true when the unit is known. */
    private checkUnit(
        node: AstNode,
        property: string,
        text: string | undefined,
        accept: ValidationAcceptor,
        expected?: Dimension,
    ): boolean {
        const m = parseMeasure(text);
        if (!m) return false;
        const shown = written(node, property, text);
        const units = expected ? UNIT_NAMES[expected] : "'deg' or 'rad' for angles, 'mm', 'cm' or 'm' for heights";
        if (!m.unit) {
            const example = `${m.value}${expected === 'height' ? 'cm' : 'deg'}`;
            const what = expected === 'angle' ? 'joint angle' : expected === 'height' ? 'gripper height' : 'value';
            accept('error', `The ${what} '${shown}' has no unit: write e.g. '${example}' (${units}).`, {
                node,
                property,
                code: RobotArmCodes.InvalidUnit,
            });
            return false;
        }
        if (!m.dimension) {
            accept('error', `Unknown unit '${m.unit}' in '${shown}': a value is a number with a unit (${units}), e.g. '90deg' or '20cm'.`, {
                node,
                property,
                code: RobotArmCodes.InvalidUnit,
            });
            return false;
        }
        return true;
    }

    // ---- moves ----

    private checkMove(move: Move, accept: ValidationAcceptor): void {
        // A value with a bad unit (`move 90 angle;` reads `90angle`) says more than the arity.
        let units = true;
        for (const a of move.arguments) {
            if (a.value !== undefined && !this.checkUnit(a, 'value', a.value, accept)) units = false;
        }
        if (!units) return;
        const form = moveForm(move);
        if (form.kind === 'ill-formed') {
            if (form.reason) accept('error', `${form.reason}.`, { node: form.node, code: RobotArmCodes.MoveArity });
            return;
        }
        if (form.kind !== 'joints') return;
        this.checkJoint(form.angle, 'angle', accept);
        this.checkJoint(form.height, 'height', accept);
    }

    private checkJoint(o: JointOperand, dimension: Dimension, accept: ValidationAcceptor): void {
        if (o.kind === 'value') {
            this.checkMeasure(o.node, 'value', o.text, accept, dimension);
            return;
        }
        if (o.kind !== 'input' && o.kind !== 'port') return;
        const body = o.node.$container.$container.$container;
        const node = o.kind === 'input' ? o.input : o.port;
        const type = feederType(node, body);
        if (!type || isErroneous(type) || this.rel.isNumeric(type)) return;
        const what = o.kind === 'input' ? 'input' : 'incoming port';
        accept(
            'error',
            `The ${what} '${node.name}' is of type ${printType(type)}, but 'move' needs a number for the ${dimension === 'angle' ? 'joint angle' : 'gripper height'} (read in ${dimension === 'angle' ? 'degrees' : 'centimeters'}).`,
            { node: o.node, code: RobotArmCodes.MoveNotNumeric },
        );
    }

    // ---- the port protocol of an embedded robot arm ----

    private checkProtocol(body: RobotArm, accept: ValidationAcceptor): void {
        const component = robotArmComponent(body);
        if (!component) return;
        const { cmd, status } = protocolPorts(body);
        const at = { node: body, keyword: 'robotarm' } as const;
        const { commandPort, statusPort, statusValues, noCommand } = RobotArmProtocol;

        if (cmd?.direction !== 'in') {
            const why = cmd ? `its port '${commandPort}' is outgoing` : `it has no port '${commandPort}'`;
            accept(
                'error',
                `Component '${component.name}' runs RobotArm programs, but ${why}: declare 'port in <Enum> ${commandPort};' whose enum constants name the programs (e.g. '${
                    programsOf(body)
                        .filter((p) => p.name)
                        .map((p) => commandConstantName(p.name))[0] ?? 'PICKUP'
                }').`,
                { ...at, code: RobotArmCodes.MissingCmdPort },
            );
        } else {
            const constants = enumConstants(cmd.type);
            if (!constants) {
                if (!isErroneous(cmd.type)) {
                    accept(
                        'error',
                        `Port '${commandPort}' of component '${component.name}' is of type ${printType(cmd.type)}, but the program to run is selected by an enum from a class diagram whose constants name the programs.`,
                        { node: cmd.port, property: 'type', code: RobotArmCodes.CmdPortType },
                    );
                }
            } else {
                const typeName = printType(cmd.type);
                for (const c of constants) {
                    if (c === noCommand || programForCommand(body, c)) continue;
                    accept(
                        'error',
                        `Command '${typeName}.${c}' (port '${commandPort}') selects no program of this robot arm: add a program '${c}' or '${pascal(c)}', or remove the constant ('${noCommand}' is the only constant that names no program).`,
                        { ...at, code: RobotArmCodes.CommandWithoutProgram },
                    );
                }
                for (const p of programsOf(body)) {
                    if (!p.name) continue;
                    if (!constants.some((c) => c !== noCommand && programForCommand(body, c) === p)) {
                        accept(
                            'warning',
                            `Program '${p.name}' can never run: no constant of ${typeName} (port '${commandPort}') selects it; add '${commandConstantName(p.name)}' to ${typeName}.`,
                            { node: p, property: 'name', code: RobotArmCodes.ProgramWithoutCommand },
                        );
                    }
                }
            }
        }

        if (status?.direction !== 'out') {
            const why = status ? `its port '${statusPort}' is incoming` : `it has no port '${statusPort}'`;
            accept(
                'error',
                `Component '${component.name}' runs RobotArm programs, but ${why}: declare 'port out <Enum> ${statusPort};' with an enum of ${statusValues.join(', ')} that reports when a program runs and completes.`,
                { ...at, code: RobotArmCodes.MissingStatusPort },
            );
        } else {
            const constants = enumConstants(status.type);
            if (!isErroneous(status.type) && !hasAll(constants, statusValues)) {
                const missing = constants ? statusValues.filter((v) => !constants.includes(v)) : [];
                const why = constants
                    ? `its enum ${printType(status.type)} lacks ${missing.join(', ')}`
                    : `it is of type ${printType(status.type)}`;
                accept(
                    'error',
                    `Port '${statusPort}' of component '${component.name}' reports the arm's state with an enum of ${statusValues.join(', ')}, but ${why}.`,
                    { node: status.port, property: 'type', code: RobotArmCodes.StatusPortType },
                );
            }
        }
    }
}

const UNIT_NAMES: Readonly<Record<Dimension, string>> = { angle: "'deg' or 'rad'", height: "'mm', 'cm' or 'm'" };

/** The measure as written in the model (`120deg`, `90 angle`), for messages. */
function written(node: AstNode, property: string, text: string | undefined): string {
    const cst = node.$cstNode ? GrammarUtils.findNodeForProperty(node.$cstNode, property) : undefined;
    return cst?.text ?? text ?? '';
}

function hasAll(constants: string[] | undefined, values: readonly string[]): boolean {
    return constants !== undefined && values.every((v) => constants.includes(v));
}

function kindOf(e: RobotArmInput | Location): string {
    return e.$type === 'RobotArmInput' ? 'Input' : 'Location';
}

function line(n: AstNode): number {
    return (n.$cstNode?.range.start.line ?? 0) + 1;
}

/** `PICKUP_AND_DEPLOY` -> `PickupAndDeploy`. */
function pascal(constant: string): string {
    return constant
        .toLowerCase()
        .split('_')
        .filter((s) => s)
        .map((s) => s.charAt(0).toUpperCase() + s.slice(1))
        .join('');
}
