// The RobotArm language inside the language family of @maa/language-server (imported here, in a
// test only: this package's sources never depend on the family). The family composes its own
// grammar build from every registered language and creates a service container for `.ra` files.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { NodeFileSystem } from 'langium/node';
import { afterAll, describe, expect, test } from 'vitest';
import { behaviorLanguages, checkModelRoots, createMaaServices, familyDiagnostics } from '@maa/language-server';
import { LISTING_1, LISTING_2 } from './fixtures.js';

const dirs: string[] = [];
afterAll(() => {
    for (const d of dirs) rmSync(d, { recursive: true, force: true });
});

/** Writes a model root to a fresh temporary folder. */
function root(files: Record<string, string>): string {
    const dir = mkdtempSync(join(tmpdir(), 'maa-robotarm-'));
    dirs.push(dir);
    for (const [path, text] of Object.entries(files)) {
        mkdirSync(dirname(join(dir, path)), { recursive: true });
        writeFileSync(join(dir, path), text);
    }
    return dir;
}

const TYPES =
    'package toast.types;\n\nclassdiagram Types {\n  enum ArmCommand { NONE, PICKUP_AND_DEPLOY; }\n  enum ArmStatus { IDLE, BUSY, DONE; }\n}\n';
const ARM = `package toast;\n\nimport toast.types.*;\n\n${LISTING_2}\n`;
/** The arm controller as the composed robot uses it: its status feeds a sync automaton. */
const SYNC_ARM = ARM.replace('out ArmStatus status', '<<sync>> out ArmStatus status');
const RA = `package toast;\n\n${LISTING_1}\n`;

/** A controller automaton and the arm controller, composed: both behavior languages in one model root. */
const CONTROLLER = `package toast;

import toast.types.*;

component Controller {
  port in int distance, in ArmStatus armStatus, <<delayed>> out ArmCommand arm, <<delayed>> out int angle, <<delayed>> out int height;

  <<sync>> automaton {
    initial { arm = ArmCommand.NONE; angle = 0; height = 10; } state Idle;
    state Busy;
    Idle -> Busy [distance < 30] / { angle = 45; height = 12; arm = ArmCommand.PICKUP_AND_DEPLOY; };
    Busy -> Idle [armStatus == ArmStatus.DONE] / { arm = ArmCommand.NONE; };
  }
}
`;
const ROBOT = `package toast;

component Robot {
  port in int distance;

  Controller ctrl;
  ArmController armCtrl;

  distance -> ctrl.distance;
  ctrl.arm -> armCtrl.cmd;
  ctrl.angle -> armCtrl.angle;
  ctrl.height -> armCtrl.height;
  armCtrl.status -> ctrl.armStatus;
}
`;

describe('the language family', () => {
    test('registers the embedded block and the .ra language', () => {
        expect(behaviorLanguages()).toContain('robotarm');
        const services = createMaaServices(NodeFileSystem);
        const ra = services.languages.get('ra');
        expect(ra?.LanguageMetaData.fileExtensions).toEqual(['.ra']);
        expect(services.shared.ServiceRegistry.all.flatMap((s) => s.LanguageMetaData.fileExtensions)).toEqual(
            expect.arrayContaining(['.arc', '.cd', '.ra']),
        );
        expect(familyDiagnostics().map((c) => c.title)).toContain('RobotArm');
    });

    test('checkModelRoots checks a standalone .ra file and an embedded block together, without diagnostics', async () => {
        const dir = root({
            'toast/types/Types.cd': TYPES,
            'toast/ArmController.arc': SYNC_ARM,
            'toast/ToastService.ra': RA,
            'toast/Controller.arc': CONTROLLER,
            'toast/Robot.arc': ROBOT,
        });
        const found = await checkModelRoots([{ root: dir }]);
        expect(found.map((d) => `${d.file}:${d.line} ${d.code} ${d.message}`)).toEqual([]);
    });

    test('problems in both forms are reported with their codes, per file', async () => {
        const dir = root({
            'toast/types/Types.cd': TYPES,
            'toast/ArmController.arc': ARM.replace('robotarm {', 'robotarm {\n    input int speed;').replace(
                'move angle height',
                'move angle hight',
            ),
            'toast/ToastService.ra': RA.replace('move angle height', 'move angle 45cm')
                .replace('input int height;', 'input String height;\n  input String name;')
                .replace('move top; open;', 'move top; move name 10cm; open;'),
        });
        const found = await checkModelRoots([{ root: dir }]);
        const rel = (f: string): string => f.substring(dir.length + 1);
        expect(found.map((d) => `${rel(d.file)}:${d.line} ${d.severity} ${d.code}`)).toEqual([
            'toast/ArmController.arc:11 error robotarm/input-in-embedded',
            'toast/ArmController.arc:14 error robotarm/unresolved-name',
            'toast/ToastService.ra:9 error robotarm/move-not-numeric',
            'toast/ToastService.ra:9 error robotarm/joint-limit',
        ]);
    });

    test('a single .ra file is checked within its model root', async () => {
        const dir = root({ 'toast/ToastService.ra': RA.replace('120deg', '120') });
        const found = await checkModelRoots([{ root: dir, files: [join(dir, 'toast/ToastService.ra')] }]);
        expect(found.map((d) => `${d.code}:${d.line}:${d.column}`)).toEqual(['robotarm/invalid-unit:6:20']);
    });
});
