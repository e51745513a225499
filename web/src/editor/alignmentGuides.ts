// Alignment guides while components are dragged: when the dragged component's centre comes
// within a few pixels of another object's centre line, across or down, the drag snaps onto it
// and a guide line is drawn along it, so that components line up (and their lines run straight)
// without a grid.
import type { Point } from '../model/geometry';

/** A guide: the vertical line x = at (or the horizontal y = at) from `from` to `to` across it. */
export interface Guide { axis: 'x' | 'y'; at: number; from: number; to: number }

export interface Snap {
    /** The drag's offset after snapping. */
    offset: Point;
    guides: Guide[];
}

/**
 * Snaps a drag that would put the dragged centre at `centre + offset` onto the nearest centre
 * of `others` within `tolerance` on each axis.
 */
export function snapToAlignment(centre: Point, offset: Point, others: Point[], tolerance: number): Snap {
    const at = { x: centre.x + offset.x, y: centre.y + offset.y };
    const nearest = (axis: 'x' | 'y') => {
        let best: number | null = null;
        for (const o of others) {
            const d = Math.abs(o[axis] - at[axis]);
            if (d <= tolerance && (best === null || d < Math.abs(best - at[axis]))) best = o[axis];
        }
        return best;
    };
    const x = nearest('x');
    const y = nearest('y');
    const snapped = { x: x ?? at.x, y: y ?? at.y };
    const guides: Guide[] = [];
    const span = (axis: 'x' | 'y', value: number): Guide => {
        const across = axis === 'x' ? 'y' : 'x';
        const on = others.filter((o) => Math.abs(o[axis] - value) < 0.5).map((o) => o[across]);
        return { axis, at: value, from: Math.min(snapped[across], ...on), to: Math.max(snapped[across], ...on) };
    };
    if (x !== null) guides.push(span('x', x));
    if (y !== null) guides.push(span('y', y));
    return { offset: { x: snapped.x - centre.x, y: snapped.y - centre.y }, guides };
}
