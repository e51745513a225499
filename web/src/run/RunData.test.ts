import { describe, expect, it } from 'vitest';
import { alignSeries, RunData, toCsv } from './RunData';
import type { FrameEvent } from '../protocol/types';

const frame = (seq: number, time: number[], values: number[], dropped = 0, job = 1): FrameEvent => ({
    type: 'event.frame', job_id: job, seq, time, variables: { 'A#out#Value': values }, dropped,
});

describe('RunData', () => {
    it('concatenates frames in order', () => {
        const run = new RunData(1, ['A#out#Value']);
        run.addFrame(frame(0, [0, 0.1], [1, 2]));
        run.addFrame(frame(1, [0.2], [3]));
        expect(run.time).toEqual([0, 0.1, 0.2]);
        expect(run.columns.get('A#out#Value')).toEqual([1, 2, 3]);
        expect(run.gap).toBe(false);
    });

    it('ignores frames of other jobs', () => {
        const run = new RunData(1, []);
        run.addFrame(frame(0, [0], [1], 0, 2));
        expect(run.time).toEqual([]);
    });

    it('notes a gap when a frame is skipped, not when frames were merged', () => {
        const a = new RunData(1, []);
        a.addFrame(frame(0, [0], [1], 2));
        expect(a.gap).toBe(false);
        expect(a.columns.get('A#out#Value')).toEqual([1]);
        const b = new RunData(1, []);
        b.addFrame(frame(0, [0], [1]));
        b.addFrame(frame(2, [1], [1]));
        expect(b.gap).toBe(true);
    });

    it('after a resync frames are ignored until the stored result replaces the columns', () => {
        const run = new RunData(1, []);
        run.addFrame(frame(0, [0], [1]));
        run.resync();
        run.addFrame(frame(1, [1], [2]));
        expect(run.columns.get('A#out#Value')).toEqual([1]);
        expect(run.gap).toBe(true);
    });

    it('stored results replace the streamed columns', () => {
        const run = new RunData(1, []);
        run.addFrame(frame(0, [0], [1], 1));
        run.setResults({ time: [0, 1], variables: [{ name: 'A#out#Value', unit: '', data: [5, 6] }] });
        expect(run.columns.get('A#out#Value')).toEqual([5, 6]);
        expect(run.gap).toBe(false);
    });
});

describe('alignSeries', () => {
    it('shares one time vector when the runs have the same times', () => {
        const t = [0, 1, 2];
        expect(alignSeries([{ time: t, data: [1, 2, 3] }, { time: [0, 1, 2], data: [4, 5] }])).toEqual([[0, 1, 2], [1, 2, 3], [4, 5, null]]);
    });

    it('merges different time vectors with nulls where a series has no sample', () => {
        const aligned = alignSeries([{ time: [0, 2], data: [1, 3] }, { time: [0, 1, 2], data: [7, 8, 9] }]);
        expect(aligned).toEqual([[0, 1, 2], [1, null, 3], [7, 8, 9]]);
    });

    it('writes CSV with a time column and empty cells for gaps', () => {
        expect(toCsv(['a', 'b'], [[0, 0.5], [1, null], [0.1, 2]])).toBe('time,a,b\n0,1,0.1\n0.5,,2\n');
    });
});
