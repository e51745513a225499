import { describe, expect, it } from 'vitest';
import { advance, changeMarks, samplePlace, stepOfTime, timeOfStep, valueAt, valuesAt } from './timeline';

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

    it("marks a recorded session's changes where they fall in the run, leaving out those outside it", () => {
        const changes = [{ time: 0.5, name: 'Step.y_A', value: 0.3 }, { time: 2, name: 'Gain.k', value: 4 }, { time: 9, name: 'Step.y_A', value: 1 }];
        expect(changeMarks(changes, 0, 4)).toEqual([
            { at: 0.125, time: 0.5, label: 'Step.y_A = 0.3 at 0.500 s' },
            { at: 0.5, time: 2, label: 'Gain.k = 4 at 2.000 s' },
        ]);
        expect(changeMarks(changes, 1, 1)).toEqual([]);
    });
});
