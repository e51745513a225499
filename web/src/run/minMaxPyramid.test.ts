import { describe, expect, it } from 'vitest';
import { MinMaxPyramid } from './minMaxPyramid';

describe('MinMaxPyramid', () => {
    it('finds the smallest and largest value of any range, as walking it does', () => {
        let seed = 11;
        const next = () => (seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648;
        const ys = Array.from({ length: 1013 }, (_, i) => (next() < 0.2 ? null : Math.sin(i / 40) * 5 + next()));
        const pyramid = new MinMaxPyramid(ys);
        for (let trial = 0; trial < 500; ++trial) {
            const from = Math.floor(next() * ys.length);
            const to = Math.min(ys.length - 1, from + Math.floor(next() * 600));
            const values = ys.slice(from, to + 1).filter((y): y is number => y !== null);
            expect(pyramid.range(from, to)).toEqual(values.length ? [Math.min(...values), Math.max(...values)] : [Infinity, -Infinity]);
        }
    });

    it('leaves gaps out, and has nothing in a range of gaps only', () => {
        const pyramid = new MinMaxPyramid([3, null, NaN, undefined, -1, 7]);
        expect(pyramid.range(0, 5)).toEqual([-1, 7]);
        expect(pyramid.range(1, 3)).toEqual([Infinity, -Infinity]);
        expect(new MinMaxPyramid([]).range(0, -1)).toEqual([Infinity, -Infinity]);
    });
});
