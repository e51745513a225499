import { describe, expect, it } from 'vitest';
import { columnEnvelope } from './columnEnvelope';

/** A repeatable pseudo-random sequence in [0, 1). */
function random(seed: number): () => number {
    let s = seed;
    return () => {
        s = (s * 1103515245 + 12345) % 2147483648;
        return s / 2147483648;
    };
}

type Ys = (number | null)[];

/** Times (some repeated) and noisy values with some gaps, as aligned runs have. */
function curve(n: number, seed: number, gaps: number): { xs: number[]; ys: Ys } {
    const next = random(seed);
    const xs: number[] = [];
    const ys: Ys = [];
    let t = 0;
    for (let i = 0; i < n; ++i) {
        t += next() < 0.05 ? 0 : next();
        xs.push(t);
        ys.push(next() < gaps ? null : Math.sin(i / 50) * 10 + (next() - 0.5) * 4);
    }
    return { xs, ys };
}

/**
 * The lowest and highest point of the line through the samples `indices` (gaps skipped) in
 * each of `columns` columns over xMin … xMax, segments cut at the column edges.
 */
function drawnEnvelope(xs: number[], ys: Ys, indices: ArrayLike<number>, xMin: number, xMax: number, columns: number): [number, number][] {
    const width = (xMax - xMin) / columns;
    const envelope: [number, number][] = Array.from({ length: columns }, () => [Infinity, -Infinity]);
    const mark = (c: number, y: number) => {
        envelope[c][0] = Math.min(envelope[c][0], y);
        envelope[c][1] = Math.max(envelope[c][1], y);
    };
    const points = Array.from(indices).filter((i) => ys[i] !== null).map((i) => [xs[i], ys[i] as number]);
    for (let p = 0; p < points.length; ++p) {
        const [x0, y0] = points[p];
        if (x0 >= xMin && x0 < xMax) mark(Math.floor((x0 - xMin) / width), y0);
        if (p + 1 === points.length) continue;
        const [x1, y1] = points[p + 1];
        if (x1 === x0) continue;
        // where the segment crosses a column edge inside the range, both columns see it
        for (let c = 1; c < columns; ++c) {
            const edge = xMin + c * width;
            if (edge <= x0 || edge >= x1) continue;
            const y = y0 + (y1 - y0) * (edge - x0) / (x1 - x0);
            mark(c - 1, y);
            mark(c, y);
        }
    }
    return envelope;
}

const everyIndex = (from: number, to: number) => Array.from({ length: to - from + 1 }, (_, i) => from + i);

describe('columnEnvelope', () => {
    it('draws the same envelope as every sample, in each pixel column, from at most four samples a column', () => {
        for (const [seed, gaps] of [[1, 0], [2, 0.3], [5, 0.9]]) {
            const { xs, ys } = curve(20_000, seed, gaps);
            const columns = 300;
            // a zoomed-in view, with one sample beyond each side as the plot hands them over
            const xMin = xs[2000] + 0.3;
            const xMax = xs[15_000] + 0.6;
            const from = 2000;
            const to = 15_001;
            const kept = columnEnvelope(xs, ys.map((y) => y ?? NaN), from, to, xMin, xMax, columns);
            expect(kept.length).toBeLessThanOrEqual(4 * (columns + 2));
            expect(kept.length).toBeLessThan((to - from) / 8);
            for (let k = 1; k < kept.length; ++k) expect(kept[k]).toBeGreaterThan(kept[k - 1]);
            const original = drawnEnvelope(xs, ys, everyIndex(from, to), xMin, xMax, columns);
            const drawn = drawnEnvelope(xs, ys, kept, xMin, xMax, columns);
            drawn.forEach(([low, high], c) => {
                expect(low, `column ${c} lowest`).toBeCloseTo(original[c][0], 9);
                expect(high, `column ${c} highest`).toBeCloseTo(original[c][1], 9);
            });
        }
    });

    it('keeps every sample when there are few', () => {
        const xs = [0, 1, 2, 3];
        const ys = [1, 5, -2, 4];
        expect([...columnEnvelope(xs, ys, 0, 3, 0, 3, 100)]).toEqual([0, 1, 2, 3]);
    });

    it('skips gaps: a column of gaps only keeps nothing, the line joins the samples around it', () => {
        const xs = [0, 1, 2, 3, 4, 5];
        const ys = [1, NaN, NaN, NaN, 2, NaN];
        expect([...columnEnvelope(xs, ys, 0, 5, 0, 6, 6)]).toEqual([0, 4]);
    });
});
