// The live session as a run the plot windows draw: its frames appended as they come, shown
// over a window of the last `seconds` of model time that scrolls on (as Hopsan users expect
// of a live plot). Samples older than the window are dropped, in batches, so a long session
// holds only what is seen; "Keep as run" stores the whole session on the server.
import { RunData } from '../run/RunData';
import type { LiveFrameEvent } from '../protocol/types';

/** Scrolling windows offered, in seconds of model time. */
export const PLOT_WINDOWS = [2, 5, 10, 30, 60] as const;

export function liveRun(sessionId: number, variables: string[]): RunData {
    // a negative id: no job has it, so nothing asks the server for its results
    const run = new RunData(-sessionId, variables, 'live');
    run.state = 'running';
    return run;
}

/** Appends a frame's samples and scrolls the run's span to end at its latest time. */
export function appendLiveFrame(run: RunData, frame: LiveFrameEvent, seconds: number, start: number): void {
    for (const t of frame.time) run.time.push(t);
    for (const [name, values] of Object.entries(frame.variables)) {
        let column = run.columns.get(name);
        if (!column) {
            column = [];
            run.columns.set(name, column);
        }
        for (const v of values) column.push(v);
    }
    const end = run.time.at(-1) ?? start;
    run.span = [Math.max(start, end - seconds), Math.max(end, start + seconds)];
    dropOlderThan(run, end - 2 * seconds);
}

/** Drops the samples before `t` once they are half of the run (a copy per batch, not per frame). */
function dropOlderThan(run: RunData, t: number): void {
    let first = 0;
    while (first < run.time.length && run.time[first] < t) first++;
    if (first < run.time.length / 2) return;
    run.time.splice(0, first);
    for (const column of run.columns.values()) column.splice(0, first);
}
