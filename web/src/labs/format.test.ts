import { describe, expect, it } from 'vitest';
import { formatNumber, formatScore, formatTime, fromDatetimeLocal, optionalNumber, toDatetimeLocal } from './format';

describe('lab formats', () => {
    it('writes numbers with four significant digits', () => {
        expect(formatNumber(0.123456)).toBe('0.1235');
        expect(formatNumber(2)).toBe('2');
        expect(formatNumber(1.5e-5)).toBe('1.500e-5');
        expect(formatNumber(null)).toBe('—');
        expect(formatScore(2, 3)).toBe('2 / 3');
        expect(formatScore(null, 3)).toBe('—');
        expect(formatTime(0)).toBe('—');
    });
    it('turns datetime-local values into unix seconds and back', () => {
        const unix = fromDatetimeLocal('2026-12-03T16:50')!;
        expect(toDatetimeLocal(unix)).toBe('2026-12-03T16:50');
        expect(fromDatetimeLocal('')).toBeUndefined();
        expect(toDatetimeLocal(0)).toBe('');
    });
    it('reads optional number fields', () => {
        expect(optionalNumber(' ')).toBeUndefined();
        expect(optionalNumber('1e2')).toBe(100);
        expect(optionalNumber('x')).toBeNaN();
    });
});
