import { describe, expect, it } from 'vitest';
import { alignSeries } from './OverlayPlot';

describe('overlay alignment', () => {
    it('puts every run on the union of their times, null where a run has no sample', () => {
        const data = alignSeries([
            { student: { id: 1, username: 'a' }, job_id: 1, time: [0, 0.5, 1], values: [0, 1, 2] },
            { student: { id: 2, username: 'b' }, job_id: 2, time: [0, 1, 2], values: [5, 6, 7] },
        ]);
        expect(data).toEqual([[0, 0.5, 1, 2], [0, 1, 2, null], [5, null, 6, 7]]);
    });
    it('is empty for no runs', () => {
        expect(alignSeries([])).toEqual([[]]);
    });
});
