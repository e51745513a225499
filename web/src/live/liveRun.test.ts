import { describe, expect, it } from 'vitest';
import { appendLiveFrame, liveRun } from './liveRun';
import type { LiveFrameEvent } from '../protocol/types';

const frame = (times: number[]): LiveFrameEvent => ({
    type: 'event.live.frame', session_id: 3, model_time: times.at(-1)!, wall_time: 0, seq: 0, dropped: 0,
    time: times, variables: { 'Mass#P1#x': times.map((t) => 2 * t) },
});

describe('the live run in the plots', () => {
    it('is a running run no job has, with every frame appended', () => {
        const run = liveRun(3, ['Mass#P1#x']);
        expect(run.jobId).toBeLessThan(0);
        expect(run.finished).toBe(false);
        appendLiveFrame(run, frame([0.1, 0.2]), 10, 0);
        appendLiveFrame(run, frame([0.3]), 10, 0);
        expect(run.time).toEqual([0.1, 0.2, 0.3]);
        expect(run.columns.get('Mass#P1#x')).toEqual([0.2, 0.4, 0.6]);
    });

    it('shows the window of the last seconds, scrolling once the session is past it', () => {
        const run = liveRun(3, ['Mass#P1#x']);
        appendLiveFrame(run, frame([1]), 10, 0);
        expect(run.span).toEqual([0, 10]);
        appendLiveFrame(run, frame([12]), 10, 0);
        expect(run.span).toEqual([2, 12]);
    });

    it('drops samples long out of the window, keeping the window whole', () => {
        const run = liveRun(3, ['Mass#P1#x']);
        for (let t = 0; t <= 50; t += 0.5) appendLiveFrame(run, frame([t]), 5, 0);
        expect(run.time[0]).toBeGreaterThan(30);
        expect(run.time[0]).toBeLessThanOrEqual(45);
        expect(run.time.at(-1)).toBe(50);
        expect(run.columns.get('Mass#P1#x')!.length).toBe(run.time.length);
    });
});
