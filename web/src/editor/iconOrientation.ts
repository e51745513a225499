// Icons Hopsan keeps upright (iconRotation not ON: a Step's edge, a function's name, a gauge):
// the component's box and ports turn and flip with its pose, the graphic does not. The icon sits
// inside the posed body, so it gets the inverse of the pose's rotation and mirror; a quarter turn
// of a non-square box draws the graphic in the turned box, where the ports now are.
import type { Pose } from '../protocol/types';
import { keepsIconUpright } from '../model/appearance';
import { componentIcon } from './icons';

/** The transform that undoes a pose's rotation and mirror inside the posed body, or null. */
export function uprightTransform(pose: Pose): string | null {
    const angle = ((pose.angle % 360) + 360) % 360;
    if (angle === 0 && !pose.flipped) return null;
    // the body maps mirror·rotate(a); rotate(−a)·mirror cancels it
    return `rotate(${-angle})${pose.flipped ? ' scale(-1,1)' : ''}`;
}

const quarterTurned = (pose: Pose) => Math.abs(Math.round(pose.angle / 90)) % 2 === 1;

/**
 * Bring the icon of a posed component body (`.icon`, its first child of that class) to the
 * pose: upright types get a fresh icon in the box as it lies on screen, the others are left
 * to turn with the body.
 */
export function orientIcon(body: SVGGElement, type: string, pose: Pose, box: { halfWidth: number; halfHeight: number }): void {
    if (!keepsIconUpright(type)) return;
    const { halfWidth, halfHeight } = box;
    const old = body.querySelector(':scope > .icon');
    const turned = quarterTurned(pose);
    const transform = uprightTransform(pose);
    // moves change only the body's translation: keep the icon drawn for this orientation
    const key = `${turned} ${transform ?? ''}`;
    if (old?.getAttribute('data-orientation') === key) return;
    const icon = turned ? componentIcon(type, halfHeight, halfWidth) : componentIcon(type, halfWidth, halfHeight);
    icon.setAttribute('data-orientation', key);
    if (transform) icon.setAttribute('transform', transform);
    if (old) old.replaceWith(icon);
    else body.prepend(icon);
}
