// Hopsan's animation mode on our drawing: hydraulic lines coloured by their pressure (with the
// scale over the canvas), dashes running along them with the flow, and the moving parts of
// animated components (partDrawings.ts). Driven by values by variable name, from a recorded
// run (playback) or a live session. Everything is drawn in groups of its own over the editor's
// drawing and updated in place per frame (attributes, never new elements); clear() removes it.
import type { CanvasView } from '../editor/CanvasView';
import type { EditorStore } from '../editor/EditorStore';
import { boundVariables, diagramBindings, parameterValue, type ComponentBinding, type DiagramBindings, type LineBinding } from './diagramBindings';
import { movableState } from './movableState';
import { partDrawing, type PartDrawing } from './partDrawings';
import { PressureRange } from './pressureScale';
import { ColourScale } from './ColourScale';
import { s } from '../ui/dom';
import './animation.css';

/** Dash pattern along a line and its speed at the largest flow seen, in scene px per second. */
const DASHES = '5 9';
const DASH_PERIOD = 14;
const DASH_SPEED = 40;
/** Flows under this share of the largest seen show no dashes (a still line). */
const STILL_FLOW = 0.01;

/** A part's drawing, and the matrix from its group's frame to the scene's (for the lines on its moving ports). */
interface DrawnParts { binding: ComponentBinding; drawing: PartDrawing; toScene: DOMMatrix | null }
/** A line end on a port that moves with a part. */
interface MovingEnd { parts: DrawnParts; port: string }
/**
 * A line drawn over the editor's: a hydraulic one (`binding`) coloured by pressure with its flow
 * dashes, or another whose end moves with a part. `base` is the editor's path, `original` its
 * line (hidden while an end of ours moves away from it).
 */
interface DrawnLine {
    binding: LineBinding | null; line: SVGPolylineElement; dashes: SVGPolylineElement | null; original: SVGPolylineElement;
    base: [number, number][]; from: MovingEnd | null; to: MovingEnd | null; points: string;
    colour: string; offset: number; moving: boolean;
}

export class DiagramAnimation {
    /** The colour range of the line pressures (adjustable by the user on the scale). */
    readonly range = new PressureRange();
    private bindings: DiagramBindings | null = null;
    private boundKey = '';
    private lines: DrawnLine[] = [];
    private parts: DrawnParts[] = [];
    private layer: SVGGElement | null = null;
    private readonly scale: ColourScale;
    /** The largest flow seen (m³/s): the dashes' full speed. */
    private flowMax = 0;
    private lastShow = 0;
    private lastValues: ReadonlyMap<string, number> = new Map();

    constructor(private readonly canvas: CanvasView, private readonly store: EditorStore) {
        this.scale = new ColourScale(this.range, () => this.show(this.lastValues));
    }

    /** Names, as job results and live.start name them (Comp#Port#Var), whose values the diagram needs. */
    variables(): string[] {
        return boundVariables(this.bound());
    }

    /** Draws the diagram at one instant; names missing from `values` leave their part at rest. */
    show(values: ReadonlyMap<string, number>): void {
        this.lastValues = values;
        this.bind();
        const now = performance.now();
        const dt = this.lastShow > 0 ? Math.min(0.1, (now - this.lastShow) / 1000) : 0;
        this.lastShow = now;
        for (const { binding } of this.lines) {
            if (!binding) continue;
            const p = values.get(binding.pressure);
            if (p !== undefined) this.range.see(p);
            const q = binding.flow ? values.get(binding.flow) : undefined;
            if (q !== undefined && Math.abs(q) > this.flowMax) this.flowMax = Math.abs(q);
        }
        const pressureColour = (p: number) => this.range.colour(p);
        for (const { binding, drawing } of this.parts) {
            const data = binding.data.map((names) => names.map((n) => (n ? values.get(n) : undefined)));
            const states = binding.description.movables.map((m, i) =>
                movableState(m, (k) => data[i][k], (name) => parameterValue(binding.parameters, name)));
            drawing.update({ states, values: data, pressureColour });
        }
        for (const l of this.lines) {
            if (l.from || l.to) this.moveEnds(l);
            if (l.binding) this.drawLine(l, l.binding, values, dt);
        }
        this.scale.update();
    }

    /** Leaves animation: the drawing is the editor's again. */
    clear(): void {
        this.unbind();
        this.scale.element.remove();
        this.bindings = null;
        this.boundKey = '';
        this.lastShow = 0;
        // the next run or session starts with the ranges of what it shows
        this.range.set(0, 0, true);
        this.flowMax = 0;
    }

    private drawLine(l: DrawnLine, binding: LineBinding, values: ReadonlyMap<string, number>, dt: number): void {
        const p = values.get(binding.pressure);
        // without a pressure the line keeps the editor's colour
        const colour = p === undefined ? (l.original.getAttribute('stroke') ?? 'none') : this.range.colour(p);
        if (colour !== l.colour) l.line.setAttribute('stroke', (l.colour = colour));
        const q = binding.flow ? values.get(binding.flow) : undefined;
        const share = q === undefined || this.flowMax === 0 ? 0 : q / this.flowMax;
        const moving = Math.abs(share) >= STILL_FLOW;
        if (moving !== l.moving) l.dashes?.setAttribute('visibility', (l.moving = moving) ? 'visible' : 'hidden');
        if (!moving) return;
        // the dashes run from `from` to `to` for a positive share times the binding's sign
        l.offset = (l.offset - binding.sign * share * DASH_SPEED * dt) % DASH_PERIOD;
        l.dashes?.setAttribute('stroke-dashoffset', l.offset.toFixed(2));
    }

    /** Moves a line's ends with the ports they are on (the corners stay, as in the editor). */
    private moveEnds(l: DrawnLine): void {
        const shift = (end: MovingEnd | null): [number, number] => {
            const local = end?.parts.drawing.portShift(end.port);
            const m = end?.parts.toScene;
            return local && m ? [m.a * local[0] + m.c * local[1], m.b * local[0] + m.d * local[1]] : [0, 0];
        };
        const [a, b] = [shift(l.from), shift(l.to)];
        const last = l.base.length - 1;
        const points = l.base.map(([x, y], i) => {
            const [dx, dy] = i === 0 ? a : i === last ? b : [0, 0];
            return `${(x + dx).toFixed(2)},${(y + dy).toFixed(2)}`;
        }).join(' ');
        if (points === l.points) return;
        l.points = points;
        l.line.setAttribute('points', points);
        l.dashes?.setAttribute('points', points);
    }

    private bound(): DiagramBindings {
        const key = `${this.store.generation} ${this.store.path.join('$')}`;
        if (!this.bindings || key !== this.boundKey) {
            this.unbind();
            this.bindings = diagramBindings(this.store.model, this.store.path);
            this.boundKey = key;
        }
        return this.bindings;
    }

    /** Draws the groups over the editor's drawing, again when the editor has drawn anew (another system, a reloaded model). */
    private bind(): void {
        const before = this.bindings;
        const bindings = this.bound();
        const stale = this.layer === null || !this.layer.isConnected || before !== bindings
            || this.parts.some((p) => !p.drawing.element.isConnected) || this.lines.some((l) => !l.original.isConnected);
        if (!stale) return;
        this.unbind();
        const svg = this.canvas.element.querySelector<SVGSVGElement>('svg.canvas');
        const connections = svg?.querySelector(':scope > .world > .connections');
        if (!svg || !connections) return;
        const world = svg.querySelector<SVGGElement>(':scope > .world')!;
        for (const binding of bindings.components) {
            const icon = svg.querySelector<SVGGElement>(`.components > .component[data-name="${CSS.escape(binding.name)}"] > .component-body > .icon`);
            const layout = this.canvas.layouts.get(binding.name);
            if (!icon || !layout) continue;
            const drawing = partDrawing(binding.type, binding.description, icon, layout.halfWidth, layout.halfHeight);
            if (!drawing) continue;
            drawing.element.dataset.component = binding.name;
            // (no matrices without a layout engine: lines then keep their ends)
            const parts = drawing.element.getCTM?.();
            const scene = world.getCTM?.();
            this.parts.push({ binding, drawing, toScene: parts && scene ? scene.inverse().multiply(parts) : null });
        }
        const movingEnd = (ref: { component: string; port: string }): MovingEnd | null => {
            const parts = this.parts.find((p) => p.binding.name === ref.component);
            const moves = parts?.binding.description.movables.some((m) => m.movingPorts?.some((x) => x.port === ref.port));
            return parts && moves ? { parts, port: ref.port } : null;
        };
        const layer = s('g', { class: 'animation-lines' });
        const hydraulic = new Map(bindings.lines.map((b) => [b.connection, b]));
        for (const original of connections.querySelectorAll<SVGPolylineElement>('polyline.connection')) {
            const [from, to] = [original.dataset.from!, original.dataset.to!].map((text) =>
                ({ component: text.slice(0, text.lastIndexOf('.')), port: text.slice(text.lastIndexOf('.') + 1) }));
            const connection = this.store.system.connections.find((c) =>
                c.from.component === from.component && c.from.port === from.port && c.to.component === to.component && c.to.port === to.port);
            const binding = connection ? hydraulic.get(connection) ?? null : null;
            const ends = [movingEnd(from), movingEnd(to)];
            if (!binding && !ends[0] && !ends[1]) continue;
            const points = original.getAttribute('points') ?? '';
            const base = points.trim().split(/\s+/).map((p) => p.split(',').map(Number) as [number, number]);
            const attributes = { points, 'data-from': original.dataset.from, 'data-to': original.dataset.to };
            const line = binding ? s('polyline', { class: 'animated-line', stroke: 'none', ...attributes })
                : s('polyline', { class: `moved-line ${original.classList.contains('signal') ? 'signal' : 'power'}`, stroke: original.getAttribute('stroke'), ...attributes });
            const dashes = binding ? s('polyline', { class: 'flow-dashes', 'stroke-dasharray': DASHES, visibility: 'hidden', ...attributes }) : null;
            layer.append(line, ...(dashes ? [dashes] : []));
            // a line whose end moves away would leave the editor's line behind
            if (ends[0] || ends[1]) original.style.visibility = 'hidden';
            this.lines.push({ binding, line, dashes, original, base, from: ends[0], to: ends[1], points, colour: '', offset: 0, moving: false });
        }
        connections.after(layer);
        this.layer = layer;
        svg.classList.add('animating');
        if (!this.scale.element.isConnected) this.canvas.element.append(this.scale.element);
    }

    private unbind(): void {
        this.layer?.remove();
        this.layer = null;
        for (const l of this.lines) l.original.style.visibility = '';
        for (const p of this.parts) p.drawing.remove();
        this.parts = [];
        this.lines = [];
        this.canvas.element.querySelector('svg.canvas')?.classList.remove('animating');
    }
}
