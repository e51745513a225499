import { describe, expect, it } from 'vitest';
import { axisUnits, siPrefix, unitOfVariable } from './units';

describe('units', () => {
    it('knows the unit of a variable when the node types agree', () => {
        expect(unitOfVariable('Piston#P1#Pressure')).toBe('Pa');
        expect(unitOfVariable('Mass#P1#Position')).toBe('m');
        expect(unitOfVariable('Gain#out#Value')).toBe('');
        // WaveVariable is Pa, N, Nm or V depending on the node: unknown from the name
        expect(unitOfVariable('Volume#P1#WaveVariable')).toBe('');
    });

    it('picks the SI prefix that puts the values between 1 and 1000', () => {
        expect(siPrefix(1.2e7, 'Pa')).toEqual({ factor: 1e6, unit: 'MPa' });
        expect(siPrefix(0.05, 'm')).toEqual({ factor: 1e-3, unit: 'mm' });
        expect(siPrefix(0.2, 'm/s')).toEqual({ factor: 1e-3, unit: 'mm/s' });
        expect(siPrefix(999, 'N')).toEqual({ factor: 1, unit: 'N' });
        expect(siPrefix(1000, 'N')).toEqual({ factor: 1e3, unit: 'kN' });
        // no prefix where it would be wrong or meaningless
        expect(siPrefix(1e-4, 'm^3/s')).toEqual({ factor: 1, unit: 'm^3/s' });
        expect(siPrefix(5000, '')).toEqual({ factor: 1, unit: '' });
        expect(siPrefix(0, 'Pa')).toEqual({ factor: 1, unit: 'Pa' });
    });

    it('one axis per unit in order of appearance', () => {
        expect(axisUnits(['Pa', 'm', 'Pa', ''])).toEqual(['Pa', 'm', '']);
    });
});
