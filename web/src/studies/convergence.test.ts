import { describe, expect, it } from 'vitest';
import { convergenceSeries, inferGoal } from './convergence';
import type { StudyTable } from './studyTypes';

const table: StudyTable = {
    columns: ['run', 'ok', 'GainP.k', 'objective'],
    // out of order, as progress events may join them; run 2 failed
    rows: [[1, 1, 0.04, 29.9], [0, 1, 0.027, 14.5], [2, 0, 0.03, null], [3, 1, 0.024, 14.7], [4, 1, 0.001, 0.00044]],
    errors: {},
};

describe('an optimisation\'s convergence', () => {
    it('minimise: the best so far only falls, and a failed run carries it on', () => {
        expect(convergenceSeries(table, 'minimise')).toEqual({
            runs: [0, 1, 2, 3, 4],
            objective: [14.5, 29.9, null, 14.7, 0.00044],
            best: [14.5, 14.5, 14.5, 14.5, 0.00044],
        });
    });

    it('maximise: the best so far only rises', () => {
        expect(convergenceSeries(table, 'maximise')!.best).toEqual([14.5, 29.9, 29.9, 29.9, 29.9]);
    });

    it('is null without an objective column', () => {
        expect(convergenceSeries({ columns: ['run', 'ok', 'A'], rows: [], errors: {} }, 'minimise')).toBeNull();
    });

    it('infers the goal of a listed study from its best objective', () => {
        expect(inferGoal(table, 0.00044)).toBe('minimise');
        expect(inferGoal(table, 29.9)).toBe('maximise');
        expect(inferGoal(table, undefined)).toBe('minimise');
    });
});
