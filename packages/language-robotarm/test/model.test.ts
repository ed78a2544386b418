import { AstUtils } from 'langium';
import { describe, expect, test } from 'vitest';
import type { Move, RobotArm, RobotArmModel } from '../src/generated/ast.js';
import {
    commandConstantName,
    commandTable,
    feedersOf,
    feedersOfBody,
    INPUT_UNITS,
    parseMeasure,
    programForCommand,
    programSteps,
    programsOf,
    protocolPorts,
    ROBOT_ARM_PROFILE,
    withinLimits,
    type RobotArmStep,
} from '../src/index.js';
import { build } from './helpers.js';
import { ARM_TYPES, LISTING_1, LISTING_2 } from './fixtures.js';

const deg = (d: number): number => (d * Math.PI) / 180;

/** A step in a compact form: `open`, `move <angle> <height>` with SI numbers rounded to 4 places. */
function show(s: RobotArmStep): string {
    if (s.kind !== 'move') return s.kind;
    const joint = (j: Extract<RobotArmStep, { kind: 'move' }>['angle']): string => {
        switch (j.kind) {
            case 'fixed':
                return String(Math.round(j.si * 1e4) / 1e4);
            case 'keep':
                return 'keep';
            default:
                return `${j.kind}:${j.name}[${j.unit}]`;
        }
    };
    return `move ${joint(s.angle)} ${joint(s.height)}${s.target ? ` (${s.target.kind} ${s.target.name})` : ''}`;
}

describe('measures', () => {
    test('are read in SI units', () => {
        expect(parseMeasure('120deg')).toMatchObject({ value: 120, unit: 'deg', dimension: 'angle' });
        expect(parseMeasure('120deg')!.si).toBeCloseTo(deg(120));
        expect(parseMeasure('-1.5rad')!.si).toBe(-1.5);
        expect(parseMeasure('20cm')!.si).toBeCloseTo(0.2);
        expect(parseMeasure('100mm')!.si).toBeCloseTo(0.1);
        expect(parseMeasure('1e-1m')!.si).toBeCloseTo(0.1);
        expect(parseMeasure('90')).toEqual({ value: 90, unit: '' });
        expect(parseMeasure('2km')).toEqual({ value: 2, unit: 'km' });
    });
    test('the reference arm: limits and constants', () => {
        expect(ROBOT_ARM_PROFILE.constants).toEqual({ top: 0.3, bottom: 0.02 });
        expect(withinLimits('angle', Math.PI)).toBe(true);
        expect(withinLimits('angle', deg(181))).toBe(false);
        expect(withinLimits('height', 0.3)).toBe(true);
        expect(withinLimits('height', 0.01)).toBe(false);
        expect(INPUT_UNITS).toEqual({ angle: 'deg', height: 'cm' });
    });
});

describe('programs as steps', () => {
    test('Listing 1: resolved joint-space targets and the inputs that feed moves', async () => {
        const {
            docs: [doc],
        } = await build({ 'ToastService.ra': LISTING_1 });
        const r = (doc!.parseResult.value as RobotArmModel).robot!;
        const [program] = programsOf(r);
        expect(programSteps(program!).map(show)).toEqual([
            'move keep 0.3 (constant top)',
            'open',
            `move ${Math.round(deg(120) * 1e4) / 1e4} 0.2 (location toaster)`,
            'close',
            'move keep 0.3 (constant top)',
            'move input:angle[deg] input:height[cm]',
            'open',
        ]);
        const joints = programSteps(program!)[5] as Extract<RobotArmStep, { kind: 'move' }>;
        expect(joints.angle.kind === 'input' && joints.angle.toSI).toBeCloseTo(Math.PI / 180);
        expect(joints.height.kind === 'input' && joints.height.toSI).toBeCloseTo(0.01);
        const moves = program!.steps.filter((s): s is Move => s.$type === 'Move');
        expect(feedersOf(moves[3]!).map((f) => `${f.$type}:${f.name}`)).toEqual(['RobotArmInput:angle', 'RobotArmInput:height']);
        expect(feedersOfBody(r).map((f) => f.name)).toEqual(['angle', 'height']);
    });

    test('Listing 2: ports feed the moves; literal joint values and bottom', async () => {
        const { docs } = await build({
            'ArmTypes.cd': ARM_TYPES,
            'ArmController.arc': LISTING_2.replace('move angle height; open;', 'move angle height; open; move -90deg 25mm; move bottom;'),
        });
        const r = AstUtils.streamAst(docs[1]!.parseResult.value).find((n): n is RobotArm => n.$type === 'RobotArm')!;
        const steps = programSteps(programsOf(r)[0]!).map(show);
        expect(steps.slice(5)).toEqual([
            'move port:angle[deg] port:height[cm]',
            'open',
            `move ${Math.round(deg(-90) * 1e4) / 1e4} 0.025`,
            'move keep 0.02 (constant bottom)',
        ]);
        expect(feedersOfBody(r).map((f) => `${f.$type}:${f.name}`)).toEqual(['Port:angle', 'Port:height']);
    });

    test('ill-formed moves are left out', async () => {
        const {
            docs: [doc],
        } = await build({ 'R.ra': 'robotarm R {\n  input int a;\n  program P { move a; move 10cm 10cm; open; }\n}' });
        const r = (doc!.parseResult.value as RobotArmModel).robot!;
        expect(programSteps(programsOf(r)[0]!).map(show)).toEqual(['open']);
    });
});

describe('the port protocol', () => {
    test('command constants name programs; the command table maps each constant', async () => {
        expect(commandConstantName('PickupAndDeploy')).toBe('PICKUP_AND_DEPLOY');
        expect(commandConstantName('Fetch')).toBe('FETCH');
        expect(commandConstantName('Fetch2Toast')).toBe('FETCH2_TOAST');
        expect(commandConstantName('HTTPGet')).toBe('HTTP_GET');
        const { docs } = await build({ 'ArmTypes.cd': ARM_TYPES, 'ArmController.arc': LISTING_2 });
        const r = AstUtils.streamAst(docs[1]!.parseResult.value).find((n): n is RobotArm => n.$type === 'RobotArm')!;
        const { cmd, status } = protocolPorts(r);
        expect([cmd?.name, cmd?.direction, status?.name, status?.direction]).toEqual(['cmd', 'in', 'status', 'out']);
        expect(commandTable(r).map((c) => `${c.constant}->${c.program?.name ?? '-'}`)).toEqual([
            'NONE->-',
            'PICKUP_AND_DEPLOY->PickupAndDeploy',
        ]);
        expect(programForCommand(r, 'PickupAndDeploy')?.name).toBe('PickupAndDeploy');
        expect(programForCommand(r, 'FETCH')).toBeUndefined();
    });
});
