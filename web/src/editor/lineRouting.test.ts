import { describe, expect, it } from 'vitest';
import { addCorner, dragGrip, gripAt, removeCorner, routePoints, segmentDraggable } from './lineRouting';

// from a port at the left, over a vertical middle segment, to a port at the right (an elbow)
const elbow = [{ x: 0, y: 0 }, { x: 50, y: 0 }, { x: 50, y: 40 }, { x: 100, y: 40 }];

describe('reshaping a line', () => {
    it('takes hold of a corner near the press, else of a segment between corners, never of a segment on a port', () => {
        expect(gripAt(elbow, { x: 52, y: 2 }, 5)).toEqual({ kind: 'corner', index: 1 });
        expect(gripAt(elbow, { x: 51, y: 20 }, 5)).toEqual({ kind: 'segment', index: 1 });
        expect(gripAt(elbow, { x: 20, y: 1 }, 5)).toBeNull();
        expect(gripAt(elbow, { x: 80, y: 40 }, 5)).toBeNull();
        expect(segmentDraggable([{ x: 0, y: 0 }, { x: 10, y: 0 }], 0)).toBe(false);
    });

    it('moves a vertical segment sideways only and a horizontal one up and down only, keeping its neighbours square', () => {
        expect(dragGrip(elbow, { kind: 'segment', index: 1 }, { x: 12.4, y: 30 })).toEqual(
            [{ x: 0, y: 0 }, { x: 62, y: 0 }, { x: 62, y: 40 }, { x: 100, y: 40 }]);
        const zigzag = [{ x: 0, y: 0 }, { x: 20, y: 0 }, { x: 20, y: 30 }, { x: 60, y: 30 }, { x: 60, y: 50 }, { x: 90, y: 50 }];
        expect(dragGrip(zigzag, { kind: 'segment', index: 2 }, { x: 15, y: -10 })).toEqual(
            [{ x: 0, y: 0 }, { x: 20, y: 0 }, { x: 20, y: 20 }, { x: 60, y: 20 }, { x: 60, y: 50 }, { x: 90, y: 50 }]);
    });

    it('moves a corner anywhere, leaving the ends on their ports', () => {
        expect(dragGrip(elbow, { kind: 'corner', index: 2 }, { x: -10, y: 5 })).toEqual(
            [{ x: 0, y: 0 }, { x: 50, y: 0 }, { x: 40, y: 45 }, { x: 100, y: 40 }]);
    });

    it('adds a corner on the nearest segment where the press meets it, and removes a corner but never an end', () => {
        const added = addCorner(elbow, { x: 75, y: 43 });
        expect(added).toEqual([{ x: 0, y: 0 }, { x: 50, y: 0 }, { x: 50, y: 40 }, { x: 75, y: 40 }, { x: 100, y: 40 }]);
        expect(removeCorner(added, 3)).toEqual(elbow);
        expect(removeCorner(elbow, 0)).toEqual(elbow);
        expect(removeCorner(elbow, 3)).toEqual(elbow);
    });

    it('saves the path as points without repeats', () => {
        expect(routePoints([{ x: 0, y: 0 }, { x: 0, y: 0.2 }, { x: 30, y: 0 }, { x: 30, y: 0 }])).toEqual([[0, 0], [30, 0]]);
    });
});
