// Where a component's name goes: upright and centred above its body, as Hopsan puts it by
// default, so the name never covers the component's own icon. Where that spot would cover a
// name already placed or another body, the name tries below, then left, then right.
import type { ComponentLayout, Point } from '../model/geometry';
import type { Pose } from '../protocol/types';

/** Gap between the body's edge and the text (px, at 10 px text). */
export const LABEL_GAP = 4;
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
    if (side === 'left') return spot(body.x0 - LABEL_GAP, midline, 'end');
    return spot(body.x1 + LABEL_GAP, midline, 'start');
}

export function overlaps(a: Box, b: Box): boolean {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/**
 * Every component's name, in drawing order: the first side whose box covers no name placed
 * before and no other body; above when every side does.
 */
export function placeLabels(items: Labelled[]): Map<string, LabelSpot> {
    const bodies = items.map((item) => bodyBox(item.pose, item.layout));
    const placed: Box[] = [];
    const spots = new Map<string, LabelSpot>();
    items.forEach((item, i) => {
        const free = (spot: LabelSpot) => !placed.some((b) => overlaps(spot.box, b))
            && !bodies.some((b, j) => j !== i && overlaps(spot.box, b));
        const candidates = SIDES.map((side) => labelAt(side, bodies[i], item.name));
        const spot = candidates.find(free) ?? candidates[0];
        placed.push(spot.box);
        spots.set(item.name, spot);
    });
    return spots;
}
