// Which port a press or a drop means. The drawn markers overlap where ports sit close, and the
// topmost element is not the port the user aimed at: a power port wins over a signal port
// under the pointer, then the nearest one. A dragged connection only drops on a port of its own
// node type, so a neighbour of another type cannot take it.
import type { Point } from '../model/geometry';
import type { PortRef } from '../protocol/types';

export interface PortTarget {
    ref: PortRef;
    /** Scene position of the marker's centre. */
    at: Point;
    nodeType: string | null;
    power: boolean;
}

/** The port within `reach` of `pointer` to take, or null; `nodeType` limits it to a dragged connection's type. */
export function pickPort(targets: PortTarget[], pointer: Point, reach: number, nodeType?: string | null): PortRef | null {
    let best: { target: PortTarget; distance: number } | null = null;
    for (const target of targets) {
        // a port of no type yet (an unconnected system port) takes any
        if (nodeType !== undefined && target.nodeType !== null && target.nodeType !== nodeType) continue;
        const distance = Math.hypot(target.at.x - pointer.x, target.at.y - pointer.y);
        if (distance > reach) continue;
        const better = !best || (target.power !== best.target.power ? target.power : distance < best.distance);
        if (better) best = { target, distance };
    }
    return best?.target.ref ?? null;
}
