import { expect, test } from 'vitest';
import { describeCatalog } from '@maa/language-adl/testing';
import { ROBOTARM_DIAGNOSTICS, RobotArmCodes, RobotArmLanguage } from '../src/index.js';
import { validate } from './helpers.js';

describeCatalog(ROBOTARM_DIAGNOSTICS, validate, { strict: true, codes: Object.values(RobotArmCodes) });

test('the catalog is part of the registration, so docs/diagnostics.md includes it', () => {
    expect(RobotArmLanguage.diagnostics).toBe(ROBOTARM_DIAGNOSTICS);
});
