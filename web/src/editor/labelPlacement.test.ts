import { describe, expect, it } from 'vitest';
import { LABEL_GAP, labelPlacement } from './labelPlacement';

describe('component name placement', () => {
    const layout = { halfWidth: 80, halfHeight: 25 };
    it('sits above the body, upright, whatever the rotation', () => {
        expect(labelPlacement({ x: 0, y: 0, angle: 0, flipped: false }, layout)).toEqual({ x: 0, y: -25 - LABEL_GAP });
        const turned = labelPlacement({ x: 10, y: 20, angle: 90, flipped: true }, layout);
        expect(turned.x).toBe(10);
        expect(turned.y).toBeCloseTo(20 - 80 - LABEL_GAP, 9);
    });
});
