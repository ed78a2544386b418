import { AstUtils, type LangiumDocument } from 'langium';
import { describe, expect, test } from 'vitest';
import type { ArcModel, Location, Move, Program, RobotArm, RobotArmModel } from '../src/generated/ast.js';
import { inputsOf, locationsOf, programsOf } from '../src/index.js';
import { build, dump, validate } from './helpers.js';
import { ARM_TYPES, LISTING_1, LISTING_2 } from './fixtures.js';

function noErrors(doc: LangiumDocument): void {
    expect(doc.parseResult.lexerErrors).toEqual([]);
    expect(doc.parseResult.parserErrors.map((e) => e.message)).toEqual([]);
}

function steps(p: Program): string[] {
    return p.steps.map((s) =>
        s.$type === 'GripperStep'
            ? s.action
            : `move ${(s as Move).arguments.map((a) => a.constant ?? a.value ?? a.target?.$refText).join(' ')}`,
    );
}

async function robotArmOf(body: string, ports = ''): Promise<RobotArm> {
    const {
        docs: [doc],
    } = await build({ 'Comp.arc': `component Comp {\n${ports}\n  robotarm {\n${body}\n  }\n}` });
    noErrors(doc!);
    return AstUtils.streamAst(doc!.parseResult.value).find((n): n is RobotArm => n.$type === 'RobotArm')!;
}

describe('the paper', () => {
    test('Listing 1 parses as a standalone .ra file and has no diagnostics', async () => {
        const found = await validate({ 'ToastService.ra': LISTING_1 });
        expect(found, dump(found)).toEqual([]);
        const {
            docs: [doc],
        } = await build({ 'ToastService.ra': LISTING_1 });
        noErrors(doc!);
        const model = doc!.parseResult.value as RobotArmModel;
        expect(model.$type).toBe('RobotArmModel');
        const r = model.robot!;
        expect(r.name).toBe('ToastService');
        expect(inputsOf(r).map((i) => `${i.type.$cstNode?.text} ${i.name}`)).toEqual(['int angle', 'int height']);
        expect(locationsOf(r).map((l) => [l.name, l.angle, l.height])).toEqual([['toaster', '120deg', '20cm']]);
        expect(programsOf(r).map((p) => p.name)).toEqual(['PickupAndDeploy']);
        expect(steps(programsOf(r)[0]!)).toEqual(['move top', 'open', 'move toaster', 'close', 'move top', 'move angle height', 'open']);
    });

    test('Listing 2 parses as the behavior of a component and has no diagnostics', async () => {
        const files = { 'ArmTypes.cd': ARM_TYPES, 'ArmController.arc': LISTING_2 };
        const found = await validate(files);
        expect(found, dump(found)).toEqual([]);
        const { docs } = await build(files);
        const doc = docs[1]!;
        noErrors(doc);
        const c = (doc.parseResult.value as ArcModel).component!;
        const behavior = c.body.elements.find((e) => e.$type === 'BehaviorDeclaration');
        const r = (behavior as { behavior: RobotArm }).behavior;
        expect(r.$type).toBe('RobotArm');
        expect(inputsOf(r)).toEqual([]);
        expect(locationsOf(r).map((l) => l.name)).toEqual(['toaster']);
        expect(steps(programsOf(r)[0]!)).toEqual(['move top', 'open', 'move toaster', 'close', 'move top', 'move angle height', 'open']);
    });
});

describe('values with units', () => {
    test('every unit, signs, decimals, exponents, and spaces before the unit', async () => {
        const r = await robotArmOf(`    location a 120deg 20cm;
    location b -30deg 0.2m;
    location c 1.5rad 100mm;
    location d 90 deg 10 cm;
    location e .5rad 1e-1m;
    location f 0deg 25cm;`);
        expect(locationsOf(r).map((l: Location) => `${l.angle} ${l.height}`)).toEqual([
            '120deg 20cm',
            '-30deg 0.2m',
            '1.5rad 100mm',
            '90deg 10cm',
            '.5rad 1e-1m',
            '0deg 25cm',
        ]);
    });

    test('in moves: values, names, constants, mixed', async () => {
        const r = await robotArmOf(
            '    program P { move 90deg 10cm; move -45.5deg height; move angle 2.5cm; move bottom; move top; }',
            '  port in int angle, in int height;',
        );
        expect(steps(programsOf(r)[0]!)).toEqual([
            'move 90deg 10cm',
            'move -45.5deg height',
            'move angle 2.5cm',
            'move bottom',
            'move top',
        ]);
    });

    test('a value without unit parses (the check reports it)', async () => {
        const r = await robotArmOf('    location a 90 10;');
        expect(locationsOf(r).map((l) => `${l.angle}|${l.height}`)).toEqual(['90|10']);
    });
});

describe('structure', () => {
    test('elements in any order; empty programs and bodies', async () => {
        const r = await robotArmOf('    program A { }\n    location l 0deg 10cm;\n    program B { open; close; }');
        expect(r.elements.map((e) => e.$type)).toEqual(['Program', 'Location', 'Program']);
        const empty = await robotArmOf('');
        expect(empty.elements).toEqual([]);
    });

    test('a .ra file may declare a package; its robot arm is optional while typing', async () => {
        const { docs } = await build({ 'arm/Shelf.ra': 'package arm;\nrobotarm Shelf { }', 'arm/Empty.ra': 'package arm;' });
        for (const d of docs) noErrors(d);
        expect((docs[0]!.parseResult.value as RobotArmModel).package).toBe('arm');
        expect((docs[1]!.parseResult.value as RobotArmModel).robot).toBeUndefined();
    });

    test('inputs may have any type syntax of the family', async () => {
        const {
            docs: [doc],
        } = await build({ 'R.ra': 'robotarm R {\n  input Double a;\n  input long b;\n  input java.lang.Integer c;\n}' });
        noErrors(doc!);
        expect(inputsOf((doc!.parseResult.value as RobotArmModel).robot!).map((i) => i.type.$cstNode?.text)).toEqual([
            'Double',
            'long',
            'java.lang.Integer',
        ]);
    });

    test('syntax errors carry syntax codes', async () => {
        const found = await validate({ 'R.ra': 'robotarm R {\n  program P { move; }\n}' });
        expect(found.map((f) => f.code)).toContain('syntax/unexpected-token');
    });
});

describe('soft keywords', () => {
    test('every RobotArm word stays usable as an identifier in components and class diagrams', async () => {
        const found = await validate({
            'Types.cd':
                'classdiagram Types {\n  class Pose { double rad; double deg; double m; double mm; double cm; }\n  enum Gripper { open, close; }\n}',
            'Gripper.arc': `component Gripper {
  port in boolean open,
       in int top,
       in int bottom,
       out double m;
  int move = 0, location = 1, program = 2, input = 3, robotarm = 4, deg = 5, rad = 6, mm = 7, cm = 8;
  compute {
    boolean close = open;
    m = top + bottom + move + location + program + input + robotarm + deg + rad + mm + cm;
  }
}`,
        });
        expect(found, dump(found)).toEqual([]);
    });

    test('inside a body, words of the language are names where a name is expected', async () => {
        const r = await robotArmOf(
            '    location open 10deg 10cm;\n    location deg 20deg 10cm;\n    program P { move open; move deg; open; }',
        );
        const moves = programsOf(r)[0]!.steps.filter((s): s is Move => s.$type === 'Move');
        expect(moves.map((m) => m.arguments[0]!.target?.ref?.$type)).toEqual(['Location', 'Location']);
    });

    test('`top` and `bottom` after move are the constants', async () => {
        const r = await robotArmOf('    program P { move top; move bottom; }');
        const moves = programsOf(r)[0]!.steps as Move[];
        expect(moves.map((m) => [m.arguments[0]!.constant, m.arguments[0]!.target])).toEqual([
            ['top', undefined],
            ['bottom', undefined],
        ]);
    });
});
