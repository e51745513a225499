// Where a component's name goes: upright and centred above its body, as Hopsan puts it by
// default, so the name never covers the component's own icon. Where that spot would cover a
// name already placed or another body, the name tries below, then left, then right; among the
// sides that are free of those, the one crossed by the fewest connection lines wins.
import type { ComponentLayout, Point } from '../model/geometry';
import type { Pose } from '../protocol/types';

/** Gap between the body's edge and the text (px, at 10 px text). */
export const LABEL_GAP = 4;
/** More of a gap beside the body: the port marks on its left and right edges stick out 4.5 px. */
export const SIDE_GAP = LABEL_GAP + 4;
// 10 px sans-serif: the text's extent around its baseline and a typical character width
const ASCENT = 8;
const DESCENT = 2;
const CHAR_WIDTH = 5.5;

export type LabelSide = 'above' | 'below' | 'left' | 'right';
const SIDES: LabelSide[] = ['above', 'below', 'left', 'right'];

export interface Box { x0: number; y0: number; x1: number; y1: number }

/** A name's baseline point, how the text hangs from it, and the box it covers. */
export interface LabelSpot extends Point { anchor: 'middle' | 'start' | 'end'; side: LabelSide; box: Box }

export interface Labelled { name: string; pose: Pose; layout: Pick<ComponentLayout, 'halfWidth' | 'halfHeight'> }

/** The scene box of a component's body (its rotated icon box). */
export function bodyBox(pose: Pose, layout: Labelled['layout']): Box {
    const a = (pose.angle * Math.PI) / 180;
    const [c, s] = [Math.abs(Math.cos(a)), Math.abs(Math.sin(a))];
    const halfX = layout.halfWidth * c + layout.halfHeight * s;
    const halfY = layout.halfWidth * s + layout.halfHeight * c;
    return { x0: pose.x - halfX, y0: pose.y - halfY, x1: pose.x + halfX, y1: pose.y + halfY };
}

/** The name of a component with this body box at one side of it. */
export function labelAt(side: LabelSide, body: Box, name: string): LabelSpot {
    const width = name.length * CHAR_WIDTH;
    const cx = (body.x0 + body.x1) / 2;
    const midline = (body.y0 + body.y1) / 2 + (ASCENT - DESCENT) / 2;
    const spot = (x: number, y: number, anchor: LabelSpot['anchor']): LabelSpot => {
        const x0 = anchor === 'middle' ? x - width / 2 : anchor === 'start' ? x : x - width;
        return { x, y, anchor, side, box: { x0, y0: y - ASCENT, x1: x0 + width, y1: y + DESCENT } };
    };
    if (side === 'above') return spot(cx, body.y0 - LABEL_GAP - DESCENT, 'middle');
    if (side === 'below') return spot(cx, body.y1 + LABEL_GAP + ASCENT, 'middle');
    if (side === 'left') return spot(body.x0 - SIDE_GAP, midline, 'end');
    return spot(body.x1 + SIDE_GAP, midline, 'start');
}

export function overlaps(a: Box, b: Box): boolean {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/** A connection line as drawn: its points in scene coordinates. */
export type Polyline = readonly Point[];

/** A line's segments with the box around all of them (to skip far lines at once). */
interface IndexedLine { bounds: Box; points: Polyline }

function indexLine(points: Polyline): IndexedLine {
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const p of points) {
        if (p.x < x0) x0 = p.x;
        if (p.x > x1) x1 = p.x;
        if (p.y < y0) y0 = p.y;
        if (p.y > y1) y1 = p.y;
    }
    return { bounds: { x0, y0, x1, y1 }, points };
}

/**
 * Whether the segment a-b passes through the inside of `box` (touching its edge is not
 * crossing): its own bounding box first, then the segment clipped to the box (Liang-Barsky).
 */
export function segmentCrosses(a: Point, b: Point, box: Box): boolean {
    if (Math.max(a.x, b.x) <= box.x0 || Math.min(a.x, b.x) >= box.x1 || Math.max(a.y, b.y) <= box.y0 || Math.min(a.y, b.y) >= box.y1) return false;
    // horizontal and vertical segments, most of Hopsan's lines: the box test was exact
    if (a.x === b.x || a.y === b.y) return true;
    const [dx, dy] = [b.x - a.x, b.y - a.y];
    let [t0, t1] = [0, 1];
    for (const [p, q] of [[-dx, a.x - box.x0], [dx, box.x1 - a.x], [-dy, a.y - box.y0], [dy, box.y1 - a.y]]) {
        const t = q / p;
        if (p < 0) { if (t > t0) t0 = t; } else if (t < t1) t1 = t;
        if (t0 >= t1) return false;
    }
    return true;
}

/** How many of `lines` pass through `box`. */
function crossings(box: Box, lines: IndexedLine[]): number {
    let n = 0;
    for (const line of lines) {
        const r = line.bounds;
        if (r.x1 <= box.x0 || r.x0 >= box.x1 || r.y1 <= box.y0 || r.y0 >= box.y1) continue;
        const pts = line.points;
        for (let k = 1; k < pts.length; k++) {
            if (segmentCrosses(pts[k - 1], pts[k], box)) { n++; break; }
        }
    }
    return n;
}

/**
 * Every component's name, in drawing order: of the sides whose box covers no name placed
 * before and no other body, the one crossed by the fewest `lines` (the first in the order
 * above, below, left, right on a tie); above when every side covers a name or a body.
 */
export function placeLabels(items: Labelled[], lines: Polyline[] = []): Map<string, LabelSpot> {
    const bodies = items.map((item) => bodyBox(item.pose, item.layout));
    const indexed = lines.filter((l) => l.length >= 2).map(indexLine);
    const placed: Box[] = [];
    const spots = new Map<string, LabelSpot>();
    items.forEach((item, i) => {
        const free = (spot: LabelSpot) => !placed.some((b) => overlaps(spot.box, b))
            && !bodies.some((b, j) => j !== i && overlaps(spot.box, b));
        const candidates = SIDES.map((side) => labelAt(side, bodies[i], item.name));
        let spot: LabelSpot | undefined;
        let fewest = Infinity;
        for (const candidate of candidates) {
            if (!free(candidate)) continue;
            const n = crossings(candidate.box, indexed);
            if (n < fewest) [spot, fewest] = [candidate, n];
            if (n === 0) break;
        }
        spot ??= candidates[0];
        placed.push(spot.box);
        spots.set(item.name, spot);
    });
    return spots;
}
