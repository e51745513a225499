// Where a component's name goes: upright and centred above its body, as Hopsan puts it by
// default, so the name never covers the component's own icon.
import type { ComponentLayout, Point } from '../model/geometry';
import type { Pose } from '../protocol/types';

/** Gap between the body's top edge and the text's baseline (px, at 10 px text). */
export const LABEL_GAP = 4;

/** Baseline point of the name (text-anchor middle) of a component with `layout` at `pose`. */
export function labelPlacement(pose: Pose, layout: Pick<ComponentLayout, 'halfWidth' | 'halfHeight'>): Point {
    const a = (pose.angle * Math.PI) / 180;
    // the rotated box's half height on screen
    const halfUp = Math.abs(layout.halfWidth * Math.sin(a)) + Math.abs(layout.halfHeight * Math.cos(a));
    return { x: pose.x, y: pose.y - halfUp - LABEL_GAP };
}
