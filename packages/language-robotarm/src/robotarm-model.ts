import { AstUtils, type AstNode } from 'langium';
import { allPorts, enclosingComponent, typeOfMCType, type PortInfo, type SymType } from '@maa/language-adl';
import type {
    ComponentType,
    GripperStep,
    Location,
    Move,
    MoveArgument,
    Port,
    Program,
    RobotArm,
    RobotArmDefinition,
    RobotArmInput,
} from './generated/ast.js';

/**
 * The RobotArm model API: derived facts about robot arm programs that the checks, the scopes and
 * the behavior generators share. Pure functions over the AST; they read `$type` only, so they
 * work on the AST of any language family build that composes this grammar.
 *
 * Joint space: the reference arm (docs/robotarm.md) has a rotating base (the joint angle) and a
 * lift (the gripper height), plus a gripper that opens and closes. All targets are resolved to
 * SI units: radians and meters.
 */

/** A robot arm body: the embedded `robotarm { }` block or the standalone `robotarm Name { }`. */
export type RobotArmBody = RobotArm | RobotArmDefinition;

/** The measurements of the reference arm, in SI units (docs/robotarm.md, "The reference arm"). */
export const ROBOT_ARM_PROFILE = {
    /** The base rotation: -180deg .. 180deg. */
    angle: { min: -Math.PI, max: Math.PI },
    /** The lift: from `bottom` (2 cm above the table) to `top` (30 cm). */
    height: { min: 0.02, max: 0.3 },
    /** The constants: heights the lift moves to while the base keeps its angle. */
    constants: { top: 0.3, bottom: 0.02 } as const,
} as const;

export type RobotArmConstant = keyof typeof ROBOT_ARM_PROFILE.constants;
export type Dimension = 'angle' | 'height';

/** The units of the language by dimension, with their factor to SI (rad, m). */
export const UNITS: Readonly<Record<string, { readonly dimension: Dimension; readonly toSI: number }>> = {
    deg: { dimension: 'angle', toSI: Math.PI / 180 },
    rad: { dimension: 'angle', toSI: 1 },
    mm: { dimension: 'height', toSI: 0.001 },
    cm: { dimension: 'height', toSI: 0.01 },
    m: { dimension: 'height', toSI: 1 },
};

/**
 * The units in which values read from inputs and ports are interpreted: degrees and centimeters
 * (the units of the paper's Listing 1, whose inputs are `int`s).
 */
export const INPUT_UNITS: Readonly<Record<Dimension, string>> = { angle: 'deg', height: 'cm' };

/** A measure as written (`120deg`, `-1.5rad`, `20cm`), interpreted. */
export interface ParsedMeasure {
    /** The number as written, with its sign. */
    readonly value: number;
    /** The unit as written; empty when there is none. */
    readonly unit: string;
    /** The dimension of a known unit. */
    readonly dimension?: Dimension;
    /** The value in SI units (rad, m) for a known unit. */
    readonly si?: number;
}

/** Interprets the text of a `Measure` (see the grammar: the text is reassembled from tokens). */
export function parseMeasure(text: string | undefined): ParsedMeasure | undefined {
    if (!text) return undefined;
    const m = /^(-?)((?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)(.*)$/.exec(text.trim());
    if (!m) return undefined;
    const value = (m[1] === '-' ? -1 : 1) * Number(m[2]);
    const unit = m[3]!.trim();
    const known = UNITS[unit];
    return known ? { value, unit, dimension: known.dimension, si: value * known.toSI } : { value, unit };
}

/** Whether an SI value lies within the reference arm's limits for its dimension (with rounding slack). */
export function withinLimits(dimension: Dimension, si: number): boolean {
    const { min, max } = ROBOT_ARM_PROFILE[dimension];
    const eps = 1e-9;
    return si >= min - eps && si <= max + eps;
}

/** A human-readable form of an SI value in the units people write (`180deg`, `30cm`). */
export function formatSI(dimension: Dimension, si: number): string {
    const v = dimension === 'angle' ? (si * 180) / Math.PI : si * 100;
    return `${Math.round(v * 1000) / 1000}${dimension === 'angle' ? 'deg' : 'cm'}`;
}

// ---- structure ----

export function isRobotArmBody(node: unknown): node is RobotArmBody {
    const t = (node as AstNode | undefined)?.$type;
    return t === 'RobotArm' || t === 'RobotArmDefinition';
}

/** The robot arm body a node belongs to. */
export function enclosingRobotArm(node: AstNode): RobotArmBody | undefined {
    return AstUtils.getContainerOfType(node, isRobotArmBody);
}

/** Whether a body is embedded in a component (`robotarm { }`) rather than a `.ra` file. */
export function isEmbedded(body: RobotArmBody): body is RobotArm {
    return body.$type === 'RobotArm';
}

/** The component an embedded body belongs to. */
export function robotArmComponent(body: RobotArmBody): ComponentType | undefined {
    return isEmbedded(body) ? (enclosingComponent(body) as ComponentType | undefined) : undefined;
}

export function inputsOf(body: RobotArmBody): RobotArmInput[] {
    return body.elements.filter((e): e is RobotArmInput => e.$type === 'RobotArmInput');
}

export function locationsOf(body: RobotArmBody): Location[] {
    return body.elements.filter((e): e is Location => e.$type === 'Location');
}

export function programsOf(body: RobotArmBody): Program[] {
    return body.elements.filter((e): e is Program => e.$type === 'Program');
}

/** The incoming ports of the component of an embedded body (inherited ones included). */
export function incomingPortsOf(body: RobotArmBody): PortInfo[] {
    const c = robotArmComponent(body);
    return c ? allPorts(c as Parameters<typeof allPorts>[0]).filter((p) => p.direction === 'in') : [];
}

/**
 * The names a `move` argument may refer to, in lookup order: the locations of the body, then its
 * inputs (standalone) or the incoming ports of the component (embedded: the paper's
 * Port2InputAdapter). An embedded body's `input`s are errors (robotarm/input-in-embedded) and
 * are not visible.
 */
export function moveTargetsOf(body: RobotArmBody): Array<Location | RobotArmInput | Port> {
    const own: Array<Location | RobotArmInput | Port> = [...locationsOf(body)];
    if (isEmbedded(body)) own.push(...incomingPortsOf(body).map((p) => p.port as Port));
    else own.push(...inputsOf(body));
    return own;
}

// ---- moves ----

/** What one argument of a `move` denotes. */
export type MoveOperand =
    | { readonly kind: 'constant'; readonly constant: RobotArmConstant; readonly node: MoveArgument }
    | { readonly kind: 'location'; readonly location: Location; readonly node: MoveArgument }
    | { readonly kind: 'value'; readonly measure: ParsedMeasure | undefined; readonly text: string; readonly node: MoveArgument }
    | { readonly kind: 'input'; readonly input: RobotArmInput; readonly node: MoveArgument }
    | { readonly kind: 'port'; readonly port: Port; readonly node: MoveArgument }
    /** A name that resolves to nothing (reported as robotarm/unresolved-name). */
    | { readonly kind: 'unresolved'; readonly name: string; readonly node: MoveArgument };

export function operandOf(a: MoveArgument): MoveOperand {
    if (a.constant) return { kind: 'constant', constant: a.constant, node: a };
    if (a.value !== undefined) return { kind: 'value', measure: parseMeasure(a.value), text: a.value, node: a };
    const target = a.target?.ref;
    switch (target?.$type) {
        case 'Location':
            return { kind: 'location', location: target, node: a };
        case 'RobotArmInput':
            return { kind: 'input', input: target, node: a };
        case 'Port':
            return { kind: 'port', port: target, node: a };
        default:
            return { kind: 'unresolved', name: a.target?.$refText ?? '', node: a };
    }
}

/**
 * The form of a `move`: to a pose (one constant or location) or to joint values (an angle and a
 * height: values, inputs or ports); anything else is ill-formed (robotarm/move-arity).
 */
export type MoveForm =
    | { readonly kind: 'pose'; readonly operand: Extract<MoveOperand, { kind: 'constant' | 'location' }> }
    | { readonly kind: 'joints'; readonly angle: JointOperand; readonly height: JointOperand }
    | { readonly kind: 'ill-formed'; readonly reason: string; readonly node: AstNode };

export type JointOperand = Extract<MoveOperand, { kind: 'value' | 'input' | 'port' | 'unresolved' }>;

export function moveForm(move: Move): MoveForm {
    const ops = move.arguments.map(operandOf);
    const describe = (o: MoveOperand): string => {
        switch (o.kind) {
            case 'constant':
                return `the constant '${o.constant}'`;
            case 'location':
                return `the location '${o.location.name}'`;
            case 'input':
                return `the input '${o.input.name}'`;
            case 'port':
                return `the incoming port '${o.port.name}'`;
            case 'value':
                return `the value '${o.node.$cstNode?.text ?? o.text}'`;
            case 'unresolved':
                return `'${o.name}'`;
        }
    };
    if (ops.length === 1) {
        const o = ops[0]!;
        if (o.kind === 'constant' || o.kind === 'location') return { kind: 'pose', operand: o };
        if (o.kind === 'unresolved') return { kind: 'ill-formed', reason: '', node: move };
        return {
            kind: 'ill-formed',
            node: move,
            reason: `'move' to ${describe(o)} lacks a height: a move goes to a location or a constant ('move toaster;', 'move top;') or to an angle and a height ('move angle height;', 'move 90deg 10cm;')`,
        };
    }
    if (ops.length === 2) {
        const pose = ops.find((o) => o.kind === 'constant' || o.kind === 'location');
        if (pose) {
            return {
                kind: 'ill-formed',
                node: pose.node,
                reason: `${capitalize(describe(pose))} is a whole pose, not a joint value: move to it alone ('move ${pose.node.$cstNode?.text ?? ''};') or give an angle and a height`,
            };
        }
        return { kind: 'joints', angle: ops[0] as JointOperand, height: ops[1] as JointOperand };
    }
    return {
        kind: 'ill-formed',
        node: move,
        reason: `'move' takes one location or constant, or an angle and a height, but ${ops.length} arguments are given`,
    };
}

function capitalize(s: string): string {
    return s.charAt(0).toUpperCase() + s.slice(1);
}

// ---- programs as steps (for generators) ----

/** Where a joint target comes from when a move starts. */
export type JointSource =
    /** A fixed value in SI units (rad, m): from a literal, a location or a constant. */
    | { readonly kind: 'fixed'; readonly si: number }
    /** The joint keeps its current value (the base angle on `move top;`/`move bottom;`). */
    | { readonly kind: 'keep' }
    /** The latest value of an input (standalone) or incoming port (embedded), in `unit` (INPUT_UNITS). */
    | {
          readonly kind: 'input' | 'port';
          readonly name: string;
          readonly node: RobotArmInput | Port;
          readonly unit: string;
          readonly toSI: number;
      };

export type RobotArmStep =
    | { readonly kind: 'open' | 'close'; readonly node: GripperStep }
    | {
          readonly kind: 'move';
          readonly node: Move;
          /** The location or constant moved to, if any. */
          readonly target?: { readonly kind: 'location' | 'constant'; readonly name: string };
          readonly angle: JointSource;
          readonly height: JointSource;
      };

/**
 * The steps of a program with their joint-space targets resolved (SI units). Ill-formed moves
 * (reported by the checks) are left out: generators run on models without errors.
 */
export function programSteps(program: Program): RobotArmStep[] {
    const out: RobotArmStep[] = [];
    for (const step of program.steps) {
        if (step.$type === 'GripperStep') {
            out.push({ kind: step.action, node: step });
            continue;
        }
        const resolved = moveTarget(step);
        if (resolved) out.push(resolved);
    }
    return out;
}

/** The resolved joint-space target of a move, or undefined for an ill-formed one. */
export function moveTarget(move: Move): Extract<RobotArmStep, { kind: 'move' }> | undefined {
    const form = moveForm(move);
    if (form.kind === 'ill-formed') return undefined;
    if (form.kind === 'pose') {
        const o = form.operand;
        if (o.kind === 'constant') {
            return {
                kind: 'move',
                node: move,
                target: { kind: 'constant', name: o.constant },
                angle: { kind: 'keep' },
                height: { kind: 'fixed', si: ROBOT_ARM_PROFILE.constants[o.constant] },
            };
        }
        const angle = parseMeasure(o.location.angle)?.si;
        const height = parseMeasure(o.location.height)?.si;
        if (angle === undefined || height === undefined) return undefined;
        return {
            kind: 'move',
            node: move,
            target: { kind: 'location', name: o.location.name },
            angle: { kind: 'fixed', si: angle },
            height: { kind: 'fixed', si: height },
        };
    }
    const angle = jointSource(form.angle, 'angle');
    const height = jointSource(form.height, 'height');
    return angle && height ? { kind: 'move', node: move, angle, height } : undefined;
}

function jointSource(o: JointOperand, dimension: Dimension): JointSource | undefined {
    switch (o.kind) {
        case 'value':
            return o.measure?.si !== undefined && o.measure.dimension === dimension ? { kind: 'fixed', si: o.measure.si } : undefined;
        case 'input':
        case 'port': {
            const node = o.kind === 'input' ? o.input : o.port;
            const unit = INPUT_UNITS[dimension];
            return { kind: o.kind, name: node.name, node, unit, toSI: UNITS[unit]!.toSI };
        }
        default:
            return undefined;
    }
}

/** The inputs (standalone) or incoming ports (embedded) that feed a move, in argument order. */
export function feedersOf(move: Move): Array<RobotArmInput | Port> {
    return move.arguments
        .map(operandOf)
        .flatMap((o): Array<RobotArmInput | Port> => (o.kind === 'input' ? [o.input] : o.kind === 'port' ? [o.port] : []));
}

/** The inputs or ports any program of a body reads (each once, in order of first use). */
export function feedersOfBody(body: RobotArmBody): Array<RobotArmInput | Port> {
    const seen = new Set<AstNode>();
    const out: Array<RobotArmInput | Port> = [];
    for (const p of programsOf(body)) {
        for (const s of p.steps) {
            if (s.$type !== 'Move') continue;
            for (const f of feedersOf(s))
                if (!seen.has(f)) {
                    seen.add(f);
                    out.push(f);
                }
        }
    }
    return out;
}

/** The type of an input or port that feeds a move. */
export function feederType(node: RobotArmInput | Port, body: RobotArmBody): SymType | undefined {
    if (node.$type === 'RobotArmInput') return typeOfMCType(node.type as Parameters<typeof typeOfMCType>[0]);
    return incomingPortsOf(body).find((p) => p.port === node)?.type;
}

// ---- the port protocol of an embedded robot arm (docs/robotarm.md) ----

export const RobotArmProtocol = {
    /** The incoming port whose messages start programs; its type is an enum of program names. */
    commandPort: 'cmd',
    /** The outgoing port that reports the arm's state; its type is an enum with `statusValues`. */
    statusPort: 'status',
    statusValues: ['IDLE', 'BUSY', 'DONE'] as const,
    /** A command constant that names no program and does nothing ("no command in this slice"). */
    noCommand: 'NONE',
} as const;

export type RobotArmStatus = (typeof RobotArmProtocol.statusValues)[number];

/** `PickupAndDeploy` -> `PICKUP_AND_DEPLOY`, the enum constant naming a program. */
export function commandConstantName(programName: string): string {
    return programName
        .replace(/([a-z0-9])([A-Z])/g, '$1_$2')
        .replace(/([A-Z]+)([A-Z][a-z])/g, '$1_$2')
        .toUpperCase();
}

/** The program a command constant selects: the program of the same name or whose UPPER_SNAKE_CASE form it is. */
export function programForCommand(body: RobotArmBody, constant: string): Program | undefined {
    const programs = programsOf(body);
    return programs.find((p) => p.name === constant) ?? programs.find((p) => p.name && commandConstantName(p.name) === constant);
}

/** The enum constants of a port type (undefined when the type is no enum). */
export function enumConstants(t: SymType | undefined): string[] | undefined {
    if (t?.kind !== 'object' || t.decl.$type !== 'CDEnum') return undefined;
    return t.decl.constants.map((c) => c.name);
}

/** The protocol ports of an embedded body's component, as far as they exist. */
export function protocolPorts(body: RobotArm): { cmd?: PortInfo; status?: PortInfo } {
    const c = robotArmComponent(body);
    if (!c) return {};
    const ports = allPorts(c as Parameters<typeof allPorts>[0]);
    return {
        cmd: ports.find((p) => p.name === RobotArmProtocol.commandPort),
        status: ports.find((p) => p.name === RobotArmProtocol.statusPort),
    };
}

/** The command constants of an embedded body with the program each selects (for generators). */
export function commandTable(body: RobotArm): Array<{ constant: string; program: Program | undefined }> {
    const constants = enumConstants(protocolPorts(body).cmd?.type) ?? [];
    return constants.map((constant) => ({
        constant,
        program: constant === RobotArmProtocol.noCommand ? undefined : programForCommand(body, constant),
    }));
}
