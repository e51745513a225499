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

interface DrawnLine { binding: LineBinding; line: SVGPolylineElement; dashes: SVGPolylineElement; colour: string; offset: number; moving: boolean }
interface DrawnParts { binding: ComponentBinding; drawing: PartDrawing }

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
        for (const l of this.lines) {
            const p = values.get(l.binding.pressure);
            if (p !== undefined) this.range.see(p);
            const q = l.binding.flow ? values.get(l.binding.flow) : undefined;
            if (q !== undefined && Math.abs(q) > this.flowMax) this.flowMax = Math.abs(q);
        }
        for (const l of this.lines) this.drawLine(l, values, dt);
        const pressureColour = (p: number) => this.range.colour(p);
        for (const { binding, drawing } of this.parts) {
            const data = binding.data.map((names) => names.map((n) => (n ? values.get(n) : undefined)));
            const states = binding.description.movables.map((m, i) =>
                movableState(m, (k) => data[i][k], (name) => parameterValue(binding.parameters, name)));
            drawing.update({ states, values: data, pressureColour });
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
    }

    private drawLine(l: DrawnLine, values: ReadonlyMap<string, number>, dt: number): void {
        const p = values.get(l.binding.pressure);
        const colour = p === undefined ? 'none' : this.range.colour(p);
        if (colour !== l.colour) l.line.setAttribute('stroke', (l.colour = colour));
        const q = l.binding.flow ? values.get(l.binding.flow) : undefined;
        const share = q === undefined || this.flowMax === 0 ? 0 : q / this.flowMax;
        const moving = Math.abs(share) >= STILL_FLOW;
        if (moving !== l.moving) l.dashes.setAttribute('visibility', (l.moving = moving) ? 'visible' : 'hidden');
        if (!moving) return;
        // the dashes run from `from` to `to` for a positive share times the binding's sign
        l.offset = (l.offset - l.binding.sign * share * DASH_SPEED * dt) % DASH_PERIOD;
        l.dashes.setAttribute('stroke-dashoffset', l.offset.toFixed(2));
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
            || this.parts.some((p) => !p.drawing.element.isConnected);
        if (!stale) return;
        this.unbind();
        const svg = this.canvas.element.querySelector<SVGSVGElement>('svg.canvas');
        const connections = svg?.querySelector(':scope > .world > .connections');
        if (!svg || !connections) return;
        const editorLines = [...connections.querySelectorAll<SVGPolylineElement>('polyline.connection')];
        const layer = s('g', { class: 'animation-lines' });
        for (const binding of bindings.lines) {
            const { from, to } = binding.connection;
            const drawn = editorLines.find((el) => el.dataset.from === `${from.component}.${from.port}` && el.dataset.to === `${to.component}.${to.port}`);
            if (!drawn) continue;
            const points = drawn.getAttribute('points') ?? '';
            const ends = { 'data-from': `${from.component}.${from.port}`, 'data-to': `${to.component}.${to.port}` };
            const line = s('polyline', { class: 'animated-line', points, stroke: 'none', ...ends });
            const dashes = s('polyline', { class: 'flow-dashes', points, 'stroke-dasharray': DASHES, visibility: 'hidden', ...ends });
            layer.append(line, dashes);
            this.lines.push({ binding, line, dashes, colour: 'none', offset: 0, moving: false });
        }
        connections.after(layer);
        this.layer = layer;
        for (const binding of bindings.components) {
            const icon = svg.querySelector<SVGGElement>(`.components > .component[data-name="${CSS.escape(binding.name)}"] > .component-body > .icon`);
            const layout = this.canvas.layouts.get(binding.name);
            if (!icon || !layout) continue;
            const drawing = partDrawing(binding.type, binding.description, icon, layout.halfWidth, layout.halfHeight);
            if (drawing) {
                drawing.element.dataset.component = binding.name;
                this.parts.push({ binding, drawing });
            }
        }
        svg.classList.add('animating');
        if (!this.scale.element.isConnected) this.canvas.element.append(this.scale.element);
    }

    private unbind(): void {
        this.layer?.remove();
        this.layer = null;
        for (const p of this.parts) p.drawing.remove();
        this.parts = [];
        this.lines = [];
        this.canvas.element.querySelector('svg.canvas')?.classList.remove('animating');
    }
}
