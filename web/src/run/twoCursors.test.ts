import { describe, expect, it } from 'vitest';
import { secondsText, valueAt } from './twoCursors';

describe('valueAt', () => {
    const xs = [0, 1, 2, 3, 4];

    it('is the sample at a sample time and a straight line between samples', () => {
        expect(valueAt(xs, [0, 10, 20, 30, 40], 2)).toBe(20);
        expect(valueAt(xs, [0, 10, 20, 30, 40], 2.25)).toBeCloseTo(22.5);
        expect(valueAt(xs, [5, 5, 8, 8, 8], 1.5)).toBeCloseTo(6.5);
    });

    it('steps over the gaps of a curve aligned with another run\'s times', () => {
        // samples at 0, 2 and 4 only
        expect(valueAt(xs, [0, null, 20, null, 40], 1)).toBeCloseTo(10);
        expect(valueAt(xs, [0, null, 20, null, 40], 3.5)).toBeCloseTo(35);
    });

    it('holds the first or last value outside the samples, and has none without samples', () => {
        expect(valueAt(xs, [null, 10, 20, null, null], 4)).toBe(20);
        expect(valueAt(xs, [null, 10, 20, null, null], 0)).toBe(10);
        expect(valueAt(xs, [null, null, null, null, null], 2)).toBeNull();
    });
});

describe('secondsText', () => {
    it('six significant digits', () => {
        expect(secondsText(1.23456789)).toBe('1.23457 s');
        expect(secondsText(40)).toBe('40 s');
    });
});
