import type { DiagnosticCatalog } from '@maa/language-adl';

/** The class diagram of the embedded examples: the command and status enums of the port protocol. */
const TYPES = 'classdiagram ArmTypes {\n  enum ArmCommand { NONE, PICKUP; }\n  enum ArmStatus { IDLE, BUSY, DONE; }\n}';

const PROGRAM =
    '    location shelf 90deg 10cm;\n    program Pickup {\n      move top; open; move shelf; close; move top; move angle height; open;\n    }';

/** An arm controller with the given port list and robotarm body (default: the valid ones). */
function arm(ports: string, body: string = PROGRAM, types: string = TYPES): Record<string, string> {
    return { 'ArmTypes.cd': types, 'Arm.arc': `component Arm {\n  port ${ports};\n  robotarm {\n${body}\n  }\n}` };
}

const PORTS = 'in ArmCommand cmd,\n       in int angle,\n       in int height,\n       out ArmStatus status';

/** A standalone `.ra` file `Shelf.ra` with the given body (default: a valid one). */
function ra(body: string, header = '', name = 'Shelf', file = 'Shelf.ra'): Record<string, string> {
    return { [file]: `${header}robotarm ${name} {\n${body}\n}` };
}

const RA_BODY =
    '  input int angle;\n  input int height;\n  location shelf 90deg 10cm;\n  program Pickup {\n    move top; open; move shelf; close; move angle height; open;\n  }';

/** The RobotArm language's diagnostics (`robotarm/*`), in `.ra` files and embedded `robotarm { }` blocks. */
export const ROBOTARM_DIAGNOSTICS: DiagnosticCatalog = {
    title: 'RobotArm',
    intro:
        'Checks of standalone RobotArm files (`.ra`) and of embedded `robotarm { }` blocks (docs/robotarm.md). ' +
        "Values carry units: angles in `deg` or `rad`, heights in `mm`, `cm` or `m`; `top` and `bottom` are the lift's upper and lower positions. " +
        'A component with a `robotarm` block follows the RobotArm port protocol: an incoming enum port `cmd` selects the program, an outgoing enum port `status` reports IDLE, BUSY and DONE.',
    entries: [
        {
            code: 'robotarm/input-in-embedded',
            severity: 'error',
            rule: "An embedded `robotarm { }` block declares no `input`s: the names after `move` denote incoming ports of the component (the paper's Port2InputAdapter). Declare a port instead.",
            invalid: { files: arm(PORTS, `    input int angle;\n${PROGRAM}`), at: 'input int angle;' },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/move-not-numeric',
            severity: 'error',
            rule: 'The inputs and incoming ports that a `move` reads are of a numeric type (`int`, `double`, `Integer`, ...): the joint angle in degrees, the gripper height in centimeters.',
            invalid: {
                files: arm('in ArmCommand cmd,\n       in boolean angle,\n       in int height,\n       out ArmStatus status'),
                at: 'angle',
            },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/unresolved-name',
            severity: 'error',
            rule: 'A name after `move` is a location of the robot arm, a constant (`top`, `bottom`), an input (in a `.ra` file) or an incoming port of the component (in an embedded block).',
            invalid: { files: arm(PORTS, PROGRAM.replace('move angle height', 'move angle hight')), at: 'hight' },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/move-arity',
            severity: 'error',
            rule: '`move` goes to one location or constant (`move shelf;`, `move top;`) or to an angle and a height (`move angle height;`, `move 90deg 10cm;`), nothing else.',
            invalid: { files: arm(PORTS, PROGRAM.replace('move angle height', 'move angle')), at: 'move angle;' },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/duplicate-name',
            severity: 'error',
            rule: 'Inputs and locations share one namespace (the names after `move`), programs another; in an embedded block a location must not have the name of an incoming port.',
            invalid: {
                files: ra(RA_BODY.replace('  location shelf 90deg 10cm;', '  location shelf 90deg 10cm;\n  location shelf 45deg 12cm;')),
                at: 'shelf',
            },
            valid: {
                files: ra(RA_BODY.replace('  location shelf 90deg 10cm;', '  location shelf 90deg 10cm;\n  location plate 45deg 12cm;')),
            },
        },
        {
            code: 'robotarm/reserved-name',
            severity: 'error',
            rule: 'No input or location is named `top` or `bottom`: `move top;` always moves to the constant.',
            invalid: {
                files: ra(RA_BODY.replace('  location shelf 90deg 10cm;', '  location shelf 90deg 10cm;\n  location bottom 0deg 5cm;')),
                at: 'bottom',
            },
            valid: { files: ra(RA_BODY.replace('  location shelf 90deg 10cm;', '  location shelf 90deg 10cm;\n  location low 0deg 5cm;')) },
        },
        {
            code: 'robotarm/invalid-unit',
            severity: 'error',
            rule: 'Every value has a unit: `deg` or `rad` for the joint angle, `mm`, `cm` or `m` for the gripper height.',
            invalid: { files: ra(RA_BODY.replace('location shelf 90deg 10cm', 'location shelf 90 10cm')), at: '90' },
            valid: { files: ra(RA_BODY) },
        },
        {
            code: 'robotarm/unit-mismatch',
            severity: 'error',
            rule: 'A location and a `move` to values give the joint angle first (an angle unit), then the gripper height (a length unit).',
            invalid: { files: ra(RA_BODY.replace('move angle height', 'move 10cm height')), at: '10cm' },
            valid: { files: ra(RA_BODY.replace('move angle height', 'move 10deg height')) },
        },
        {
            code: 'robotarm/joint-limit',
            severity: 'error',
            rule: "Values lie within the reference arm's range: joint angle -180deg .. 180deg, gripper height 2cm (`bottom`) .. 30cm (`top`). Values read from inputs and ports are clamped to the range at run time.",
            invalid: { files: ra(RA_BODY.replace('location shelf 90deg 10cm', 'location shelf 90deg 45cm')), at: '45cm' },
            valid: { files: ra(RA_BODY.replace('location shelf 90deg 10cm', 'location shelf 90deg 0.3m')) },
        },
        {
            code: 'robotarm/empty-program',
            severity: 'warning',
            rule: 'A program has at least one step; an empty program completes as soon as it starts.',
            invalid: { files: ra(`${RA_BODY}\n  program Rest { }`), at: 'Rest' },
            valid: { files: ra(`${RA_BODY}\n  program Rest { move bottom; }`) },
        },
        {
            code: 'robotarm/naming-convention',
            severity: 'warning',
            rule: 'Robot arm and program names start with an upper-case letter (command constants name programs), input and location names with a lower-case letter.',
            invalid: { files: ra(RA_BODY.replace('program Pickup', 'program pickup')), at: 'pickup' },
            valid: { files: ra(RA_BODY) },
        },
        {
            code: 'robotarm/missing-cmd-port',
            severity: 'error',
            rule: 'A component with a `robotarm` block has an incoming port `cmd` whose messages select the program to run (port protocol).',
            invalid: { files: arm('in int angle,\n       in int height,\n       out ArmStatus status'), at: 'robotarm' },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/cmd-port-type',
            severity: 'error',
            rule: 'The type of the `cmd` port is an enum from a class diagram whose constants name the programs: a constant selects the program of the same name or whose UPPER_SNAKE_CASE form it is (`PICKUP_AND_DEPLOY` selects `PickupAndDeploy`); `NONE` selects nothing.',
            invalid: {
                files: arm('in String cmd,\n       in int angle,\n       in int height,\n       out ArmStatus status'),
                at: 'String',
            },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/missing-status-port',
            severity: 'error',
            rule: 'A component with a `robotarm` block has an outgoing port `status` that reports when a program runs and when it completes (port protocol).',
            invalid: { files: arm('in ArmCommand cmd,\n       in int angle,\n       in int height'), at: 'robotarm' },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/status-port-type',
            severity: 'error',
            rule: 'The type of the `status` port is an enum from a class diagram with (at least) the constants IDLE, BUSY and DONE.',
            invalid: { files: arm('in ArmCommand cmd,\n       in int angle,\n       in int height,\n       out int status'), at: 'int' },
            valid: { files: arm(PORTS) },
        },
        {
            code: 'robotarm/command-without-program',
            severity: 'error',
            rule: 'Every constant of the `cmd` enum except `NONE` selects a program: a controller that sends it would otherwise wait for DONE forever.',
            invalid: { files: arm(PORTS, PROGRAM, TYPES.replace('NONE, PICKUP;', 'NONE, PICKUP, PARK;')), at: 'robotarm' },
            valid: {
                files: arm(
                    PORTS,
                    `${PROGRAM}\n    program Park {\n      move top; move 0deg 30cm;\n    }`,
                    TYPES.replace('NONE, PICKUP;', 'NONE, PICKUP, PARK;'),
                ),
            },
        },
        {
            code: 'robotarm/program-without-command',
            severity: 'warning',
            rule: 'Every program of an embedded block is selected by a constant of the `cmd` enum; otherwise it can never run.',
            invalid: { files: arm(PORTS, `${PROGRAM}\n    program Park {\n      move top; move 0deg 30cm;\n    }`), at: 'Park' },
            valid: {
                files: arm(
                    PORTS,
                    `${PROGRAM}\n    program Park {\n      move top; move 0deg 30cm;\n    }`,
                    TYPES.replace('NONE, PICKUP;', 'NONE, PICKUP, PARK;'),
                ),
            },
        },
        {
            code: 'robotarm/file-name-mismatch',
            severity: 'error',
            rule: 'A `.ra` file is named after its robot arm.',
            invalid: { files: ra(RA_BODY, '', 'Storage'), at: 'Storage' },
            valid: { files: ra(RA_BODY) },
        },
        {
            code: 'robotarm/package-mismatch',
            severity: 'error',
            rule: 'The package declaration of a `.ra` file (optional) equals its folder path below the model root, as for `.arc` files.',
            invalid: { files: ra(RA_BODY, 'package arm;\n\n'), at: 'arm' },
            valid: { files: ra(RA_BODY, 'package arm;\n\n', 'Shelf', 'arm/Shelf.ra') },
        },
    ],
};
