import { describe, expect, it } from 'vitest';
import { curveDifference } from './curveDifference';

/** Samples of f every `step` from `from` to `to` (inclusive). */
function sampled(f: (t: number) => number, from: number, to: number, step: number) {
    const time = Array.from({ length: Math.round((to - from) / step) + 1 }, (_, i) => from + i * step);
    return { time, data: time.map(f) };
}

describe('curveDifference', () => {
    it('on one time grid is A − B sample by sample, exactly', () => {
        const a = sampled(Math.sin, 0, 1, 0.01);
        const b = sampled((t) => Math.sin(t - 0.3), 0, 1, 0.01);
        const d = curveDifference(a, b);
        expect(d.time).toEqual(a.time);
        expect(d.data).toEqual(a.data.map((v, i) => v - b.data[i]));
    });

    it('interpolates B linearly onto A\'s times and leaves out the times B does not cover', () => {
        // sin(t) − sin(t − 0.1); B on a coarser grid over part of A's span. Linear interpolation
        // errs by at most step²/8 · max|sin''| = 0.0013²/8 ≈ 2.1e-7: 1e-6 is the tolerance.
        const a = sampled(Math.sin, 0, 2, 0.001);
        const b = sampled((t) => Math.sin(t - 0.1), 0.05, 1.5, 0.0013);
        const d = curveDifference(a, b);
        const last = b.time.at(-1)!;
        expect(d.time).toEqual(a.time.filter((t) => t >= 0.05 && t <= last));
        const worst = d.time.reduce((m, t, i) => Math.max(m, Math.abs(d.data[i] - (Math.sin(t) - Math.sin(t - 0.1)))), 0);
        expect(worst).toBeLessThan(1e-6);
        expect(worst).toBeGreaterThan(0);   // B was interpolated, not merely read
    });

    it('takes B\'s own samples where A\'s times meet them, ends included', () => {
        const a = { time: [0, 0.5, 1, 1.5, 2], data: [0, 0, 0, 0, 0] };
        const b = { time: [0, 1, 2], data: [1, 3, 7] };
        expect(curveDifference(a, b).data).toEqual([-1, -2, -3, -5, -7]);
    });

    it('counts a column still filling up as far as it goes, and gives nothing without B', () => {
        const a = { time: [0, 1, 2, 3], data: [5, 6, 7] };
        const b = { time: [0, 1, 2, 3], data: [1, 1] };
        expect(curveDifference(a, b)).toEqual({ time: [0, 1], data: [4, 5] });
        expect(curveDifference(a, { time: [], data: [] })).toEqual({ time: [], data: [] });
    });
});
