// Names of the variants of a component type (instances of one type in different feature
// configurations; buildArchitecture). The generated code of the variants runs in
// @maa/generators-python test/variability.test.ts and test/ros2/test_ros2_variability.py.
import { describe, expect, it } from 'vitest';
import { variantName } from '../src/model/architecture.js';

const none = (): boolean => false;

describe('variantName', () => {
    it('names the selected features, sorted', () => {
        expect(variantName('Lamp', { dimmable: true }, 1, none)).toBe('Lamp__dimmable');
        expect(variantName('Room', { eco: true, dim: true, fast: false }, 1, none)).toBe('Room__dim_eco');
    });

    it('names all features with no_ when none is selected', () => {
        expect(variantName('Lamp', { dimmable: false }, 1, none)).toBe('Lamp__no_dimmable');
        expect(variantName('Room', { eco: false, dim: false }, 2, none)).toBe('Room__no_dim_eco');
    });

    it("numbers a variant without features by its position among the type's variants", () => {
        expect(variantName('Wing', undefined, 1, none)).toBe('Wing__2');
        expect(variantName('Wing', {}, 2, none)).toBe('Wing__3');
    });

    it('appends _2, _3, ... to a name that is taken', () => {
        const taken = new Set(['Lamp__dimmable', 'Lamp__dimmable_2']);
        expect(variantName('Lamp', { dimmable: true }, 1, (n) => taken.has(n))).toBe('Lamp__dimmable_3');
    });
});
