// The model drawn on an SVG canvas, derived from the store on every change. Pointer input
// becomes commands: move (with alignment guides), connect (port to port), reshape a line
// (lineRouting.ts), select (click, a box dragged on the empty canvas), pan (Space+drag or the
// middle button), zoom; the right button asks for the context menu of what is under it
// (editorMenus.ts).
// A render keeps every element whose component or connection did not change and only updates
// the attributes that did (pose, selection, name spot, line points): rebuilding the whole
// drawing per pointer move or selection click is too slow on big models.
import { EditorStore } from './EditorStore';
import { AddComponent, Connect, MoveComponents, RouteConnection, type Move } from './commands';
import { dragGrip, gripAt, routePoints, type LineGrip } from './lineRouting';
import { snapToAlignment, type Guide } from './alignmentGuides';
import { componentIcon } from './icons';
import { orientIcon } from './iconOrientation';
import {
    anchorsFromSystem, connectionPath, layoutComponent, orientedPoints, poseTransform, toScene,
    type Anchors, type ComponentLayout, type Point,
} from '../model/geometry';
import { appearanceLayout } from '../model/appearanceLayout';
import { hiddenUnlessShown, placeParameterPorts, PORT_MARKER_SIZE } from '../model/parameterPortPlacement';
import { ParameterPortVisibility } from './ParameterPortVisibility';
import { NameVisibility } from './NameVisibility';
import { pickPort, type PortTarget } from './portHitTest';
import { placeLabels, type LabelSpot } from './labelPlacement';
import { nodeColour } from '../model/nodeTypes';
import { sameRef, uniqueName } from '../model/modelState';
import { abbreviation } from './icons';
import { s, h, errorText } from '../ui/dom';
import type { Component, Connection, Port, PortRef, Pose, System } from '../protocol/types';

export interface CanvasCallbacks {
    /** A port was clicked (not dragged): offer its variables for plotting. */
    onPortClick(ref: PortRef, client: Point): void;
    /** A component was double-clicked (subsystems are entered by the canvas itself). */
    onComponentDoubleClick(name: string): void;
    /** The context menu was asked for (right button, or the menu key on the canvas) on `target`. */
    onContextMenu?(target: CanvasTarget, client: Point): void;
    /** Whether a drag may move components, draw a connection or reshape a line (a locked copy:
     *  none, so the press stays a click); absent: always. */
    allows?(edit: CanvasEdit): boolean;
}

/** The edits a drag on the canvas makes. */
export type CanvasEdit = 'move' | 'connect' | 'lines';

/** What a context menu was opened on (`at`: where on a line, in scene coordinates). */
export type CanvasTarget =
    | { kind: 'component'; name: string }
    | { kind: 'port'; ref: PortRef }
    | { kind: 'connection'; from: PortRef; to: PortRef; at: Point }
    | { kind: 'canvas'; at: Point };

type Drag =
    | { kind: 'move'; start: Point; names: string[]; origin: Map<string, Pose>; moved: boolean; primary: string; guides: Guide[] }
    | { kind: 'connect'; from: PortRef; fromPoint: Point; current: Point; startClient: Point; moved: boolean }
    | { kind: 'route'; line: Connection; base: Point[]; grip: LineGrip; start: Point; moved: boolean }
    | { kind: 'pan'; startClient: Point; tx: number; ty: number }
    | { kind: 'marquee'; start: Point; current: Point; startClient: Point; additive: boolean };

const DRAG_THRESHOLD = 4;   // CSS pixels before a press becomes a drag
/** Scene distance from a port's centre that still hits it: its marker's extent. */
const PORT_REACH = PORT_MARKER_SIZE / 2 + 1;
/** Screen distance (CSS pixels) within which a press takes a line's corner, or a drag snaps to a guide. */
const CORNER_REACH = 6;
const GUIDE_REACH = 6;

/** A drawn component or line with the attribute values it was last given. */
interface DrawnComponent { el: SVGGElement; body: SVGGElement; text: SVGTextElement; comp: Component; pose: string; cls: string; spot: string }
/**
 * `hit`: an invisible wider copy of the line over it that takes the pointer, so that a thin line
 * is easy to press. `inputs`: what the line was drawn from (the system, both ends' components
 * and poses, whether it is selected).
 */
interface DrawnConnection { el: SVGPolylineElement; hit: SVGPolylineElement; points: string; cls: string; path: Point[]; inputs: unknown[] }

/** The drawn line (or its hit area) an event's target belongs to. */
function lineElementOf(target: Element): Element | null {
    return target.closest('.connection, .line-hit');
}

/** The connection a drawn line stands for (its data-from and data-to, `component.port`). */
function connectionOfElement(el: Element): { from: PortRef; to: PortRef } {
    const split = (text: string) => ({ component: text.slice(0, text.lastIndexOf('.')), port: text.slice(text.lastIndexOf('.') + 1) });
    return { from: split(el.getAttribute('data-from')!), to: split(el.getAttribute('data-to')!) };
}

/** Puts `children` in `parent` in this order, touching the DOM only when they differ. */
function setChildren(parent: Element, children: Element[]): void {
    const current = parent.children;
    if (current.length === children.length && children.every((c, i) => current[i] === c)) return;
    parent.replaceChildren(...children);
}

export class CanvasView {
    readonly element: HTMLDivElement;
    private readonly svg: SVGSVGElement;
    private readonly world: SVGGElement;
    private view = { tx: 0, ty: 0, scale: 1 };
    private readonly anchors = new Map<string, Anchors>();
    /** The types the components had when their lines were loaded: a replaced one's port spots are not its own. */
    private readonly loadedTypes = new Map<string, string>();
    private readonly poseOverride = new Map<string, Pose>();
    private drag: Drag | null = null;
    /** Space is held: a drag pans. */
    private spaceHeld = false;
    /** A line being reshaped, drawn along this path until the server has the new points. */
    private routeOverride: { line: Connection; path: Point[] } | null = null;
    private lastPress: { name: string; time: number } | null = null;
    private generation = 0;
    private drawnPath: string | null = null;
    private byName = new Map<string, Component>();
    private portError: { ref: PortRef; message: string; timer: number } | null = null;
    private fittedPath: string | null = null;
    /** A clicked connection (Delete removes it). */
    selectedConnection: { from: PortRef; to: PortRef } | null = null;
    /** Layouts of the components on screen, by name (for hit tests and tests). */
    layouts = new Map<string, ComponentLayout>();
    /** Which parameter ports are drawn (hidden unless shown). */
    readonly parameterPorts = new ParameterPortVisibility();
    /** Which component names are hidden. */
    readonly names = new NameVisibility();

    constructor(private readonly store: EditorStore, private readonly callbacks: CanvasCallbacks) {
        this.world = s('g', { class: 'world' });
        this.svg = s('svg', { class: 'canvas', tabindex: 0, 'data-testid': 'canvas' }, this.world);
        this.element = h('div', { class: 'canvas-wrap' }, this.svg);
        this.svg.addEventListener('pointerdown', (e) => this.onPointerDown(e));
        this.svg.addEventListener('pointermove', (e) => this.onPointerMove(e));
        this.svg.addEventListener('pointerup', (e) => void this.onPointerUp(e));
        this.svg.addEventListener('wheel', (e) => this.onWheel(e), { passive: false });
        this.svg.addEventListener('dragover', (e) => {
            if (e.dataTransfer?.types.includes('application/x-tlmhub-type')) e.preventDefault();
        });
        this.svg.addEventListener('drop', (e) => {
            const type = e.dataTransfer?.getData('application/x-tlmhub-type');
            if (!type) return;
            e.preventDefault();
            void this.addComponent(type, this.sceneFromClient(e.clientX, e.clientY));
        });
        this.world.append(this.connectionGroup, this.componentGroup, this.overlay);
        const unsubscribeStore = store.subscribe(() => this.render());
        const unsubscribeVisibility = this.parameterPorts.subscribe(() => this.render());
        const unsubscribeNames = this.names.subscribe(() => this.render());
        this.svg.addEventListener('contextmenu', (e) => this.onContextMenu(e));
        // Space held over the focused canvas makes a drag pan (its keyup may come anywhere)
        this.svg.addEventListener('keydown', (e) => {
            if (e.key !== ' ' || e.ctrlKey || e.metaKey || e.altKey) return;
            e.preventDefault();
            this.setSpaceHeld(true);
        });
        const onKeyUp = (e: KeyboardEvent) => { if (e.key === ' ') this.setSpaceHeld(false); };
        const onBlur = () => this.setSpaceHeld(false);
        window.addEventListener('keyup', onKeyUp);
        window.addEventListener('blur', onBlur);
        this.unsubscribe = () => {
            unsubscribeStore(); unsubscribeVisibility(); unsubscribeNames();
            window.removeEventListener('keyup', onKeyUp);
            window.removeEventListener('blur', onBlur);
        };
        this.resizeObserver.observe(this.element);
    }

    /** What the last render drew, reused by the next one where nothing changed. */
    private drawnComponents = new Map<string, DrawnComponent>();
    private drawnConnections = new Map<Connection, DrawnConnection>();
    private drawnPorts = new Map<string, SVGGElement>();
    private readonly connectionGroup = s('g', { class: 'connections' });
    private readonly componentGroup = s('g', { class: 'components' });
    private overlay: SVGGElement = s('g', { class: 'overlay' });
    /** Layouts by component object: a changed component is a new object. */
    private layoutCache = new WeakMap<Component, ComponentLayout>();
    private readonly unsubscribe: () => void;

    private readonly resizeObserver = new ResizeObserver(() => { if (this.fittedPath === null) this.render(); });

    /** Stops watching the page and the store (the editor was left). */
    dispose(): void {
        this.resizeObserver.disconnect();
        this.unsubscribe();
        if (this.portError) clearTimeout(this.portError.timer);
        this.portError = null;
    }

    /** Draws `layer` over the drawing, in its coordinates (the live controls): it pans and zooms with it. */
    addLayer(layer: SVGGElement): void { this.world.append(layer); }

    private get pathKey(): string { return this.store.path.join('$'); }
    private key(name: string): string { return `${this.pathKey}/${name}`; }

    // ---- coordinates ----
    sceneFromClient(clientX: number, clientY: number): Point {
        const r = this.svg.getBoundingClientRect();
        return { x: (clientX - r.left - this.view.tx) / this.view.scale, y: (clientY - r.top - this.view.ty) / this.view.scale };
    }

    /** Screen (client) position of a scene point. */
    clientFromScene(p: Point): Point {
        const r = this.svg.getBoundingClientRect();
        return { x: r.left + this.view.tx + p.x * this.view.scale, y: r.top + this.view.ty + p.y * this.view.scale };
    }

    private applyView(): void {
        // setting it, even unchanged, makes the browser lay out the whole drawing again
        const transform = `translate(${this.view.tx},${this.view.ty}) scale(${this.view.scale})`;
        if (this.world.getAttribute('transform') !== transform) this.world.setAttribute('transform', transform);
    }

    zoomBy(factor: number, aroundClient?: Point): void {
        const r = this.svg.getBoundingClientRect();
        const cx = aroundClient ? aroundClient.x - r.left : r.width / 2;
        const cy = aroundClient ? aroundClient.y - r.top : r.height / 2;
        const scale = Math.min(8, Math.max(0.1, this.view.scale * factor));
        const k = scale / this.view.scale;
        this.view = { scale, tx: cx - (cx - this.view.tx) * k, ty: cy - (cy - this.view.ty) * k };
        this.applyView();
    }

    /** Shows the whole system. */
    fit(): void {
        const system = this.store.system;
        const r = this.svg.getBoundingClientRect();
        if (r.width === 0 || r.height === 0) return;
        const xs: number[] = [];
        const ys: number[] = [];
        for (const c of system.components) {
            const l = this.layouts.get(c.name);
            const ext = l ? Math.max(l.halfWidth, l.halfHeight) : 30;
            xs.push(c.pose.x - ext, c.pose.x + ext);
            ys.push(c.pose.y - ext - 16, c.pose.y + ext);
        }
        for (const p of system.ports) { xs.push(p.pose.x - 20, p.pose.x + 20); ys.push(p.pose.y - 20, p.pose.y + 20); }
        if (xs.length === 0) {
            this.view = { scale: 1, tx: r.width / 2, ty: r.height / 2 };
        } else {
            const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
            const scale = Math.min(2, Math.max(0.1, Math.min((r.width - 40) / (x1 - x0 || 1), (r.height - 40) / (y1 - y0 || 1))));
            this.view = { scale, tx: r.width / 2 - ((x0 + x1) / 2) * scale, ty: r.height / 2 - ((y0 + y1) / 2) * scale };
        }
        this.fittedPath = this.pathKey;
        this.applyView();
    }

    /** Centre of the visible area in scene coordinates. */
    viewCentre(): Point {
        const r = this.svg.getBoundingClientRect();
        return this.sceneFromClient(r.left + r.width / 2, r.top + r.height / 2);
    }

    // ---- drawing ----
    private anchorsFor(system: System): Anchors {
        let anchors = this.anchors.get(this.pathKey);
        if (!anchors) {
            anchors = anchorsFromSystem(system);
            this.anchors.set(this.pathKey, anchors);
            for (const c of system.components) {
                this.loadedTypes.set(this.key(c.name), c.type);
            }
        }
        return anchors;
    }

    private poseOf(c: Component): Pose { return this.poseOverride.get(c.name) ?? c.pose; }

    private setSpaceHeld(held: boolean): void {
        this.spaceHeld = held;
        this.svg.classList.toggle('pan-ready', held);
    }

    /** A line as drawn, from its connection's `from` port to its `to` port; null if not drawn. */
    linePath(from: PortRef, to: PortRef): Point[] | null {
        for (const [c, d] of this.drawnConnections) {
            if (sameRef(c.from, from) && sameRef(c.to, to)) return d.path;
            if (sameRef(c.from, to) && sameRef(c.to, from)) return [...d.path].reverse();
        }
        return null;
    }

    /** The scene distance that `pixels` CSS pixels span at the current zoom. */
    sceneDistance(pixels: number): number {
        return pixels / this.view.scale;
    }

    /** Scene position of a port (a system port is its own pose). */
    portPoint(system: System, ref: PortRef): Point | null {
        const comp = this.byName.get(ref.component);
        if (comp) {
            const local = this.layouts.get(comp.name)?.ports.get(ref.port);
            return local ? toScene(this.poseOf(comp), local) : toScene(this.poseOf(comp), { x: 0, y: 0 });
        }
        const sp = system.ports.find((p) => p.name === ref.component);
        return sp ? { x: sp.pose.x, y: sp.pose.y } : null;
    }

    render(): void {
        if (this.generation !== this.store.generation || this.drawnPath !== this.pathKey) {
            // another model (or the same one reopened) or another subsystem: drawn afresh
            if (this.generation !== this.store.generation) {
                this.anchors.clear();
                this.loadedTypes.clear();
                this.fittedPath = null;
            }
            this.generation = this.store.generation;
            this.drawnPath = this.pathKey;
            this.layoutCache = new WeakMap();
            this.drawnComponents = new Map();
            this.drawnConnections = new Map();
            this.drawnPorts = new Map();
        }
        const system = this.store.system;
        const anchors = this.anchorsFor(system);
        // Hopsan's own icon size and port positions where known; our rules for subsystems and the rest
        this.layouts = new Map(system.components.map((c) => {
            let layout = this.layoutCache.get(c);
            if (!layout) {
                const known = this.loadedTypes.get(this.key(c.name)) === c.type ? anchors.get(c.name) : undefined;
                layout = placeParameterPorts(c, appearanceLayout(c, known) ?? layoutComponent(c, known), known);
                this.layoutCache.set(c, layout);
            }
            return [c.name, layout];
        }));
        this.byName = new Map(system.components.map((c) => [c.name, c]));
        // fitted before the new drawing is added, so that measuring the canvas does not lay it out
        if (this.fittedPath !== this.pathKey) this.fit();

        const connections = new Map<Connection, DrawnConnection>();
        for (const conn of system.connections) {
            const drawn = this.drawConnection(system, conn, this.drawnConnections.get(conn));
            if (drawn) connections.set(conn, drawn);
        }
        this.drawnConnections = connections;
        setChildren(this.connectionGroup, [...connections.values()].flatMap((d) => [d.el, d.hit]));

        // names keep off the lines where they can
        const lines = [...connections.values()].map((d) => d.path);
        const labels = placeLabels(system.components.map((c) => ({ name: c.name, pose: this.poseOf(c), layout: this.layouts.get(c.name)! })), lines);
        const components = new Map<string, DrawnComponent>();
        for (const comp of system.components) components.set(comp.name, this.drawComponent(comp, labels.get(comp.name)!, this.drawnComponents.get(comp.name)));
        this.drawnComponents = components;
        const ports = new Map(system.ports.map((sp) => {
            const key = `${sp.name} ${sp.node_type} ${sp.pose.x},${sp.pose.y}`;
            return [key, this.drawnPorts.get(key) ?? this.drawSystemPort(sp.name, sp.node_type, sp.pose)];
        }));
        this.drawnPorts = ports;
        setChildren(this.componentGroup, [...[...components.values()].map((d) => d.el), ...ports.values()]);

        this.renderOverlay();
        this.applyView();
    }

    /** Redraws only the overlay (drag line, marquee, the mark of a refused connection's port). */
    private renderOverlay(): void {
        const fresh = this.drawOverlay(this.store.system);
        if (fresh.childElementCount === 0 && this.overlay.childElementCount === 0) return;
        this.overlay.replaceWith(fresh);
        this.overlay = fresh;
    }

    /**
     * A connection's line: the one drawn before (`drawn`) with its points and class brought up
     * to date. Its corners stay where they were put when an end moves, as in Hopsan: the line
     * is rejoined to the moved port.
     */
    private drawConnection(system: System, conn: Connection, drawn: DrawnConnection | undefined): DrawnConnection | null {
        // while neither end moved, the line is as drawn (a drag moves few of the many lines)
        const ends = [conn.from.component, conn.to.component].map((name) => this.byName.get(name));
        const chosen = this.selectedConnection !== null && sameRef(this.selectedConnection.from, conn.from) && sameRef(this.selectedConnection.to, conn.to);
        const override = this.routeOverride?.line === conn ? this.routeOverride.path : null;
        const inputs = [system, chosen, override, ...ends, ...ends.map((c) => c && this.poseOf(c))];
        if (drawn && inputs.every((x, i) => x === drawn.inputs[i])) return drawn;
        const a = this.portPoint(system, conn.from);
        const b = this.portPoint(system, conn.to);
        if (!a || !b) return null;
        const pts = override ?? connectionPath(orientedPoints(conn, a, b), a, b, true);
        const nodeType = this.portOf(conn.from)?.node_type ?? this.portOf(conn.to)?.node_type;
        const points = pts.map((p) => `${p.x},${p.y}`).join(' ');
        const cls = `connection ${nodeType === 'NodeSignal' ? 'signal' : 'power'}${chosen ? ' selected' : ''}`;
        if (drawn) {
            if (drawn.points !== points) {
                drawn.el.setAttribute('points', points);
                drawn.hit.setAttribute('points', points);
            }
            if (drawn.cls !== cls) drawn.el.setAttribute('class', cls);
            return { ...drawn, points, cls, path: pts, inputs };
        }
        const endAttributes = { 'data-from': `${conn.from.component}.${conn.from.port}`, 'data-to': `${conn.to.component}.${conn.to.port}` };
        const el = s('polyline', { class: cls, points, stroke: nodeColour(nodeType), ...endAttributes });
        const hit = s('polyline', { class: 'line-hit', points, ...endAttributes });
        return { el, hit, points, cls, path: pts, inputs };
    }

    private drawOverlay(system: System): SVGGElement {
        const overlay = s('g', { class: 'overlay' });
        const drag = this.drag;
        if (drag?.kind === 'connect' && drag.moved) {
            overlay.append(s('line', { class: 'drag-line', x1: drag.fromPoint.x, y1: drag.fromPoint.y, x2: drag.current.x, y2: drag.current.y }));
        }
        if (drag?.kind === 'marquee') {
            const [x0, y0, x1, y1] = [Math.min(drag.start.x, drag.current.x), Math.min(drag.start.y, drag.current.y),
                Math.max(drag.start.x, drag.current.x), Math.max(drag.start.y, drag.current.y)];
            overlay.append(s('rect', { class: 'marquee', x: x0, y: y0, width: x1 - x0, height: y1 - y0 }));
        }
        if (drag?.kind === 'move') {
            for (const g of drag.guides) {
                const [x1, y1, x2, y2] = g.axis === 'x' ? [g.at, g.from - 20, g.at, g.to + 20] : [g.from - 20, g.at, g.to + 20, g.at];
                overlay.append(s('line', { class: 'alignment-guide', 'data-axis': g.axis, x1, y1, x2, y2 }));
            }
        }
        // the selected line's corners, which a drag takes hold of
        const chosen = this.selectedConnection;
        const line = chosen && [...this.drawnConnections].find(([c]) => sameRef(c.from, chosen.from) && sameRef(c.to, chosen.to))?.[1];
        if (line) {
            const size = 5 / this.view.scale;
            for (const p of line.path.slice(1, -1)) {
                overlay.append(s('rect', { class: 'line-corner', x: p.x - size / 2, y: p.y - size / 2, width: size, height: size }));
            }
        }
        if (this.portError) {
            const at = this.portPoint(system, this.portError.ref);
            if (at) {
                overlay.append(s('circle', { class: 'port-error-mark', cx: at.x, cy: at.y, r: 8 },
                    s('title', {}, this.portError.message)));
            }
        }
        return overlay;
    }

    private portOf(ref: PortRef): Port | undefined {
        return this.byName.get(ref.component)?.ports.find((p) => p.name === ref.port);
    }

    /**
     * A component: the element drawn before (`drawn`) while the component is the same object,
     * with its pose, selection and name spot brought up to date; else a new one.
     */
    private drawComponent(comp: Component, label: LabelSpot, drawn: DrawnComponent | undefined): DrawnComponent {
        const pose = poseTransform(this.poseOf(comp));
        const shown = this.parameterPorts.shownFor(this.store.path, comp.name);
        const nameHidden = this.names.hiddenFor(this.store.path, comp.name);
        const cls = `component${this.store.selection.has(comp.name) ? ' selected' : ''}${comp.system ? ' subsystem' : ''}${shown ? ' parameter-ports-shown' : ''}${nameHidden ? ' name-hidden' : ''}`;
        const spot = `${label.x},${label.y},${label.anchor}`;
        if (drawn && drawn.comp === comp) {
            if (drawn.pose !== pose) drawn.body.setAttribute('transform', pose);
            if (drawn.pose !== pose) orientIcon(drawn.body, comp.type, this.poseOf(comp), this.layouts.get(comp.name)!);
            if (drawn.cls !== cls) drawn.el.setAttribute('class', cls);
            if (drawn.spot !== spot) {
                drawn.text.setAttribute('x', String(label.x));
                drawn.text.setAttribute('y', String(label.y));
                drawn.text.setAttribute('text-anchor', label.anchor);
            }
            [drawn.pose, drawn.cls, drawn.spot] = [pose, cls, spot];
            return drawn;
        }
        const layout = this.layouts.get(comp.name)!;
        const body = s('g', { class: 'component-body', transform: pose },
            componentIcon(comp.type, layout.halfWidth, layout.halfHeight),
            ...comp.ports.map((p) => this.drawPort(comp, p, layout.ports.get(p.name) ?? { x: 0, y: 0 })));
        orientIcon(body, comp.type, this.poseOf(comp), layout);
        const text = s('text', { class: 'component-label', x: label.x, y: label.y, 'text-anchor': label.anchor }, comp.name);
        const el = s('g', { class: cls, 'data-name': comp.name, 'data-type': comp.type },
            s('title', {}, `${comp.name} (${comp.type})`), body, text);
        return { el, body, text, comp, pose, cls, spot };
    }

    private drawPort(comp: Component, port: Port, at: Point): SVGElement {
        const colour = nodeColour(port.node_type);
        // drawn only when shown (see .port.parameter in styles.css)
        const hideable = hiddenUnlessShown(comp, port);
        const size = hideable ? 3 : 4.5;
        const attrs = {
            class: `port port-${port.kind}${port.connected ? ' connected' : ''}${hideable ? ' parameter' : ''}${port.multiport ? ' multiport' : ''}`,
            'data-component': comp.name, 'data-port': port.name,
            stroke: colour, fill: port.connected ? colour : '#fff',
        };
        let shape: SVGElement;
        if (port.kind === 'read') {
            shape = s('polygon', { ...attrs, points: `${at.x - size},${at.y - size} ${at.x + size},${at.y} ${at.x - size},${at.y + size}` });
        } else if (port.kind === 'write') {
            shape = s('rect', { ...attrs, x: at.x - size, y: at.y - size, width: 2 * size, height: 2 * size });
        } else if (port.kind === 'bidirectional') {
            const r = size + 1;
            shape = s('polygon', { ...attrs, points: `${at.x},${at.y - r} ${at.x + r},${at.y} ${at.x},${at.y + r} ${at.x - r},${at.y}` });
        } else {
            shape = s('circle', { ...attrs, cx: at.x, cy: at.y, r: port.multiport ? size + 1 : size });
        }
        shape.append(s('title', {}, `${comp.name}.${port.name} (${port.node_type.replace(/^Node/, '')}, ${port.kind}${port.multiport ? ', multiport' : ''})`));
        return shape;
    }

    private drawSystemPort(name: string, nodeType: string | null, pose: Pose): SVGGElement {
        const r = 8;
        const colour = nodeColour(nodeType);
        return s('g', { class: 'component system-port', 'data-name': name, 'data-type': 'SystemPort' },
            s('polygon', { class: 'system-port-shape', points: `${pose.x - r},${pose.y} ${pose.x},${pose.y - r} ${pose.x + r},${pose.y} ${pose.x},${pose.y + r}`, fill: '#fff', stroke: colour }),
            s('circle', { class: 'port port-system', 'data-component': name, 'data-port': name, cx: pose.x, cy: pose.y, r: 3.5, fill: colour, stroke: colour }),
            s('text', { class: 'component-label', x: pose.x, y: pose.y + r + 11, 'text-anchor': 'middle' }, name));
    }

    /**
     * Marks the port a refused connection concerns for a while; the reason goes to the editor's
     * message area (an `editor-error` event), where it wraps and is never cut off by the canvas.
     */
    showPortError(ref: PortRef, message: string): void {
        if (this.portError) clearTimeout(this.portError.timer);
        const timer = window.setTimeout(() => { this.portError = null; this.render(); }, 10000);
        this.portError = { ref, message, timer };
        this.render();
        this.element.dispatchEvent(new CustomEvent('editor-error', { bubbles: true, detail: message }));
    }

    // ---- commands started from the canvas ----
    async addComponent(type: string, at: Point): Promise<string | null> {
        const system = this.store.system;
        const base = type === 'Subsystem' ? 'Subsystem' : type.replace(/^(Hydraulic|Mechanic|Signal|Electric|Pneumatic|Aero)/, '') || abbreviation(type);
        const command = new AddComponent(this.store.path, type, uniqueName(system, base), { x: Math.round(at.x), y: Math.round(at.y), angle: 0, flipped: false });
        try {
            await this.store.execute(command);
            this.store.select([command.addedName]);
            return command.addedName;
        } catch (e) {
            this.notifyError(e);
            return null;
        }
    }

    private notifyError(e: unknown): void {
        this.element.dispatchEvent(new CustomEvent('editor-error', { bubbles: true, detail: errorText(e) }));
    }

    // ---- pointer input ----
    private onPointerDown(e: PointerEvent): void {
        this.svg.focus();
        const target = e.target as Element;
        const scene = this.sceneFromClient(e.clientX, e.clientY);
        const portEl = target.closest('[data-port]');
        const compEl = target.closest('.component');
        const connEl = lineElementOf(target);
        if (e.button === 1 || (e.button === 0 && this.spaceHeld)) {
            e.preventDefault();   // no middle-button autoscroll
            this.drag = { kind: 'pan', startClient: { x: e.clientX, y: e.clientY }, tx: this.view.tx, ty: this.view.ty };
            this.svg.setPointerCapture(e.pointerId);
            return;
        }
        if (e.button === 0 && connEl && !portEl) {
            this.selectedConnection = connectionOfElement(connEl);
            this.store.select([]);
            this.render();
            this.startRoute(connEl, scene, e.pointerId);
            return;
        }
        if (this.selectedConnection) {
            this.selectedConnection = null;
            this.render();
        }
        if (e.button !== 0) {
            return;
        } else if (portEl) {
            const from = pickPort(this.portTargets(false), scene, PORT_REACH)
                ?? { component: portEl.getAttribute('data-component')!, port: portEl.getAttribute('data-port')! };
            const fromPoint = this.portPoint(this.store.system, from) ?? scene;
            this.drag = { kind: 'connect', from, fromPoint, current: scene, startClient: { x: e.clientX, y: e.clientY }, moved: false };
        } else if (compEl) {
            const name = compEl.getAttribute('data-name')!;
            if (compEl.classList.contains('system-port')) return;
            // an element may be rebuilt between two clicks, so the browser's dblclick cannot be used
            const now = performance.now();
            const last = this.lastPress;
            this.lastPress = { name, time: now };
            if (last && last.name === name && now - last.time < 450) {
                this.lastPress = null;
                this.onDoubleClick(name);
                return;
            }
            if (e.shiftKey || e.ctrlKey || e.metaKey) {
                const next = new Set(this.store.selection);
                if (next.has(name)) next.delete(name); else next.add(name);
                this.store.select(next);
                return;
            }
            if (!this.store.selection.has(name)) this.store.select([name]);
            const names = [...this.store.selection];
            const origin = new Map(this.store.system.components.filter((c) => names.includes(c.name)).map((c) => [c.name, { ...c.pose }]));
            this.drag = { kind: 'move', start: scene, names, origin, moved: false, primary: name, guides: [] };
        } else {
            this.drag = { kind: 'marquee', start: scene, current: scene, startClient: { x: e.clientX, y: e.clientY }, additive: e.shiftKey || e.ctrlKey || e.metaKey };
        }
        this.svg.setPointerCapture(e.pointerId);
    }

    /** A press on a line: takes hold of the corner or the segment between corners under it, if any. */
    private startRoute(connEl: Element, scene: Point, pointerId: number): void {
        if (!this.allows('lines')) return;
        const drawn = [...this.drawnConnections].find(([, d]) => d.el === connEl || d.hit === connEl);
        if (!drawn) return;
        const [line, { path }] = drawn;
        const grip = gripAt(path, scene, CORNER_REACH / this.view.scale);
        if (!grip) return;
        this.drag = { kind: 'route', line, base: path, grip, start: scene, moved: false };
        this.svg.setPointerCapture(pointerId);
    }

    private onPointerMove(e: PointerEvent): void {
        const drag = this.drag;
        if (!drag) return;
        const scene = this.sceneFromClient(e.clientX, e.clientY);
        if (drag.kind === 'pan') {
            this.view.tx = drag.tx + e.clientX - drag.startClient.x;
            this.view.ty = drag.ty + e.clientY - drag.startClient.y;
            this.applyView();
        } else if (drag.kind === 'connect') {
            drag.current = scene;
            if (!drag.moved && Math.hypot(e.clientX - drag.startClient.x, e.clientY - drag.startClient.y) > DRAG_THRESHOLD
                && this.allows('connect')) {
                drag.moved = true;
                this.svg.classList.toggle('offer-parameter-ports', this.offersParameterPorts(drag.from));
            }
            this.renderOverlay();
        } else if (drag.kind === 'move') {
            const dx = scene.x - drag.start.x;
            const dy = scene.y - drag.start.y;
            if (Math.hypot(dx, dy) * this.view.scale > DRAG_THRESHOLD && this.allows('move')) drag.moved = true;
            if (!drag.moved) return;
            const offset = this.alignedOffset(drag, { x: dx, y: dy });
            for (const [name, pose] of drag.origin) this.poseOverride.set(name, { ...pose, x: Math.round(pose.x + offset.x), y: Math.round(pose.y + offset.y) });
            this.render();
        } else if (drag.kind === 'route') {
            const delta = { x: scene.x - drag.start.x, y: scene.y - drag.start.y };
            if (Math.hypot(delta.x, delta.y) * this.view.scale > DRAG_THRESHOLD) drag.moved = true;
            if (!drag.moved) return;
            this.routeOverride = { line: drag.line, path: dragGrip(drag.base, drag.grip, delta) };
            this.render();
        } else {
            drag.current = scene;
            this.renderOverlay();
        }
    }

    private allows(edit: CanvasEdit): boolean {
        return this.callbacks.allows?.(edit) ?? true;
    }

    /**
     * The move's offset snapped so that the pressed component's centre lines up with another
     * object's centre when it comes within a few pixels; the guides are kept for the overlay.
     */
    private alignedOffset(drag: Extract<Drag, { kind: 'move' }>, offset: Point): Point {
        const origin = drag.origin.get(drag.primary);
        if (!origin) return offset;
        const moving = new Set(drag.names);
        const others = [
            ...this.store.system.components.filter((c) => !moving.has(c.name)).map((c) => ({ x: c.pose.x, y: c.pose.y })),
            ...this.store.system.ports.map((p) => ({ x: p.pose.x, y: p.pose.y })),
        ];
        const snap = snapToAlignment({ x: origin.x, y: origin.y }, offset, others, GUIDE_REACH / this.view.scale);
        drag.guides = snap.guides;
        return snap.offset;
    }

    private async onPointerUp(e: PointerEvent): Promise<void> {
        const drag = this.drag;
        this.drag = null;
        if (this.svg.hasPointerCapture(e.pointerId)) this.svg.releasePointerCapture(e.pointerId);
        if (!drag) return;
        if (drag.kind === 'pan') {
            return;
        } else if (drag.kind === 'marquee') {
            const clicked = Math.hypot(e.clientX - drag.startClient.x, e.clientY - drag.startClient.y) <= DRAG_THRESHOLD;
            if (clicked) {
                if (!drag.additive) this.store.select([]);
            } else {
                this.selectInBox(drag.start, drag.current, drag.additive);
            }
            this.renderOverlay();
        } else if (drag.kind === 'route') {
            const path = this.routeOverride?.line === drag.line ? this.routeOverride.path : null;
            if (!drag.moved || !path) return;
            const line = drag.line;
            try {
                await this.store.execute(new RouteConnection(this.store.path, line.from, line.to, line.points, routePoints(path)));
            } catch (err) {
                this.notifyError(err);
            } finally {
                this.routeOverride = null;
                this.render();
            }
        } else if (drag.kind === 'connect') {
            const offered = this.offersParameterPorts(drag.from);
            this.svg.classList.remove('offer-parameter-ports');
            this.render();
            if (!drag.moved) {
                this.callbacks.onPortClick(drag.from, { x: e.clientX, y: e.clientY });
                return;
            }
            const to = this.dropTarget(drag.from, this.sceneFromClient(e.clientX, e.clientY), offered, { x: e.clientX, y: e.clientY });
            if (!to) return;
            if (to.component === drag.from.component && to.port === drag.from.port) return;
            try {
                await this.store.execute(new Connect(this.store.path, drag.from, to));
            } catch (err) {
                this.showPortError(to, errorText(err));
            }
        } else if (drag.kind === 'move') {
            if (!drag.moved) return;
            const moves: Move[] = [];
            for (const [name, from] of drag.origin) {
                const to = this.poseOverride.get(name);
                if (to) moves.push({ name, from, to });
            }
            try {
                await this.store.execute(new MoveComponents(this.store.path, moves));
            } catch (err) {
                this.notifyError(err);
            } finally {
                for (const name of drag.origin.keys()) this.poseOverride.delete(name);
                this.render();
            }
        }
    }

    private nodeTypeOf(ref: PortRef): string | null {
        return this.portOf(ref)?.node_type ?? this.store.system.ports.find((p) => p.name === ref.component)?.node_type ?? null;
    }

    /** A signal output dragged: the hidden parameter ports could take it, so they show meanwhile. */
    private offersParameterPorts(from: PortRef): boolean {
        const port = this.portOf(from);
        return this.nodeTypeOf(from) === 'NodeSignal' && port?.kind !== 'read';
    }

    /** The drawn ports in scene coordinates; hidden parameter ports only when `withParameterPorts`. */
    private portTargets(withParameterPorts: boolean): PortTarget[] {
        const targets: PortTarget[] = [];
        for (const comp of this.store.system.components) {
            const layout = this.layouts.get(comp.name);
            const shown = withParameterPorts || this.parameterPorts.shownFor(this.store.path, comp.name);
            for (const port of comp.ports) {
                const at = layout?.ports.get(port.name);
                if (!at || (!shown && hiddenUnlessShown(comp, port))) continue;
                targets.push({ ref: { component: comp.name, port: port.name }, at: toScene(this.poseOf(comp), at), nodeType: port.node_type, power: port.kind === 'power' });
            }
        }
        for (const sp of this.store.system.ports) {
            targets.push({ ref: { component: sp.name, port: sp.name }, at: { x: sp.pose.x, y: sp.pose.y }, nodeType: sp.node_type, power: sp.node_type !== 'NodeSignal' });
        }
        return targets;
    }

    /**
     * Where a dragged connection lands: a port of its own node type under the pointer, power
     * ports first; else the port element there, so that the server says why it does not fit.
     */
    private dropTarget(from: PortRef, scene: Point, withParameterPorts: boolean, client: Point): PortRef | null {
        const nodeType = this.nodeTypeOf(from);
        const fitting = pickPort(this.portTargets(withParameterPorts), scene, PORT_REACH, nodeType ?? undefined);
        if (fitting) return fitting;
        const element = document.elementFromPoint(client.x, client.y)?.closest('[data-port]');
        return element ? { component: element.getAttribute('data-component')!, port: element.getAttribute('data-port')! } : null;
    }

    /** Selects the components whose centres lie in the box; `additive`: added to the selection. */
    private selectInBox(a: Point, b: Point, additive: boolean): void {
        const [x0, x1, y0, y1] = [Math.min(a.x, b.x), Math.max(a.x, b.x), Math.min(a.y, b.y), Math.max(a.y, b.y)];
        const inside = this.store.system.components
            .filter((c) => c.pose.x >= x0 && c.pose.x <= x1 && c.pose.y >= y0 && c.pose.y <= y1)
            .map((c) => c.name);
        this.store.select(additive ? [...this.store.selection, ...inside] : inside);
    }

    private onDoubleClick(name: string): void {
        const comp = this.store.system.components.find((c) => c.name === name);
        if (comp?.system) {
            this.store.enterSystem([...this.store.path, name]);
        } else {
            this.callbacks.onComponentDoubleClick(name);
        }
    }

    /** Right button (or the menu key): the menu of what is under the pointer, which becomes the selection. */
    private onContextMenu(e: MouseEvent): void {
        e.preventDefault();
        if (!this.callbacks.onContextMenu || this.drag) return;   // not in the middle of a drag
        const target = e.target as Element;
        const client = { x: e.clientX, y: e.clientY };
        const scene = this.sceneFromClient(e.clientX, e.clientY);
        const portEl = target.closest('[data-port]');
        const compEl = target.closest('.component');
        const connEl = lineElementOf(target);
        let what: CanvasTarget;
        if (portEl) {
            // the port a press there would take: power ports first, as for plotting and connecting
            const ref = pickPort(this.portTargets(false), scene, PORT_REACH)
                ?? { component: portEl.getAttribute('data-component')!, port: portEl.getAttribute('data-port')! };
            what = { kind: 'port', ref };
        } else if (compEl?.classList.contains('system-port')) {
            const name = compEl.getAttribute('data-name')!;
            what = { kind: 'port', ref: { component: name, port: name } };
        } else if (compEl) {
            const name = compEl.getAttribute('data-name')!;
            // a component of the selection keeps it (the menu acts on all); another becomes it
            if (!this.store.selection.has(name)) this.store.select([name]);
            what = { kind: 'component', name };
        } else if (connEl) {
            this.selectedConnection = connectionOfElement(connEl);
            this.store.select([]);
            what = { kind: 'connection', ...this.selectedConnection, at: scene };
        } else {
            what = { kind: 'canvas', at: scene };
        }
        if (what.kind !== 'connection' && this.selectedConnection) {
            this.selectedConnection = null;
            this.render();
        }
        this.callbacks.onContextMenu(what, client);
    }

    /**
     * What the keyboard's menu key (Shift+F10) opens a menu on, and where: the selected line or
     * component, else the canvas at its middle.
     */
    contextTargetOfSelection(): { target: CanvasTarget; client: Point } {
        const r = this.svg.getBoundingClientRect();
        const middle = { x: r.left + r.width / 2, y: r.top + r.height / 2 };
        const inside = (p: Point) => ({ x: Math.min(Math.max(p.x, r.left), r.right), y: Math.min(Math.max(p.y, r.top), r.bottom) });
        const line = this.selectedConnection;
        if (line) {
            const system = this.store.system;
            const a = this.portPoint(system, line.from);
            const b = this.portPoint(system, line.to);
            const mid = a && b ? { x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 } : this.sceneFromClient(middle.x, middle.y);
            return { target: { kind: 'connection', ...line, at: mid }, client: inside(this.clientFromScene(mid)) };
        }
        const chosen = this.store.system.components.find((c) => this.store.selection.has(c.name));
        if (chosen) return { target: { kind: 'component', name: chosen.name }, client: inside(this.clientFromScene(this.poseOf(chosen))) };
        return { target: { kind: 'canvas', at: this.sceneFromClient(middle.x, middle.y) }, client: middle };
    }

    private onWheel(e: WheelEvent): void {
        e.preventDefault();
        this.zoomBy(Math.exp(-e.deltaY * 0.0015), { x: e.clientX, y: e.clientY });
    }
}
