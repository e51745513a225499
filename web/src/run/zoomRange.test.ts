import { describe, expect, it } from 'vitest';
import { keepWithin, panBy, wheelFactor, zoomAbout } from './zoomRange';

describe('wheelFactor', () => {
    it('zooms in for a wheel turned away from the user and out towards, by the same step', () => {
        const inwards = wheelFactor(-100, 0, 800);
        expect(inwards).toBeLessThan(1);
        expect(wheelFactor(100, 0, 800)).toBeCloseTo(1 / inwards, 12);
        expect(wheelFactor(0, 0, 800)).toBe(1);
    });

    it('counts lines and pages as pixels, and a fast flick as a few notches at most', () => {
        expect(wheelFactor(3, 1, 800)).toBeCloseTo(wheelFactor(48, 0, 800), 12);
        expect(wheelFactor(1, 2, 400)).toBeCloseTo(wheelFactor(400, 0, 800), 12);
        expect(wheelFactor(100_000, 0, 800)).toBeCloseTo(wheelFactor(500, 0, 800), 12);
    });
});

describe('zoomAbout', () => {
    it('keeps the value under the pointer in its place', () => {
        const [min, max] = zoomAbout([0, 10], 2.5, 0.5);
        expect([min, max]).toEqual([1.25, 6.25]);
        expect((2.5 - min) / (max - min)).toBeCloseTo(0.25, 12);
    });

    it('zooms back out to where it began with the inverse factor', () => {
        const there = zoomAbout([2, 9], 3, 0.8);
        const back = zoomAbout(there, 3, 1 / 0.8);
        expect(back[0]).toBeCloseTo(2, 12);
        expect(back[1]).toBeCloseTo(9, 12);
    });
});

describe('panBy', () => {
    it('shifts both ends', () => {
        expect(panBy([1, 4], -0.5)).toEqual([0.5, 3.5]);
    });
});

describe('keepWithin', () => {
    it('leaves a range inside the run as it is', () => {
        expect(keepWithin([2, 5], [0, 10])).toEqual([2, 5]);
    });

    it('shifts a range that sticks out back inside, keeping its width', () => {
        expect(keepWithin([8, 12], [0, 10])).toEqual([6, 10]);
        expect(keepWithin([-3, 1], [0, 10])).toEqual([0, 4]);
    });

    it('is the whole run at most, and a millionth of it at least', () => {
        expect(keepWithin([-5, 20], [0, 10])).toEqual([0, 10]);
        const [min, max] = keepWithin([5, 5], [0, 10]);
        expect(max - min).toBeCloseTo(1e-5, 15);
        expect((min + max) / 2).toBeCloseTo(5, 12);
    });
});
