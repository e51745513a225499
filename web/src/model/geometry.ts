// Poses and port placement. A pose is Hopsan's: centre x,y, angle in degrees (clockwise on
// screen, y down), then a left-right mirror about the centre applied after the rotation.
import type { Component, Connection, Pose, System } from '../protocol/types';

export interface Point { x: number; y: number }

export function toScene(pose: Pose, local: Point): Point {
    const a = (pose.angle * Math.PI) / 180;
    const c = Math.cos(a);
    const s = Math.sin(a);
    const rx = local.x * c - local.y * s;
    return { x: pose.x + (pose.flipped ? -rx : rx), y: pose.y + local.x * s + local.y * c };
}

export function toLocal(pose: Pose, scene: Point): Point {
    const dx = pose.flipped ? pose.x - scene.x : scene.x - pose.x;
    const dy = scene.y - pose.y;
    const a = (pose.angle * Math.PI) / 180;
    const c = Math.cos(a);
    const s = Math.sin(a);
    return { x: dx * c + dy * s, y: -dx * s + dy * c };
}

/** The SVG transform drawing a component's own frame at its pose (the same map as toScene). */
export function poseTransform(pose: Pose): string {
    return `translate(${pose.x},${pose.y})${pose.flipped ? ' scale(-1,1)' : ''} rotate(${pose.angle})`;
}

export interface ComponentLayout {
    halfWidth: number;
    halfHeight: number;
    /** Port positions in the component's own (unrotated) frame. */
    ports: Map<string, Point>;
}

/** Where each port of each component sat in the author's drawing (ends of connection lines). */
export type Anchors = Map<string, Map<string, Point>>;

/** Centre of a component or system port of `system`. */
export function objectCentre(system: System, name: string): Point | undefined {
    const pose = system.components.find((c) => c.name === name)?.pose ?? system.ports.find((p) => p.name === name)?.pose;
    return pose ? { x: pose.x, y: pose.y } : undefined;
}

const dist = (a: Point, x: [number, number]) => Math.hypot(a.x - x[0], a.y - x[1]);

/**
 * A connection's drawn points in from -> to order. The points keep the order the author drew
 * the line in, which need not be the connection's from/to order: the end nearer to each
 * component decides.
 */
export function orientedPoints(conn: Connection, from: Point | undefined, to: Point | undefined): [number, number][] {
    const pts = conn.points;
    if (pts.length < 2 || !from || !to) return pts;
    const first = pts[0];
    const last = pts[pts.length - 1];
    const asIs = dist(from, first) + dist(to, last);
    const reversed = dist(from, last) + dist(to, first);
    return reversed < asIs ? [...pts].reverse() : pts;
}

export function anchorsFromSystem(system: System): Anchors {
    const anchors: Anchors = new Map();
    const poses = new Map(system.components.map((c) => [c.name, c.pose]));
    const note = (component: string, port: string, point: [number, number] | undefined) => {
        const pose = poses.get(component);
        if (!pose || !point) return;
        if (!anchors.has(component)) anchors.set(component, new Map());
        const ports = anchors.get(component)!;
        if (!ports.has(port)) ports.set(port, toLocal(pose, { x: point[0], y: point[1] }));
    };
    for (const c of system.connections) {
        const pts = orientedPoints(c, objectCentre(system, c.from.component), objectCentre(system, c.to.component));
        note(c.from.component, c.from.port, pts[0]);
        note(c.to.component, c.to.port, pts[pts.length - 1]);
    }
    return anchors;
}

const MIN_HALF = 20;
const MAX_HALF = 90;
const PORT_GAP = 14;

type Side = 'left' | 'right' | 'top' | 'bottom';

// Hopsan hides the input-variable ports (a read port backed by a "<port>#Value" parameter)
// until used; parameterPortPlacement.ts says which they are and where they sit when shown.
export function isInputVariablePort(component: Component, port: string): boolean {
    return component.parameters.some((p) => p.name === `${port}#Value`);
}

// A subsystem's port sits on the side of its box where its system port sits inside, seen from
// the middle of the content (Hopsan places a subsystem's ports so); undefined when it cannot tell.
function subsystemPortPlace(component: Component, port: string): { side: Side; along: number } | undefined {
    const inner = component.system;
    const at = inner?.ports.find((p) => p.name === port)?.pose;
    if (!inner || !at || inner.components.length === 0) return undefined;
    const xs = inner.components.map((c) => c.pose.x);
    const ys = inner.components.map((c) => c.pose.y);
    const dx = at.x - (Math.min(...xs) + Math.max(...xs)) / 2;
    const dy = at.y - (Math.min(...ys) + Math.max(...ys)) / 2;
    if (dx === 0 && dy === 0) return undefined;
    if (Math.abs(dx) >= Math.abs(dy)) return { side: dx < 0 ? 'left' : 'right', along: at.y };
    return { side: dy < 0 ? 'top' : 'bottom', along: at.x };
}

function sideOf(component: Component, index: number): Side {
    const port = component.ports[index];
    const inSubsystem = port.kind === 'system' ? subsystemPortPlace(component, port.name) : undefined;
    if (inSubsystem) return inSubsystem.side;
    if (port.kind === 'read') return isInputVariablePort(component, port.name) ? 'top' : 'left';
    if (port.kind === 'write') return 'right';
    // power ports (and two-way signal ports) alternate left and right
    const power = component.ports.filter((p) => p.kind === 'power' || p.kind === 'system' || p.kind === 'bidirectional');
    const i = power.indexOf(port);
    if (power.length === 1 && component.ports.length === 1) return 'left';
    return i % 2 === 0 ? 'left' : 'right';
}

/** Icon size and port positions: known anchors first, the rest laid out by kind. */
export function layoutComponent(component: Component, known: Map<string, Point> | undefined): ComponentLayout {
    const ports = new Map<string, Point>();
    let halfWidth = MIN_HALF;
    let halfHeight = MIN_HALF;
    for (const port of component.ports) {
        const at = known?.get(port.name);
        if (!at) continue;
        ports.set(port.name, at);
        halfWidth = Math.max(halfWidth, Math.abs(at.x));
        halfHeight = Math.max(halfHeight, Math.abs(at.y));
    }
    const bySide: Record<Side, string[]> = { left: [], right: [], top: [], bottom: [] };
    component.ports.forEach((port, i) => { if (!ports.has(port.name)) bySide[sideOf(component, i)].push(port.name); });
    if (component.system) {
        // in the order they sit inside, so the lines into the box do not cross
        const along = (name: string) => subsystemPortPlace(component, name)?.along ?? 0;
        for (const names of Object.values(bySide)) names.sort((a, b) => along(a) - along(b));
    }
    halfHeight = Math.max(halfHeight, ((Math.max(bySide.left.length, bySide.right.length) + 1) * PORT_GAP) / 2);
    halfWidth = Math.max(halfWidth, ((Math.max(bySide.top.length, bySide.bottom.length) + 1) * PORT_GAP) / 2);
    halfWidth = Math.min(halfWidth, MAX_HALF);
    halfHeight = Math.min(halfHeight, MAX_HALF);
    const spread = (names: string[], place: (t: number) => Point) => {
        names.forEach((name, i) => ports.set(name, place((i + 1) / (names.length + 1))));
    };
    spread(bySide.left, (t) => ({ x: -halfWidth, y: -halfHeight + 2 * halfHeight * t }));
    spread(bySide.right, (t) => ({ x: halfWidth, y: -halfHeight + 2 * halfHeight * t }));
    spread(bySide.top, (t) => ({ x: -halfWidth + 2 * halfWidth * t, y: -halfHeight }));
    spread(bySide.bottom, (t) => ({ x: -halfWidth + 2 * halfWidth * t, y: halfHeight }));
    return { halfWidth, halfHeight, ports };
}

/**
 * From a port to the first inner point of a saved line whose end lay elsewhere (stale geometry):
 * a corner keeps the saved segment's direction, as Hopsan re-routes such lines on load.
 */
function rejoin(port: Point, savedEnd: Point, next: Point): Point[] {
    if (Math.hypot(port.x - savedEnd.x, port.y - savedEnd.y) <= 0.5) return [port];
    if (Math.abs(port.x - next.x) < 0.5 || Math.abs(port.y - next.y) < 0.5) return [port];
    const horizontal = Math.abs(savedEnd.y - next.y) < Math.abs(savedEnd.x - next.x);
    return [port, horizontal ? { x: port.x, y: next.y } : { x: next.x, y: port.y }];
}

/**
 * The line of a connection (points oriented from -> to): the author's points while both ends
 * stay put, rejoined to the ports; else an elbow.
 */
export function connectionPath(points: [number, number][], from: Point, to: Point, keepInner: boolean): Point[] {
    if (keepInner && points.length > 2) {
        const pts = points.map(([x, y]) => ({ x, y }));
        const inner = pts.slice(1, -1);
        const head = rejoin(from, pts[0], inner[0]);
        const tail = rejoin(to, pts[pts.length - 1], inner[inner.length - 1]).reverse();
        return [...head, ...inner, ...tail];
    }
    if (Math.abs(from.x - to.x) < 1 || Math.abs(from.y - to.y) < 1) return [from, to];
    const midX = (from.x + to.x) / 2;
    return [from, { x: midX, y: from.y }, { x: midX, y: to.y }, to];
}
