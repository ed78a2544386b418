import { expect, test } from 'vitest';
import { describeCatalog } from '@maa/language-adl/testing';
import { AUTOMATON_DIAGNOSTICS, AutomataLanguage, AutomatonCodes, ModeCodes } from '../src/index.js';
import { validate } from './helpers.js';

describeCatalog(AUTOMATON_DIAGNOSTICS, validate, { strict: true, codes: [...Object.values(AutomatonCodes), ...Object.values(ModeCodes)] });

test('the catalog is part of the registration, so docs/diagnostics.md includes it', () => {
    expect(AutomataLanguage.diagnostics).toBe(AUTOMATON_DIAGNOSTICS);
});
