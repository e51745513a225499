// @vitest-environment jsdom
import { describe, expect, it } from 'vitest';
import { valveGlyph } from './valves';

const parts = (type: string, w = 80, h = 25) => {
    const g = valveGlyph(type, w, h);
    if (!g) throw new Error(`${type}: no valve glyph`);
    return g;
};
const count = (els: SVGElement[], cls: string) => els.filter((e) => e.getAttribute('class') === cls).length;

/** Every drawn coordinate of the symbol, to check it stays inside its box. */
function coordinates(els: SVGElement[]): [number, number][] {
    const out: [number, number][] = [];
    for (const e of els) {
        const pts = e.getAttribute('points');
        if (pts) for (const p of pts.trim().split(/\s+/)) out.push(p.split(',').map(Number) as [number, number]);
        if (e.tagName === 'rect') {
            const [x, y, wd, ht] = ['x', 'y', 'width', 'height'].map((k) => Number(e.getAttribute(k)));
            out.push([x, y], [x + wd, y + ht]);
        }
    }
    return out;
}

describe('valve symbols', () => {
    it('draws directional valves as one envelope per position, with flow arrows', () => {
        expect(count(parts('Hydraulic43Valve'), 'glyph-envelope')).toBe(3);
        expect(count(parts('Hydraulic43Valve'), 'glyph-block')).toBe(4);
        expect(count(parts('Hydraulic22Valve'), 'glyph-envelope')).toBe(2);
        expect(count(parts('Hydraulic42DirectionalValve'), 'glyph-arrow')).toBe(8);
    });

    it('gives pressure valves a spring and a dashed pilot line, check valves a ball on a seat', () => {
        const relief = parts('HydraulicPressureReliefValve');
        expect(count(relief, 'glyph-envelope')).toBe(1);
        expect(count(relief, 'glyph-spring')).toBe(1);
        expect(relief.find((e) => e.getAttribute('class') === 'glyph-pilot')!.getAttribute('stroke-dasharray')).toBeTruthy();
        const check = parts('HydraulicCheckValve');
        expect([count(check, 'glyph-ball'), count(check, 'glyph-seat'), count(check, 'glyph-pilot')]).toEqual([1, 1, 0]);
        expect(count(parts('HydraulicPilotControlledCheckValve'), 'glyph-pilot')).toBe(1);
        expect(count(parts('HydraulicCheckValvePreLoaded'), 'glyph-spring')).toBe(1);
    });

    it('stays inside the component box and leaves other types alone', () => {
        for (const type of ['Hydraulic43Valve', 'Hydraulic22Valve', 'HydraulicPressureReliefValve', 'HydraulicPilotControlledCheckValve']) {
            for (const [x, y] of coordinates(parts(type, 40, 15))) {
                expect(Math.abs(x), type).toBeLessThanOrEqual(40);
                expect(Math.abs(y), type).toBeLessThanOrEqual(15);
            }
        }
        expect(valveGlyph('HydraulicVolume', 40, 15)).toBeNull();
        expect(valveGlyph('HydraulicValvePlate', 40, 15)).toBeNull();
    });
});
