// Where a port sits in the scene, from Hopsan's layout facts (appearance.md, "Coordinates"):
// the port's fractions of the icon box, the box centred on the pose, rotated clockwise by the
// pose's angle and then, if flipped, mirrored left-right about the centre.
import type { Pose } from '../protocol/types';
import { toScene, type Point } from './geometry';
import { localPortPoint } from './appearanceLayout';

export type { Point };

/** `port` as fractions (0..1) of the box `width` x `height`. */
export function portScenePoint(pose: Pose, width: number, height: number, port: Point): Point {
    return toScene(pose, localPortPoint(width, height, port));
}
