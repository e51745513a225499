import { describe, expect, it } from 'vitest';
import { integralSquaredError, overshootPercent, previewObjective, termVariables, timeAverage } from './objectivePreview';
import { emptyTerm } from './studyForm';
import type { ResultsJson } from '../protocol/types';

const result: ResultsJson = {
    time: [0, 1, 2, 3],
    variables: [
        { name: 'Pos#out#Value', unit: '', data: [0, 1.2, 1.0, 1.0] },
        { name: 'Ref#out#Value', unit: '', data: [1, 1, 1, 1] },
    ],
};

describe('the objective on the latest run (as the server evaluates it)', () => {
    it('overshoot is the per cent past the final value, relative to the change', () => {
        expect(overshootPercent([0, 1.2, 1, 1])).toBeCloseTo(20);
        expect(overshootPercent([1, 0.5, 0.8])).toBeCloseTo(100 * 0.3 / 0.2);
        expect(overshootPercent([2, 2])).toBe(0);
    });

    it('the time average and the ISE use the trapezoidal rule', () => {
        expect(timeAverage([0, 1, 2], [0, 2, 2])).toBeCloseTo(1.5);
        expect(timeAverage([0], [4])).toBe(4);
        expect(integralSquaredError([0, 1, 2, 3], [0, 1.2, 1, 1], [1, 1, 1, 1])).toBeCloseTo(0.5 * (1 + 0.04) + 0.5 * 0.04);
    });

    it('sums the weighted terms; a target makes a term the squared distance to it', () => {
        const preview = previewObjective([
            { ...emptyTerm('Pos#out#Value'), weight: '0.5' },
            { fn: 'max', variable: 'Pos#out#Value', reference: '', target: '1', weight: '10' },
            { fn: 'ise', variable: 'Pos#out#Value', reference: 'Ref#out#Value', target: '', weight: '1' },
        ], result);
        expect(preview.ok).toBe(true);
        if (!preview.ok) return;
        expect(preview.terms[0]).toBeCloseTo(10);
        expect(preview.terms[1]).toBeCloseTo(0.4);
        expect(preview.value).toBeCloseTo(10 + 0.4 + 0.54);
    });

    it('says which variable the run lacks', () => {
        expect(previewObjective([emptyTerm('Nope#out#Value')], result)).toEqual({ ok: false, reason: 'the latest run has no variable Nope#out#Value' });
        expect(previewObjective([], result)).toEqual({ ok: false, reason: 'no terms' });
    });

    it('fetches each variable the terms read once', () => {
        expect(termVariables([emptyTerm('A'), { fn: 'ise', variable: 'A', reference: 'B', target: '', weight: '1' }])).toEqual(['A', 'B']);
    });
});
