import { describe, expect, test } from 'vitest';
import { dump, hits, validate, type Finding } from './helpers.js';

const TYPES = 'classdiagram ArmTypes {\n  enum ArmCommand { NONE, PICKUP; }\n  enum ArmStatus { IDLE, BUSY, DONE; }\n}';
const PROTOCOL = 'in ArmCommand cmd, out ArmStatus status';

/** An embedded robot arm `Arm.arc` with the protocol ports plus `ports`, and a program `Pickup` with `steps`. */
function arm(ports: string, steps: string, extra = '', types = TYPES): Record<string, string> {
    const list = [PROTOCOL, ports].filter((p) => p).join(', ');
    return {
        'ArmTypes.cd': types,
        'Arm.arc': `component Arm {\n  port ${list};\n  robotarm {\n${extra}    program Pickup { ${steps} }\n  }\n}`,
    };
}

/** A standalone `R.ra` with the given body. */
function ra(body: string, name = 'R', file = 'R.ra'): Record<string, string> {
    return { [file]: `robotarm ${name} {\n${body}\n}` };
}

/** The findings of one code, as `severity@text`. */
function only(found: Finding[], code: string): string[] {
    return found.filter((f) => f.code === code).map((f) => `${f.severity}@${f.text}`);
}

function clean(found: Finding[]): void {
    expect(found, dump(found)).toEqual([]);
}

describe('robotarm/input-in-embedded', () => {
    test('an input in an embedded block is an error on the declaration, naming the port to declare', async () => {
        const found = await validate(arm('in int angle, in int height', 'move angle height;', '    input double speed;\n'));
        expect(only(found, 'robotarm/input-in-embedded')).toEqual(['error@input double speed;']);
        expect(found.find((f) => f.code === 'robotarm/input-in-embedded')!.message).toContain("'port in double speed;'");
    });
    test('valid: inputs in a .ra file', async () => {
        clean(await validate(ra('  input int angle;\n  input int height;\n  program P { move angle height; }')));
    });
});

describe('robotarm/move-not-numeric', () => {
    test('a port of a non-numeric type, reported on the argument', async () => {
        const found = await validate(arm('in String angle, in boolean height', 'move angle height;'));
        expect(only(found, 'robotarm/move-not-numeric')).toEqual(['error@angle', 'error@height']);
        expect(found[0]!.message).toMatch(/incoming port 'angle' is of type String/);
    });
    test('an input of a non-numeric type in a .ra file', async () => {
        const found = await validate({ ...ra('  input String angle;\n  input int height;\n  program P { move angle height; }') });
        expect(only(found, 'robotarm/move-not-numeric')).toEqual(['error@angle']);
        expect(found[0]!.message).toMatch(/input 'angle' is of type String/);
    });
    test('an inherited port of a non-numeric type', async () => {
        const found = await validate({
            ...arm('in int height', 'move angle height;'),
            'Base.arc': 'component Base {\n  port in boolean angle;\n}',
            'Arm.arc': arm('in int height', 'move angle height;')['Arm.arc']!.replace('component Arm', 'component Arm extends Base'),
        });
        expect(only(found, 'robotarm/move-not-numeric')).toEqual(['error@angle']);
    });
    test('valid: every numeric type, boxed or not', async () => {
        clean(await validate(arm('in double angle, in Integer height', 'move angle height;')));
        clean(
            await validate(
                ra('  input long a;\n  input Double h;\n  input short s;\n  input float f;\n  program P { move a h; move s f; }'),
            ),
        );
    });
    test('an unresolved input type is reported once, as such', async () => {
        const found = await validate(ra('  input Angle a;\n  program P { move a 10cm; }'));
        expect(found.map((f) => f.code)).toEqual(['arc/unresolved-type']);
    });
});

describe('robotarm/unresolved-name', () => {
    test('embedded: a name that is no location, constant or incoming port', async () => {
        const found = await validate(arm('in int angle, in int height, out int o', 'move hight; move o height; move angle heigth;'));
        expect(only(found, 'robotarm/unresolved-name')).toEqual(['error@hight', 'error@o', 'error@heigth']);
        expect(found.find((f) => f.text === 'hight')!.message).toContain('incoming port of the component');
    });
    test('standalone: a name that is no location, constant or input', async () => {
        const found = await validate(ra('  input int angle;\n  program P { move angle height; move shelf; }'));
        expect(only(found, 'robotarm/unresolved-name')).toEqual(['error@height', 'error@shelf']);
        expect(found[0]!.message).toContain('input of this robot arm');
        expect(found.map((f) => f.code)).toEqual(['robotarm/unresolved-name', 'robotarm/unresolved-name']);
    });
    test('valid: locations, constants, ports', async () => {
        clean(
            await validate(
                arm(
                    'in int angle, in int height',
                    'move top; move shelf; move angle height; move bottom;',
                    '    location shelf 10deg 10cm;\n',
                ),
            ),
        );
    });
});

describe('robotarm/move-arity', () => {
    test('a single joint value, a pose among joint values, and too many arguments', async () => {
        const found = await validate(
            ra(
                '  input int angle;\n  input int height;\n  location shelf 0deg 10cm;\n  program P {\n    move angle;\n    move 90deg;\n    move shelf height;\n    move angle top;\n    move angle height 10cm;\n  }',
            ),
        );
        expect(only(found, 'robotarm/move-arity')).toEqual([
            'error@move angle;',
            'error@move 90deg;',
            'error@shelf',
            'error@top',
            'error@move angle height 10cm;',
        ]);
        expect(found[0]!.message).toContain('lacks a height');
        expect(found[2]!.message).toContain("move to it alone ('move shelf;')");
    });
    test('an unresolved single name is reported as unresolved only', async () => {
        const found = await validate(ra('  program P { move nowhere; }'));
        expect(found.map((f) => f.code)).toEqual(['robotarm/unresolved-name']);
    });
    test('valid: one pose, or an angle and a height of any kind', async () => {
        clean(
            await validate(
                ra(
                    '  input int angle;\n  input int height;\n  location shelf 0deg 10cm;\n  program P { move shelf; move top; move angle height; move 10deg height; move angle 10cm; move 1rad 0.1m; }',
                ),
            ),
        );
    });
});

describe('robotarm/duplicate-name', () => {
    test('two locations, an input and a location, two programs', async () => {
        const found = await validate(
            ra(
                '  input int a;\n  location a 0deg 10cm;\n  location b 0deg 10cm;\n  location b 10deg 10cm;\n  program P { move b; }\n  program P { move b; }',
            ),
        );
        expect(found.filter((f) => f.code === 'robotarm/duplicate-name').map((f) => `${f.text}@${f.line}`)).toEqual(['a@3', 'b@5', 'P@7']);
        expect(found.find((f) => f.line === 3)!.message).toContain('has the name of the input declared on line 2');
    });
    test('embedded: a location with the name of an incoming port', async () => {
        const found = await validate(arm('in int shelf, in int height', 'move shelf;', '    location shelf 0deg 10cm;\n'));
        expect(only(found, 'robotarm/duplicate-name')).toEqual(['error@shelf']);
        expect(found.find((f) => f.code === 'robotarm/duplicate-name')!.message).toContain('incoming port');
    });
    test('valid: a program and a location may share a name (different namespaces)', async () => {
        const found = await validate(ra('  location pick 0deg 10cm;\n  program pick { move pick; }'));
        expect(
            found.map((f) => f.code),
            dump(found),
        ).toEqual(['robotarm/naming-convention']);
    });
});

describe('robotarm/reserved-name', () => {
    test('inputs and locations named like a constant', async () => {
        const found = await validate(ra('  input int top;\n  location bottom 0deg 10cm;\n  program P { move bottom; }'));
        expect(only(found, 'robotarm/reserved-name')).toEqual(['error@top', 'error@bottom']);
    });
    test('valid: a port named top in a component without move to it', async () => {
        clean(await validate(arm('in int top, in int height', 'move top;')));
    });
});

describe('robotarm/invalid-unit', () => {
    test('values without unit and with an unknown unit', async () => {
        const found = await validate(
            ra('  input int h;\n  location a 90 10cm;\n  location b 90deg 10km;\n  program P { move 90dx h; move 90 h; }'),
        );
        expect(only(found, 'robotarm/invalid-unit')).toEqual(['error@90', 'error@10km', 'error@90dx', 'error@90 h']);
        expect(found.find((f) => f.text === '10km')!.message).toContain("Unknown unit 'km'");
        expect(found.find((f) => f.text === '90')!.message).toContain("e.g. '90deg'");
        // The glued value is not also reported as a move with one argument.
        expect(hits(found, 'robotarm/move-arity')).toEqual([]);
    });
    test('valid: every unit', async () => {
        clean(
            await validate(
                ra(
                    '  location a 90deg 10cm;\n  location b 1rad 100mm;\n  location c -1.5rad 0.25m;\n  program P { move a; move b; move c; move 1rad 50mm; }',
                ),
            ),
        );
    });
});

describe('robotarm/unit-mismatch', () => {
    test('a height where an angle is expected and vice versa, in locations and moves', async () => {
        const found = await validate(ra('  input int h;\n  location a 10cm 90deg;\n  program P { move 10cm h; move 0deg 1rad; }'));
        expect(only(found, 'robotarm/unit-mismatch')).toEqual(['error@10cm', 'error@90deg', 'error@10cm', 'error@1rad']);
        expect(found[0]!.message).toBe("'10cm' is a height, but a joint angle is expected here ('deg' or 'rad').");
    });
    test('valid: angle first, height second', async () => {
        clean(await validate(ra('  location a 90deg 10cm;\n  program P { move a; move 90deg 10cm; }')));
    });
});

describe('robotarm/joint-limit', () => {
    test("values outside the reference arm's range", async () => {
        const found = await validate(
            ra(
                '  location a 181deg 10cm;\n  location b -3.2rad 10cm;\n  location c 0deg 1cm;\n  program P { move a; move b; move c; move 0deg 31cm; move 0deg 0.5m; }',
            ),
        );
        expect(only(found, 'robotarm/joint-limit')).toEqual(['error@181deg', 'error@-3.2rad', 'error@1cm', 'error@31cm', 'error@0.5m']);
        expect(found[0]!.message).toContain('-180deg .. 180deg');
        expect(found[2]!.message).toContain('2cm .. 30cm');
    });
    test('valid: the limits themselves', async () => {
        clean(
            await validate(
                ra(
                    '  location a 180deg 30cm;\n  location b -180deg 2cm;\n  location c 3.14rad 20mm;\n  program P { move a; move b; move c; move 0deg 0.3m; }',
                ),
            ),
        );
    });
});

describe('robotarm/empty-program', () => {
    test('a program without steps is a warning on its name', async () => {
        const found = await validate(ra('  program Nothing { }'));
        expect(only(found, 'robotarm/empty-program')).toEqual(['warning@Nothing']);
    });
    test('valid: one step is enough', async () => {
        clean(await validate(ra('  program Release { open; }')));
    });
});

describe('robotarm/naming-convention', () => {
    test('robot arm and programs upper case, inputs and locations lower case', async () => {
        const found = await validate(
            ra('  input int Angle;\n  location Shelf 0deg 10cm;\n  program pick { move Shelf; move Angle 10cm; }', 'r', 'r.ra'),
        );
        expect(only(found, 'robotarm/naming-convention')).toEqual(['warning@r', 'warning@Angle', 'warning@Shelf', 'warning@pick']);
    });
    test('valid: the conventions', async () => {
        clean(await validate(ra('  input int angle;\n  location shelf 0deg 10cm;\n  program Pick { move shelf; move angle 10cm; }')));
    });
});

describe('the port protocol', () => {
    const body = (programs: string) => `  robotarm {\n${programs}\n  }`;
    const comp = (ports: string, programs = '    program Pickup { open; }') => `component Arm {\n  port ${ports};\n${body(programs)}\n}`;

    test('robotarm/missing-cmd-port: no cmd port, or an outgoing one', async () => {
        let found = await validate({ 'ArmTypes.cd': TYPES, 'Arm.arc': comp('out ArmStatus status') });
        expect(only(found, 'robotarm/missing-cmd-port')).toEqual(['error@robotarm']);
        expect(found[0]!.message).toContain("'port in <Enum> cmd;'");
        found = await validate({ 'ArmTypes.cd': TYPES, 'Arm.arc': comp('out ArmCommand cmd, out ArmStatus status') });
        expect(only(found, 'robotarm/missing-cmd-port')).toEqual(['error@robotarm']);
        expect(found[0]!.message).toContain("its port 'cmd' is outgoing");
    });

    test('robotarm/cmd-port-type: not an enum', async () => {
        const found = await validate({ 'ArmTypes.cd': TYPES, 'Arm.arc': comp('in int cmd, out ArmStatus status') });
        expect(only(found, 'robotarm/cmd-port-type')).toEqual(['error@int']);
    });

    test('robotarm/missing-status-port: no status port, or an incoming one', async () => {
        let found = await validate({ 'ArmTypes.cd': TYPES, 'Arm.arc': comp('in ArmCommand cmd') });
        expect(only(found, 'robotarm/missing-status-port')).toEqual(['error@robotarm']);
        found = await validate({ 'ArmTypes.cd': TYPES, 'Arm.arc': comp('in ArmCommand cmd, in ArmStatus status') });
        expect(only(found, 'robotarm/missing-status-port')).toEqual(['error@robotarm']);
        expect(found.find((f) => f.code === 'robotarm/missing-status-port')!.message).toContain("its port 'status' is incoming");
    });

    test('robotarm/status-port-type: not an enum, or an enum without IDLE, BUSY, DONE', async () => {
        let found = await validate({ 'ArmTypes.cd': TYPES, 'Arm.arc': comp('in ArmCommand cmd, out boolean status') });
        expect(only(found, 'robotarm/status-port-type')).toEqual(['error@boolean']);
        found = await validate({ 'ArmTypes.cd': TYPES.replace('IDLE, BUSY, DONE', 'IDLE, RUNNING'), 'Arm.arc': comp(PROTOCOL) });
        expect(only(found, 'robotarm/status-port-type')).toEqual(['error@ArmStatus']);
        expect(found[0]!.message).toContain('lacks BUSY, DONE');
    });

    test('robotarm/command-without-program: every constant but NONE selects a program', async () => {
        const found = await validate({
            'ArmTypes.cd': TYPES.replace('NONE, PICKUP', 'NONE, PICKUP, PARK, STOW'),
            'Arm.arc': comp(PROTOCOL),
        });
        expect(only(found, 'robotarm/command-without-program')).toEqual(['error@robotarm', 'error@robotarm']);
        expect(found.map((f) => f.message).join('\n')).toMatch(/'ArmCommand.PARK'[\s\S]*'ArmCommand.STOW'/);
    });

    test('robotarm/program-without-command: a program no constant selects (warning)', async () => {
        const found = await validate({
            'ArmTypes.cd': TYPES,
            'Arm.arc': comp(PROTOCOL, '    program Pickup { open; }\n    program Stow { close; }'),
        });
        expect(only(found, 'robotarm/program-without-command')).toEqual(['warning@Stow']);
        expect(found[0]!.message).toContain("add 'STOW' to ArmCommand");
    });

    test('constants select programs by the same name or by UPPER_SNAKE_CASE', async () => {
        const types =
            'classdiagram ArmTypes {\n  enum ArmCommand { NONE, PICKUP_AND_DEPLOY, Park, FETCH2_TOAST; }\n  enum ArmStatus { IDLE, BUSY, DONE, ERROR; }\n}';
        clean(
            await validate({
                'ArmTypes.cd': types,
                'Arm.arc': comp(
                    PROTOCOL,
                    '    program PickupAndDeploy { open; }\n    program Park { close; }\n    program Fetch2Toast { open; }',
                ),
            }),
        );
    });

    test('inherited protocol ports count; types may be qualified', async () => {
        clean(
            await validate({
                'arm/types/ArmTypes.cd': `package arm.types;\n${TYPES}`,
                'arm/ArmBase.arc':
                    'package arm;\nimport arm.types.ArmTypes.*;\ncomponent ArmBase {\n  port in ArmCommand cmd, out arm.types.ArmStatus status;\n}',
                'arm/Arm.arc': 'package arm;\ncomponent Arm extends ArmBase {\n  robotarm {\n    program Pickup { open; }\n  }\n}',
            }),
        );
    });

    test('a standalone .ra file has no ports and no protocol checks', async () => {
        clean(await validate(ra('  program Pickup { open; }')));
    });
});

describe('robotarm/file-name-mismatch and robotarm/package-mismatch', () => {
    test('the file is named after the robot arm, its package is its folder', async () => {
        let found = await validate(ra('  program P { open; }', 'Other'));
        expect(only(found, 'robotarm/file-name-mismatch')).toEqual(['error@Other']);
        found = await validate({ 'a/b/R.ra': 'package a.c;\nrobotarm R { }' });
        expect(only(found, 'robotarm/package-mismatch')).toEqual(['error@a.c']);
        found = await validate({ 'a/R.ra': 'robotarm R { }' });
        expect(only(found, 'robotarm/package-mismatch')).toEqual(['error@R']);
        expect(found[0]!.message).toContain("must be 'a'");
    });
    test('valid: matching name and package', async () => {
        clean(await validate({ 'a/b/R.ra': 'package a.b;\nrobotarm R { }', 'S.ra': 'robotarm S { }' }));
    });
});
