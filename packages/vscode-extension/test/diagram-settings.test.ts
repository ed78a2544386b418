import { LANGUAGE_FACTS } from '@maa/language-server/language-facts';
import { describe, expect, it } from 'vitest';
import { contributions } from '../src/contributions.js';
import { openOnStart } from '../src/diagram/contributions.js';

describe('maa.diagram.openOnStart', () => {
    it('opens the diagram at start only when set to true', () => {
        expect(openOnStart((key) => (key === 'maa.diagram.openOnStart' ? true : undefined))).toBe(true);
        for (const value of [false, undefined, 'true', 1, null])
            expect(
                openOnStart(() => value),
                JSON.stringify(value),
            ).toBe(false);
    });

    it('is in the manifest with the default off (VS Code desktop opens no panel by itself)', () => {
        const config = contributions(LANGUAGE_FACTS).contributes['configuration'] as {
            properties: Record<string, { type: string; default: unknown }>;
        };
        expect(config.properties['maa.diagram.openOnStart']).toMatchObject({ type: 'boolean', default: false });
    });
});
