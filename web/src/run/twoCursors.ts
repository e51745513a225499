// Two cursors, A and B, on a time plot (Hopsan's "delta" markers): vertical lines the user drags
// (or moves with ← → once focused); the read-out gives both times and Δt = tB − tA, and each
// legend row gains the curve's Δvalue = y(tB) − y(tA), in the unit of its axis.
import type uPlot from 'uplot';
import { h } from '../ui/dom';

type Ys = ArrayLike<number | null | undefined>;

/**
 * The value of a curve at time `t`, between the samples around it. A curve of another run has
 * gaps where the aligned data holds the other run's times, so the nearest real samples count.
 */
export function valueAt(xs: ArrayLike<number>, ys: Ys, t: number): number | null {
    let lo = 0;
    let hi = xs.length;
    while (lo < hi) {
        const mid = (lo + hi) >> 1;
        if (xs[mid] < t) lo = mid + 1; else hi = mid;
    }
    const valid = (i: number) => typeof ys[i] === 'number' && Number.isFinite(ys[i]);
    let right = lo;
    while (right < xs.length && !valid(right)) ++right;
    let left = Math.min(lo, xs.length) - 1;
    while (left >= 0 && !valid(left)) --left;
    const r = right < xs.length ? ys[right] as number : null;
    const l = left >= 0 ? ys[left] as number : null;
    if (r !== null && xs[right] === t) return r;
    if (l === null || r === null) return l ?? r;
    return l + (r - l) * (t - xs[left]) / (xs[right] - xs[left]);
}

/** Times as the read-out shows them: six significant digits, in seconds. */
export function secondsText(t: number): string {
    return `${Number(t.toPrecision(6))} s`;
}

export class TwoCursors {
    /** "A … B … Δt …", shown while the cursors are on. */
    readonly readout: HTMLElement;
    private on = false;
    /** tA and tB; placed at a third and two thirds of the shown time when switched on. */
    private times: [number, number] | null = null;
    private plot: uPlot | null = null;
    private readonly lines: HTMLElement[];

    /**
     * `rows` are the legend's rows, one per series (time first); `format` writes a difference of
     * series `i` in the unit of its axis.
     */
    constructor(private readonly rows: () => HTMLElement[], private readonly format: (i: number, delta: number) => string) {
        this.readout = h('div', { class: 'delta-readout', 'data-testid': 'delta-readout', hidden: true });
        this.lines = ['A', 'B'].map((name, i) => h('div', {
                class: 'delta-cursor', 'data-cursor': name, role: 'slider', tabindex: 0, 'aria-label': `Cursor ${name}`,
                onpointerdown: (e: PointerEvent) => this.grab(e, i),
                onpointermove: (e: PointerEvent) => this.drag(e, i),
                onkeydown: (e: KeyboardEvent) => this.nudge(e, i),
            }, h('span', { class: 'delta-tag' }, name)));
    }

    get shown(): boolean { return this.on; }

    toggle(): void {
        this.on = !this.on;
        if (!this.on) {
            this.times = null;
            for (const line of this.lines) line.remove();
            for (const row of this.rows()) row.querySelector('.delta')?.remove();
            this.readout.hidden = true;
        }
        if (this.plot) this.draw(this.plot);
    }

    /** Places the lines and writes the differences; the chart calls it after every redraw. */
    draw(u: uPlot): void {
        this.plot = u;
        if (!this.on) return;
        const xs = u.data[0];
        const min = u.scales.x.min ?? xs[0];
        const max = u.scales.x.max ?? xs[xs.length - 1];
        if (min === undefined || max === undefined) return;
        this.times ??= [min + (max - min) / 3, min + 2 * (max - min) / 3];
        const [ta, tb] = this.times;
        this.lines.forEach((line, i) => {
            const t = this.times![i];
            if (line.parentNode !== u.over) u.over.append(line);
            line.hidden = t < min || t > max;
            line.style.left = `${u.valToPos(t, 'x')}px`;
            line.setAttribute('aria-valuenow', String(t));
            line.setAttribute('aria-valuetext', secondsText(t));
        });
        this.readout.hidden = false;
        this.readout.textContent = `A ${secondsText(ta)} · B ${secondsText(tb)} · Δt ${secondsText(tb - ta)}`;
        this.rows().forEach((row, i) => {
            const cell = row.querySelector<HTMLElement>('.delta') ?? row.appendChild(h('td', { class: 'delta' }));
            if (i === 0) {
                cell.textContent = 'Δ B−A';
                return;
            }
            const a = valueAt(xs, u.data[i], ta);
            const b = valueAt(xs, u.data[i], tb);
            cell.textContent = a === null || b === null ? 'Δ --' : `Δ ${this.format(i, b - a)}`;
            cell.title = a === null || b === null ? '' : `A: ${this.format(i, a)}, B: ${this.format(i, b)}`;
        });
    }

    private grab(e: PointerEvent, i: number): void {
        if (e.button !== 0) return;
        // not the chart's drag-to-zoom (a cancelled pointerdown sends no mousedown)
        e.preventDefault();
        e.stopPropagation();
        this.lines[i].setPointerCapture(e.pointerId);
        this.lines[i].focus();
    }

    private drag(e: PointerEvent, i: number): void {
        const u = this.plot;
        if (!u || !this.lines[i].hasPointerCapture(e.pointerId)) return;
        this.move(i, u.posToVal(e.clientX - u.over.getBoundingClientRect().left, 'x'));
    }

    // ← → move a hundredth of the shown time, with Shift a tenth
    private nudge(e: KeyboardEvent, i: number): void {
        const u = this.plot;
        if (!u || !this.times || (e.key !== 'ArrowLeft' && e.key !== 'ArrowRight') || e.ctrlKey || e.metaKey) return;
        e.preventDefault();
        e.stopPropagation();
        const span = (u.scales.x.max ?? 0) - (u.scales.x.min ?? 0);
        this.move(i, this.times[i] + (e.key === 'ArrowLeft' ? -1 : 1) * span * (e.shiftKey ? 0.1 : 0.01));
    }

    private move(i: number, t: number): void {
        const u = this.plot!;
        const min = u.scales.x.min ?? t;
        const max = u.scales.x.max ?? t;
        this.times![i] = Math.min(max, Math.max(min, t));
        this.draw(u);
    }
}
