import { describe, expect, it } from 'vitest';
import { PressureRange, runPressureRange, scaleColour, SCALE_STOPS } from './pressureScale';

const hex = (rgb: number[]) => `#${rgb.map((c) => c.toString(16).padStart(2, '0')).join('')}`;

describe('pressure scale', () => {
    it('maps the low end to blue, the high end to red and the middle to the middle stop', () => {
        expect(scaleColour(0)).toBe(hex(SCALE_STOPS[0]));
        expect(scaleColour(1)).toBe(hex(SCALE_STOPS[4]));
        expect(scaleColour(0.5)).toBe(hex(SCALE_STOPS[2]));
        expect(scaleColour(-3)).toBe(scaleColour(0));
        expect(scaleColour(Number.NaN)).toBe(scaleColour(0));
    });

    it('an automatic range widens to the pressures seen, from 0', () => {
        const r = new PressureRange();
        r.see(5e6);
        r.see(2e7);
        r.see(1e6);
        expect([r.min, r.max]).toEqual([0, 2e7]);
        expect(r.colour(2e7)).toBe(scaleColour(1));
        expect(r.colour(1e7)).toBe(scaleColour(0.5));
    });

    it('a range the user fixed stays as set', () => {
        const r = new PressureRange();
        r.set(1e6, 1e5);
        r.see(5e7);
        expect([r.min, r.max, r.auto]).toEqual([1e5, 1e6, false]);
        expect(r.colour(5e7)).toBe(scaleColour(1));
    });

    it("a run's range spans 0 to its highest pressure but for a brief peak", () => {
        const line = Array.from({ length: 1000 }, (_, i) => (i < 5 ? 9e7 : 1e7 + i));
        const [low, high] = runPressureRange([line, [1e5, 2e5]]);
        expect(low).toBe(0);
        expect(high).toBeGreaterThan(1e7);
        expect(high).toBeLessThan(1e7 + 1000);
        expect(runPressureRange([])).toEqual([0, 0]);
    });
});
