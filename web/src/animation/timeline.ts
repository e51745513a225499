// Time and samples of a recorded run: which samples hold an instant (and how far between
// them), the values of every variable there, and how far playback moves in a span of wall time.

/** The instant `t` between samples `i` and `i + 1`: `w` is the share of the way to `i + 1` (0 … 1). */
export interface SamplePlace { i: number; w: number }

/** Where `t` falls in the sorted `time`; before the first sample: 0, after the last: the last. */
export function samplePlace(time: ArrayLike<number>, t: number): SamplePlace {
    const n = time.length;
    if (n === 0 || !(t > time[0])) return { i: 0, w: 0 };
    if (t >= time[n - 1]) return { i: n - 1, w: 0 };
    // the last sample at or before t
    let [lo, hi] = [0, n - 1];
    while (hi - lo > 1) {
        const mid = (lo + hi) >> 1;
        if (time[mid] <= t) lo = mid; else hi = mid;
    }
    const span = time[lo + 1] - time[lo];
    return { i: lo, w: span > 0 ? (t - time[lo]) / span : 0 };
}

/** The value of `column` at a place, linear between its samples; undefined past its end. */
export function valueAt(column: ArrayLike<number>, { i, w }: SamplePlace): number | undefined {
    if (i >= column.length) return undefined;
    if (w === 0 || i + 1 >= column.length) return column[i];
    return column[i] + (column[i + 1] - column[i]) * w;
}

/** Writes into `into` the value at time `t` of every column (the map is reused frame after frame). */
export function valuesAt(time: ArrayLike<number>, columns: ReadonlyMap<string, ArrayLike<number>>, t: number,
    into: Map<string, number>): Map<string, number> {
    const place = samplePlace(time, t);
    into.clear();
    for (const [name, column] of columns) {
        const v = valueAt(column, place);
        if (v !== undefined && Number.isFinite(v)) into.set(name, v);
    }
    return into;
}

/** The time on a slider of `steps` steps at `step`, and back. */
export function timeOfStep(start: number, end: number, steps: number, step: number): number {
    return steps > 0 ? start + ((end - start) * Math.max(0, Math.min(steps, step))) / steps : start;
}
export function stepOfTime(start: number, end: number, steps: number, t: number): number {
    return end > start ? Math.round((Math.max(start, Math.min(end, t)) - start) / (end - start) * steps) : 0;
}

/** Where playback is after `wall` seconds at `speed` (simulated seconds per second), stopping at `end`. */
export function advance(t: number, wall: number, speed: number, end: number): { t: number; ended: boolean } {
    const next = t + Math.max(0, wall) * speed;
    return next >= end ? { t: end, ended: true } : { t: next, ended: false };
}

/** A change made during a recorded live session, as the run's `live.changes` lists it. */
export interface RecordedChange { time: number; name: string; value: number }

/** A change's mark on the timeline: `at` the share of the way from start to end (0 … 1). */
export interface ChangeMark { at: number; time: number; label: string }

/** The marks of `changes` within a run from `start` to `end` (those outside it are left out). */
export function changeMarks(changes: readonly RecordedChange[], start: number, end: number): ChangeMark[] {
    if (!(end > start)) return [];
    return changes.filter((c) => c.time >= start && c.time <= end)
        .map((c) => ({ at: (c.time - start) / (end - start), time: c.time, label: `${c.name} = ${c.value} at ${c.time.toFixed(3)} s` }));
}
