import { describe, expect, it } from 'vitest';
import { advance, samplePlace, stepOfTime, timeOfStep, valueAt, valuesAt } from './timeline';

describe('timeline', () => {
    const time = [0, 0.1, 0.2, 0.4];

    it('finds the samples around an instant and the share of the way between them', () => {
        expect(samplePlace(time, 0.1)).toEqual({ i: 1, w: 0 });
        const p = samplePlace(time, 0.3);
        expect(p.i).toBe(2);
        expect(p.w).toBeCloseTo(0.5);
        expect(samplePlace(time, -1)).toEqual({ i: 0, w: 0 });
        expect(samplePlace(time, 9)).toEqual({ i: 3, w: 0 });
        expect(samplePlace([], 1)).toEqual({ i: 0, w: 0 });
    });

    it('reads values between samples linearly; a column shorter than time has none past its end', () => {
        expect(valueAt([0, 10, 20, 40], samplePlace(time, 0.3))).toBeCloseTo(30);
        expect(valueAt([5], samplePlace(time, 0.3))).toBeUndefined();
        const into = new Map<string, number>([['stale', 1]]);
        valuesAt(time, new Map([['a#P#Position', [0, 1, 2, 4]], ['b#P#Pressure', [7, 7, 7, Number.NaN]]]), 0.4, into);
        expect([...into]).toEqual([['a#P#Position', 4]]);
    });

    it('maps slider steps to times and back', () => {
        expect(timeOfStep(0, 10, 1000, 500)).toBe(5);
        expect(timeOfStep(0, 10, 1000, 2000)).toBe(10);
        expect(stepOfTime(0, 10, 1000, 2.5)).toBe(250);
        expect(stepOfTime(0, 10, 1000, -3)).toBe(0);
        expect(stepOfTime(1, 1, 1000, 1)).toBe(0);
    });

    it('plays at the chosen speed and stops at the end', () => {
        expect(advance(1, 0.5, 0.1, 10).t).toBeCloseTo(1.05);
        expect(advance(1, 2, 10, 10)).toEqual({ t: 10, ended: true });
        expect(advance(1, -1, 1, 10)).toEqual({ t: 1, ended: false });
    });
});
