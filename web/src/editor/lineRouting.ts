// Reshaping a connection's line, as in Hopsan: a segment between two corners is dragged across
// its own direction (a horizontal one up and down, a vertical one sideways, a slanted one
// freely); a corner is dragged anywhere; corners are added on a segment and removed. The two
// segments that leave the ports are not dragged: their ends are the ports. A path runs from the
// connection's `from` port to its `to` port; the result is what `connection.route` saves.
import type { Point } from '../model/geometry';

/** Where a press on a line takes hold of it. */
export type LineGrip = { kind: 'segment'; index: number } | { kind: 'corner'; index: number };

const ALIGNED = 0.5;   // scene units within which two coordinates count as equal

function distanceToSegment(p: Point, a: Point, b: Point): { distance: number; along: Point } {
    const dx = b.x - a.x;
    const dy = b.y - a.y;
    const lengthSquared = dx * dx + dy * dy;
    const t = lengthSquared === 0 ? 0 : Math.min(1, Math.max(0, ((p.x - a.x) * dx + (p.y - a.y) * dy) / lengthSquared));
    const along = { x: a.x + t * dx, y: a.y + t * dy };
    return { distance: Math.hypot(p.x - along.x, p.y - along.y), along };
}

/** The segment of `path` nearest to `at` (segment i runs from point i to point i + 1). */
export function nearestSegment(path: Point[], at: Point): { index: number; distance: number; along: Point } {
    let best = { index: -1, distance: Infinity, along: at };
    for (let i = 0; i + 1 < path.length; i++) {
        const d = distanceToSegment(at, path[i], path[i + 1]);
        if (d.distance < best.distance) best = { index: i, ...d };
    }
    return best;
}

/** The corner (a point other than the two ends) within `reach` of `at`, nearest first; null if none. */
export function cornerAt(path: Point[], at: Point, reach: number): number | null {
    let best: number | null = null;
    let bestDistance = reach;
    for (let i = 1; i + 1 < path.length; i++) {
        const d = Math.hypot(path[i].x - at.x, path[i].y - at.y);
        if (d <= bestDistance) {
            best = i;
            bestDistance = d;
        }
    }
    return best;
}

/** Whether segment `index` lies between two corners (not on a port), so that it can be dragged. */
export function segmentDraggable(path: Point[], index: number): boolean {
    return index >= 1 && index + 2 <= path.length - 1;
}

/** What a press at `at` takes hold of: a corner within `reach`, else a draggable segment; null if neither. */
export function gripAt(path: Point[], at: Point, reach: number): LineGrip | null {
    const corner = cornerAt(path, at, reach);
    if (corner !== null) return { kind: 'corner', index: corner };
    const segment = nearestSegment(path, at);
    return segment.index >= 0 && segmentDraggable(path, segment.index) ? { kind: 'segment', index: segment.index } : null;
}

const rounded = (p: Point): Point => ({ x: Math.round(p.x), y: Math.round(p.y) });

/** `path` with its grip moved by `delta`: a segment across its own direction, a corner freely. */
export function dragGrip(path: Point[], grip: LineGrip, delta: Point): Point[] {
    const next = path.map((p) => ({ ...p }));
    if (grip.kind === 'corner') {
        next[grip.index] = rounded({ x: path[grip.index].x + delta.x, y: path[grip.index].y + delta.y });
        return next;
    }
    const a = path[grip.index];
    const b = path[grip.index + 1];
    const horizontal = Math.abs(a.y - b.y) < ALIGNED;
    const vertical = Math.abs(a.x - b.x) < ALIGNED;
    const shift = { x: horizontal && !vertical ? 0 : delta.x, y: vertical && !horizontal ? 0 : delta.y };
    next[grip.index] = rounded({ x: a.x + shift.x, y: a.y + shift.y });
    next[grip.index + 1] = rounded({ x: b.x + shift.x, y: b.y + shift.y });
    return next;
}

/** `path` with a corner added on its segment nearest to `at`, where `at` meets it. */
export function addCorner(path: Point[], at: Point): Point[] {
    const segment = nearestSegment(path, at);
    if (segment.index < 0) return path;
    return [...path.slice(0, segment.index + 1), rounded(segment.along), ...path.slice(segment.index + 1)];
}

/** `path` without corner `index` (the ends stay). */
export function removeCorner(path: Point[], index: number): Point[] {
    if (index <= 0 || index >= path.length - 1) return path;
    return [...path.slice(0, index), ...path.slice(index + 1)];
}

/** The points `connection.route` saves for a path: consecutive repeats dropped. */
export function routePoints(path: Point[]): [number, number][] {
    const points: [number, number][] = [];
    for (const p of path) {
        const last = points[points.length - 1];
        if (!last || Math.abs(last[0] - p.x) >= ALIGNED || Math.abs(last[1] - p.y) >= ALIGNED) points.push([p.x, p.y]);
    }
    return points;
}
