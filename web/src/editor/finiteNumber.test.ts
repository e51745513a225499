import { describe, expect, it } from 'vitest';
import { notFiniteError } from './finiteNumber';

describe('notFiniteError', () => {
    it('refuses a number that overflows and nan or inf spelled out, naming the parameter', () => {
        expect(notFiniteError('Mass.m', 'double', '1e400')).toBe("Mass.m: '1e400' is not a finite number");
        expect(notFiniteError('Mass.m', 'double', ' -1.5E+999 ')).toBe("Mass.m: '-1.5E+999' is not a finite number");
        for (const word of ['nan', 'NaN', 'inf', '-inf', '+Inf', 'infinity', '-Infinity']) {
            expect(notFiniteError('heavy', 'double', word)).toBe(`heavy: '${word}' is not a finite number`);
        }
        expect(notFiniteError('Gain.n', 'integer', '1e400')).toBe("Gain.n: '1e400' is not a finite number");
    });

    it('leaves finite numbers, expressions and system-parameter names to the server', () => {
        for (const text of ['1e300', '-0.5', '.5', '3.', '2*x', 'm_load', 'inflow', 'nan_value', '1/0', '']) {
            expect(notFiniteError('Mass.m', 'double', text)).toBeNull();
        }
    });

    it('leaves parameters that are not numbers alone', () => {
        expect(notFiniteError('Stop.message', 'string', 'inf')).toBeNull();
        expect(notFiniteError('Switch.on', 'bool', 'nan')).toBeNull();
    });
});
