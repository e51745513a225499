// Where a port sits in the scene, from Hopsan's layout facts (appearance.md, "Coordinates"):
// the port's fractions of the icon box, the box centred on the pose, rotated clockwise by the
// pose's angle and then, if flipped, mirrored left-right about the centre.
import type { Pose } from '../protocol/types';

export interface Point { x: number; y: number }

/** `port` as fractions (0..1) of the box `width` x `height`. */
export function portScenePoint(pose: Pose, width: number, height: number, port: Point): Point {
    const dx = (port.x - 0.5) * width;
    const dy = (port.y - 0.5) * height;
    const a = (pose.angle * Math.PI) / 180;
    let rx = dx * Math.cos(a) - dy * Math.sin(a);
    const ry = dx * Math.sin(a) + dy * Math.cos(a);
    if (pose.flipped) rx = -rx;
    return { x: pose.x + rx, y: pose.y + ry };
}
