// The live controls drawn on the canvas, in the drawing's coordinates (they pan and zoom with
// it, as Hopsan's widgets do). In edit mode they are inert: their handle moves them, ✎ changes
// and × removes them (undoable edits of the model). In live mode they act: every movement
// sends the value; a control bound to something the running model cannot change says so.
import type { EditorStore } from '../editor/EditorStore';
import type { Point } from '../model/geometry';
import { h, s } from '../ui/dom';
import { ChangeLiveControls } from './ChangeLiveControls';
import { controlWidget, type ControlWidget } from './controlWidgets';
import { controlsOf, modelValueOf, withinBounds, type LiveBounds, type LiveControl } from './liveControls';

/** The control's box in drawing units (its top centre is at the control's x, y). */
const WIDTH = 150;
const HEIGHT = 58;

export interface LiveControlsState {
    /** What live.set may change in the running session. */
    liveNames: ReadonlySet<string>;
    /** Controls live mode adds on its own (interactive component types), not saved. */
    defaults: LiveControl[];
    /** The value each control starts from. */
    values: ReadonlyMap<string, number>;
    /** Bounds of live values (an assignment's locked copy): the controls keep within them. */
    bounds?: ReadonlyMap<string, LiveBounds>;
}

export interface LiveControlActions {
    /** A live control was moved by the user (live mode only). */
    set(name: string, value: number): void;
    /** ✎ on a saved control: change it (index into the model's controls). */
    edit(index: number): void;
    /** Whether the model may be changed here (a locked copy: its controls stay where they are). */
    editable(): boolean;
    error(e: unknown): void;
}

export class LiveControlLayer {
    readonly element: SVGGElement = s('g', { class: 'live-controls' });
    private live: LiveControlsState | null = null;
    private drawnKey = '';
    private readonly widgets = new Map<string, ControlWidget[]>();
    private readonly unsubscribe: () => void;

    constructor(private readonly store: EditorStore, private readonly canvas: { sceneFromClient(x: number, y: number): Point },
        private readonly actions: LiveControlActions) {
        // presses on a control are the control's, not the canvas's (no selecting, panning, menu)
        for (const type of ['pointerdown', 'dblclick', 'contextmenu'] as const) {
            this.element.addEventListener(type, (e) => e.stopPropagation());
        }
        this.unsubscribe = store.subscribe(() => this.render());
        this.render();
    }

    dispose(): void { this.unsubscribe(); }

    /** Live mode (controls act) or edit mode (null). */
    setLive(live: LiveControlsState | null): void {
        this.live = live;
        this.render();
    }

    render(): void {
        const saved = controlsOf(this.store.model);
        const here = (c: LiveControl) => c.path.join('$') === this.store.path.join('$');
        const shown = [...saved.map((c, index) => ({ c, index })), ...(this.live?.defaults ?? []).map((c) => ({ c, index: -1 }))].filter(({ c }) => here(c));
        // redrawn only when what is shown changes: not on a selection click, not during a drag of a slider
        const key = JSON.stringify([shown, this.live ? [...this.live.liveNames] : null, this.actions.editable()]);
        if (key === this.drawnKey) return;
        this.drawnKey = key;
        this.widgets.clear();
        this.element.replaceChildren(...shown.map(({ c, index }) => this.draw(c, index, saved)));
    }

    private draw(c: LiveControl, index: number, saved: LiveControl[]): SVGGElement {
        const live = this.live;
        const settable = live !== null && live.liveNames.has(c.name);
        const widget = controlWidget(withinBounds(c, live?.bounds?.get(c.name)), (v) => {
            // other controls of the same value follow this one
            for (const other of this.widgets.get(c.name) ?? []) if (other !== widget) other.show(v);
            this.actions.set(c.name, v);
        });
        widget.setEnabled(settable);
        widget.show(live?.values.get(c.name) ?? modelValueOf(this.store.model, c.name) ?? c.min);
        this.widgets.set(c.name, [...(this.widgets.get(c.name) ?? []), widget]);
        const editing = live === null && index >= 0 && this.actions.editable();
        const title = live === null ? `${c.name}: acts in live mode` : settable ? c.name : `${c.name} cannot change while the model runs`;
        const handle = h('span', { class: 'live-control-name', title }, c.name);
        const box = h('div', {
            class: `live-control${live ? ' live' : ''}${live && !settable ? ' unavailable' : ''}${index < 0 ? ' default' : ''}`,
            'data-testid': 'live-control', 'data-name': c.name, 'data-kind': c.kind,
        }, h('div', { class: 'live-control-head' }, handle,
            editing ? h('button', { class: 'live-control-edit', title: 'Change this control', 'aria-label': `Change the control of ${c.name}`, onclick: () => this.actions.edit(index) }, '✎') : '',
            editing ? h('button', { class: 'live-control-remove', title: 'Remove this control', 'aria-label': `Remove the control of ${c.name}`, onclick: () => this.remove(saved, index) }, '×') : ''),
        widget.element);
        const object = s('foreignObject', { x: -WIDTH / 2, y: 0, width: WIDTH, height: HEIGHT });
        object.append(box);
        const g = s('g', { class: 'live-control-place', transform: `translate(${c.x},${c.y})` }, object);
        if (editing) this.makeMovable(handle, g, c, index, saved);
        return g;
    }

    /** Dragging the name moves the control; the move is one edit when the pointer is let go. */
    private makeMovable(handle: HTMLElement, g: SVGGElement, c: LiveControl, index: number, saved: LiveControl[]): void {
        handle.classList.add('movable');
        let start: Point | null = null;
        let at = { x: c.x, y: c.y };
        handle.addEventListener('pointerdown', (e) => {
            if (e.button !== 0) return;
            start = this.canvas.sceneFromClient(e.clientX, e.clientY);
            handle.setPointerCapture(e.pointerId);
        });
        handle.addEventListener('pointermove', (e) => {
            if (!start) return;
            const p = this.canvas.sceneFromClient(e.clientX, e.clientY);
            at = { x: c.x + p.x - start.x, y: c.y + p.y - start.y };
            g.setAttribute('transform', `translate(${at.x},${at.y})`);
        });
        handle.addEventListener('pointerup', () => {
            if (!start) return;
            start = null;
            if (at.x === c.x && at.y === c.y) return;
            const next = saved.map((x, i) => (i === index ? { ...x, ...at } : x));
            this.store.execute(new ChangeLiveControls(next, 'Move live control')).catch((e) => this.actions.error(e));
        });
    }

    private remove(saved: LiveControl[], index: number): void {
        const next = saved.filter((_, i) => i !== index);
        this.store.execute(new ChangeLiveControls(next, 'Remove live control')).catch((e) => this.actions.error(e));
    }
}
