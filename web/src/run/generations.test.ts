import { describe, expect, it } from 'vitest';
import { differencePair, generationText, MAX_GENERATIONS, shownRuns, stepGeneration, withGeneration } from './generations';

const runs = [7, 9, 12].map((jobId) => ({ jobId, label: `run ${jobId}` }));

describe('generations', () => {
    it('shows the newest run with the one before it unless the user stepped back', () => {
        expect(shownRuns(runs, null)).toEqual({ run: runs[2], before: runs[1] });
        expect(shownRuns(runs, 9)).toEqual({ run: runs[1], before: runs[0] });
        expect(shownRuns(runs, 7)).toEqual({ run: runs[0], before: null });
        expect(shownRuns([], null)).toEqual({ run: null, before: null });
    });

    it('a run that is no longer listed falls back to the newest', () => {
        expect(shownRuns(runs, 3).run).toBe(runs[2]);
    });

    it('steps back to the oldest and forward to the newest, and stops there', () => {
        expect(stepGeneration(runs, null, -1)).toBe(9);
        expect(stepGeneration(runs, 9, -1)).toBe(7);
        expect(stepGeneration(runs, 7, -1)).toBe(7);
        expect(stepGeneration(runs, 7, 1)).toBe(9);
        expect(stepGeneration(runs, null, 1)).toBeNull();
        expect(stepGeneration([], null, -1)).toBeNull();
    });

    it('stepping forward onto the newest run follows the runs that come after it', () => {
        const shown = stepGeneration(runs, 9, 1);
        expect(shown).toBeNull();
        const more = [...runs, { jobId: 15, label: 'run 15' }];
        expect(shownRuns(more, shown).run?.jobId).toBe(15);
    });

    it('names the shown run and its place among the runs', () => {
        expect(generationText(runs, null)).toBe('run 12 (3 of 3)');
        expect(generationText(runs, 7)).toBe('run 7 (1 of 3)');
        expect(generationText([], null)).toBe('');
    });

    it('a run loaded or chosen later takes its place in time, and the oldest others make room for it', () => {
        const chosen = { jobId: 3, label: 'run 3' };
        const joined = withGeneration(runs, chosen);
        expect(joined.map((r) => r.jobId)).toEqual([3, 7, 9, 12]);
        expect(generationText(joined, 3)).toBe('run 3 (1 of 4)');
        expect(stepGeneration(joined, 3, 1)).toBe(7);
        expect(withGeneration(joined, runs[1]).map((r) => r.jobId)).toEqual([3, 7, 9, 12]);

        const many = Array.from({ length: MAX_GENERATIONS }, (_, i) => ({ jobId: 10 + i, label: '' }));
        const full = withGeneration(many, chosen);
        expect(full).toHaveLength(MAX_GENERATIONS);
        expect(full.map((r) => r.jobId).slice(0, 2)).toEqual([3, 11]);
    });

    it('a difference sets the shown run against the one before it, the oldest against the one after it', () => {
        expect(differencePair(runs, null)).toEqual({ a: runs[2], b: runs[1] });
        expect(differencePair(runs, 9)).toEqual({ a: runs[1], b: runs[0] });
        expect(differencePair(runs, 7)).toEqual({ a: runs[0], b: runs[1] });
        expect(differencePair(runs.slice(0, 1), null)).toBeNull();
        expect(differencePair([], null)).toBeNull();
    });
});
