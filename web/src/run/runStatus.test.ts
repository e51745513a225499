import { describe, expect, it } from 'vitest';
import { RunData } from './RunData';
import { runStatusText } from './runStatus';

function ended(state: RunData['state'], fields: Partial<Pick<RunData, 'error' | 'stopReason'>> = {}): RunData {
    const run = new RunData(12, []);
    run.state = state;
    Object.assign(run, fields);
    return run;
}

describe('runStatusText', () => {
    it('a run a component of the model ended reads as done, with its reason', () => {
        expect(runStatusText(ended('done', { stopReason: 'Simulation stopped by Stop_simulation' })))
            .toBe('Job 12: done — Simulation stopped by Stop_simulation');
        expect(runStatusText(ended('done'))).toBe('Job 12: done');
    });

    it('a failed run names its error', () => {
        expect(runStatusText(ended('failed', { error: 'step 512: pressure is not a number' })))
            .toBe('Job 12: failed — step 512: pressure is not a number');
    });

    it('a running run shows its progress', () => {
        const run = ended('running');
        run.progress = 0.424;
        expect(runStatusText(run)).toBe('Job 12: running 42%');
    });
});
