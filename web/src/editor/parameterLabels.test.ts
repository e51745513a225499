import { describe, expect, it } from 'vitest';
import { parameterLabel, shortName, splitParameters } from './parameterLabels';
import type { Param } from '../protocol/types';

const param = (name: string, description = '', unit = ''): Param => ({ name, value: '0', unit, description, type: 'double' });

describe('parameter labels', () => {
    const params = [param('y_A#Value', 'Amplitude'), param('f#Value', 'Frequency', 'Hz'), param('P1#HeatFlow', 'Heat flow', 'W'), param('P1#Pressure'), param('k')];

    it('separates the start values of port nodes from parameters', () => {
        const { parameters, startValues } = splitParameters(params);
        expect(parameters.map((p) => p.name)).toEqual(['y_A#Value', 'f#Value', 'k']);
        expect(startValues.map((p) => p.name)).toEqual(['P1#HeatFlow', 'P1#Pressure']);
    });

    it('labels by description and the short name, never "#Value"', () => {
        expect(parameterLabel(params[0])).toBe('Amplitude');
        expect(shortName(params[0])).toBe('y_A');
        expect(parameterLabel(params[4])).toBe('k');
        expect(parameterLabel(params[2])).toBe('P1: Heat flow');
        expect(parameterLabel(params[3])).toBe('P1: Pressure');
    });
});
