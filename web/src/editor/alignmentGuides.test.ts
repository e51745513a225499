import { describe, expect, it } from 'vitest';
import { snapToAlignment } from './alignmentGuides';

describe('alignment guides', () => {
    const others = [{ x: 100, y: 200 }, { x: 300, y: 80 }, { x: 100, y: 400 }];

    it('snaps a drag that brings the centre within reach of another centre line, with a guide along it', () => {
        const snap = snapToAlignment({ x: 0, y: 0 }, { x: 97, y: 150 }, others, 6);
        expect(snap.offset).toEqual({ x: 100, y: 150 });
        // the guide runs past every centre on the line x = 100 and the dragged one
        expect(snap.guides).toEqual([{ axis: 'x', at: 100, from: 150, to: 400 }]);
    });

    it('snaps on both axes at once, to the nearest line', () => {
        const snap = snapToAlignment({ x: 10, y: 10 }, { x: 284, y: 73 }, [...others, { x: 298, y: 0 }], 6);
        expect(snap.offset).toEqual({ x: 288, y: 70 });   // x = 298 is nearer than x = 300
        expect(snap.guides.map((g) => g.axis)).toEqual(['x', 'y']);
    });

    it('leaves a drag out of reach alone', () => {
        expect(snapToAlignment({ x: 0, y: 0 }, { x: 50, y: 50 }, others, 6)).toEqual({ offset: { x: 50, y: 50 }, guides: [] });
    });
});
