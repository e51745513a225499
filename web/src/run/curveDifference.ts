// The difference of one variable between two runs (Hopsan's "subtract generations"): A − B on
// A's time points. Runs with other step sizes log at other times: B is then interpolated
// linearly between its two samples around each of A's times.
import type { SeriesSource } from './RunData';

/**
 * A − B at A's times within B's time span (B says nothing beyond it: those times are left out).
 * Both time vectors increase; a column still filling up during a run counts as far as it goes.
 */
export function curveDifference(a: SeriesSource, b: SeriesSource): SeriesSource {
    const aLength = Math.min(a.time.length, a.data.length);
    const bLength = Math.min(b.time.length, b.data.length);
    const time: number[] = [];
    const data: number[] = [];
    if (bLength === 0) return { time, data };
    const first = b.time[0];
    const last = b.time[bLength - 1];
    // j walks along B as A's times increase: the whole is linear in the two lengths
    let j = 0;
    for (let i = 0; i < aLength; ++i) {
        const t = a.time[i];
        if (t < first || t > last) continue;
        while (j + 1 < bLength - 1 && b.time[j + 1] <= t) ++j;
        time.push(t);
        data.push(a.data[i] - interpolated(b, j, Math.min(j + 1, bLength - 1), t));
    }
    return { time, data };
}

/** B's value at `t` on the line through its samples `j` and `k` (the sample itself when they coincide). */
function interpolated(b: SeriesSource, j: number, k: number, t: number): number {
    const t0 = b.time[j];
    const t1 = b.time[k];
    if (t === t0 || t1 === t0) return b.data[j];
    if (t === t1) return b.data[k];
    return b.data[j] + ((b.data[k] - b.data[j]) * (t - t0)) / (t1 - t0);
}
