import { AstUtils, type AstNode, type LangiumDocument } from 'langium';
import { describe, expect, test } from 'vitest';
import type { ArcModel, MoveArgument, Port, RobotArmModel } from '../src/generated/ast.js';
import { allPorts } from '@maa/language-adl';
import { build, dump, services, validate } from './helpers.js';
import { ARM_TYPES, LISTING_1, LISTING_2 } from './fixtures.js';

function moveArguments(doc: LangiumDocument): MoveArgument[] {
    return AstUtils.streamAst(doc.parseResult.value)
        .filter((n): n is MoveArgument => n.$type === 'MoveArgument')
        .toArray();
}

function named(doc: LangiumDocument): string[] {
    return moveArguments(doc)
        .filter((a) => a.target)
        .map((a) => `${a.target!.$refText}:${a.target!.ref?.$type ?? 'unresolved'}`);
}

/** The names a reference's scope offers (what completion shows after `move`). */
function scopeNames(s: ReturnType<typeof services>['Arc'], node: AstNode): string[] {
    const reference = (node as MoveArgument).target!;
    return s.references.ScopeProvider.getScope({ container: node, property: 'target', reference })
        .getAllElements()
        .map((d) => d.name)
        .toArray();
}

describe('standalone .ra files', () => {
    test('move resolves to locations and inputs; constants are no references', async () => {
        const {
            docs: [doc],
        } = await build({ 'ToastService.ra': LISTING_1 });
        expect(named(doc!)).toEqual(['toaster:Location', 'angle:RobotArmInput', 'height:RobotArmInput']);
        expect(
            moveArguments(doc!)
                .filter((a) => a.constant)
                .map((a) => a.constant),
        ).toEqual(['top', 'top']);
    });

    test('the scope after move offers the locations, then the inputs', async () => {
        const {
            docs: [doc],
        } = await build({ 'ToastService.ra': LISTING_1 });
        const ra = services().languages.get('ra')!;
        expect(scopeNames(ra, moveArguments(doc!).find((a) => a.target)!)).toEqual(['toaster', 'angle', 'height']);
    });

    test('names do not leak between robot arms', async () => {
        const found = await validate({
            'A.ra': 'robotarm A {\n  location shelf 0deg 10cm;\n  program P { move shelf; }\n}',
            'B.ra': 'robotarm B {\n  program P { move shelf; }\n}',
        });
        expect(found.map((f) => `${f.file}:${f.code}@${f.text}`)).toEqual(['B.ra:robotarm/unresolved-name@shelf']);
    });

    test('find references of an input lists its moves (rename support)', async () => {
        const {
            docs: [doc],
        } = await build({ 'R.ra': 'robotarm R {\n  input int a;\n  input int h;\n  program P {\n    move a h;\n    move a 10cm;\n  }\n}' });
        const a = (doc!.parseResult.value as RobotArmModel).robot!.elements[0]!;
        const refs = services().languages.get('ra')!.references.References.findReferences(a, { includeDeclaration: false }).toArray();
        expect(refs.map((r) => r.segment.range.start.line + 1)).toEqual([5, 6]);
    });
});

describe('embedded blocks: names after move denote incoming ports (Port2InputAdapter)', () => {
    test("Listing 2: `move angle height` resolves to the component's port nodes", async () => {
        const { docs } = await build({ 'ArmTypes.cd': ARM_TYPES, 'ArmController.arc': LISTING_2 });
        const doc = docs[1]!;
        expect(named(doc)).toEqual(['toaster:Location', 'angle:Port', 'height:Port']);
        const component = (doc.parseResult.value as ArcModel).component!;
        const ports = allPorts(component as never);
        const [, angle, height] = moveArguments(doc).filter((a) => a.target);
        // Go to definition: the reference's target is the Port node of the .arc file itself.
        expect(angle!.target!.ref).toBe(ports.find((p) => p.name === 'angle')!.port);
        expect(height!.target!.ref).toBe(ports.find((p) => p.name === 'height')!.port);
        expect(AstUtils.getDocument(angle!.target!.ref!).uri.toString()).toBe(doc.uri.toString());
        const decl = services().Arc.references.References.findDeclarations(angle!.target!.$refNode!);
        expect(decl).toEqual([angle!.target!.ref]);
    });

    test('inherited incoming ports are visible; outgoing ports and inputs are not', async () => {
        const { docs } = await build({
            'Base.arc': 'component Base {\n  port in int angle;\n}',
            'Comp.arc':
                'component Comp extends Base {\n  port in double height, out int o;\n  robotarm {\n    input int i;\n    location home 0deg 10cm;\n    program P { move angle height; move o height; move i height; }\n  }\n}',
        });
        const doc = docs[1]!;
        expect(named(doc)).toEqual(['angle:Port', 'height:Port', 'o:unresolved', 'height:Port', 'i:unresolved', 'height:Port']);
        const inherited = moveArguments(doc).find((a) => a.target?.$refText === 'angle')!.target!.ref as Port;
        expect(AstUtils.getDocument(inherited).uri.path).toMatch(/Base\.arc$/);
        expect(scopeNames(services().Arc, moveArguments(doc).find((a) => a.target)!)).toEqual(['home', 'height', 'angle']);
    });

    test('find references of a port include its moves, so renaming the port updates the block', async () => {
        const {
            docs: [doc],
        } = await build({
            'Comp.arc':
                'component Comp {\n  port in int angle, in int height;\n  robotarm {\n    program P {\n      move angle height;\n      move angle 10cm;\n    }\n  }\n}',
        });
        const component = (doc!.parseResult.value as ArcModel).component!;
        const angle = allPorts(component as never).find((p) => p.name === 'angle')!.port;
        const refs = services().Arc.references.References.findReferences(angle, { includeDeclaration: false }).toArray();
        expect(refs.map((r) => `${r.segment.range.start.line + 1}:${r.segment.range.start.character + 1}`)).toEqual(['5:12', '6:12']);
    });

    test("names do not leak from one component's block into another", async () => {
        const found = await validate({
            'A.arc': 'component A {\n  port in int angle, in int height;\n  compute { }\n}',
            'B.arc': 'component B {\n  robotarm {\n    program P { move angle height; }\n  }\n}',
        });
        expect(
            found.filter((f) => f.code === 'robotarm/unresolved-name').map((f) => `${f.file}@${f.text}`),
            dump(found),
        ).toEqual(['B.arc@angle', 'B.arc@height']);
    });
});
