// Where a new subsystem's system ports go inside it: on the side of its content that faces the
// outside component each port connects to, spread along that side so no two share a spot.
import type { Pose, System } from '../protocol/types';
import type { Point } from '../model/geometry';

type Side = 'left' | 'right' | 'top' | 'bottom';

/** How far outside the content's bounding box the ports sit, and their least spacing. */
const MARGIN = 80;
const SPACING = 60;

export interface PortTowards {
    /** The system port's name. */
    name: string;
    /** Where the outside end of its connection is, in the same frame as the content; none if unconnected. */
    towards: Point | undefined;
}

function sideTowards(centre: Point, towards: Point | undefined): Side {
    if (!towards) return 'left';
    const dx = towards.x - centre.x;
    const dy = towards.y - centre.y;
    if (Math.abs(dx) >= Math.abs(dy)) return dx < 0 ? 'left' : 'right';
    return dy < 0 ? 'top' : 'bottom';
}

/**
 * The poses of the system ports around content at `content` (component centres): each on the
 * side towards its outside connection, ordered along the side as their outside ends are, so the
 * lines do not cross, and at least SPACING apart.
 */
export function placeSystemPorts(content: Point[], ports: PortTowards[]): Map<string, Pose> {
    const xs = content.map((p) => p.x);
    const ys = content.map((p) => p.y);
    const box = xs.length > 0
        ? { left: Math.min(...xs), right: Math.max(...xs), top: Math.min(...ys), bottom: Math.max(...ys) }
        : { left: 0, right: 0, top: 0, bottom: 0 };
    const centre = { x: (box.left + box.right) / 2, y: (box.top + box.bottom) / 2 };
    const bySide = new Map<Side, PortTowards[]>();
    for (const port of ports) {
        const side = sideTowards(centre, port.towards);
        bySide.set(side, [...(bySide.get(side) ?? []), port]);
    }
    const poses = new Map<string, Pose>();
    for (const [side, onSide] of bySide) {
        const vertical = side === 'left' || side === 'right';
        const along = (p: PortTowards) => (p.towards ? (vertical ? p.towards.y : p.towards.x) : 0);
        const sorted = [...onSide].sort((a, b) => along(a) - along(b));
        const middle = vertical ? centre.y : centre.x;
        const length = vertical ? box.bottom - box.top : box.right - box.left;
        const step = Math.max(SPACING, length / sorted.length);
        sorted.forEach((port, i) => {
            const offset = Math.round(middle + (i - (sorted.length - 1) / 2) * step);
            const x = side === 'left' ? box.left - MARGIN : side === 'right' ? box.right + MARGIN : offset;
            const y = side === 'top' ? box.top - MARGIN : side === 'bottom' ? box.bottom + MARGIN : offset;
            poses.set(port.name, { x: Math.round(x), y: Math.round(y), angle: 0, flipped: false });
        });
    }
    return poses;
}

/**
 * The placement for subsystem `name` of `parent` (just grouped): its ports with the outside ends
 * of their connections in the parent, its content as it sits inside.
 */
export function systemPortPlan(parent: System, name: string): Map<string, Pose> {
    const sub = parent.components.find((c) => c.name === name)?.system;
    if (!sub) return new Map();
    const outsideEnd = (port: string): Point | undefined => {
        for (const c of parent.connections) {
            const [mine, other] = c.from.component === name && c.from.port === port ? [c.from, c.to]
                : c.to.component === name && c.to.port === port ? [c.to, c.from] : [null, null];
            if (!mine || !other) continue;
            const pose = parent.components.find((k) => k.name === other.component)?.pose
                ?? parent.ports.find((p) => p.name === other.component)?.pose;
            if (pose) return { x: pose.x, y: pose.y };
        }
        return undefined;
    };
    return placeSystemPorts(
        sub.components.map((c) => ({ x: c.pose.x, y: c.pose.y })),
        sub.ports.map((p) => ({ name: p.name, towards: outsideEnd(p.name) })),
    );
}
