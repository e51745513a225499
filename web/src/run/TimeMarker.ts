// A vertical line at one time over a uPlot chart: the playback cursor, at the instant the
// animated diagram shows. A positioned element over the chart, moved without redrawing it.
import type uPlot from 'uplot';

export class TimeMarker {
    private readonly line: HTMLDivElement;
    private time: number | null = null;
    private plot: uPlot | null = null;

    constructor() {
        this.line = document.createElement('div');
        this.line.className = 'playback-cursor';
        this.line.dataset.testid = 'playback-cursor';
        this.line.hidden = true;
    }

    /** The time to mark (null: none). */
    set(time: number | null): void {
        this.time = time;
        if (this.plot) this.place(this.plot);
    }

    /** Puts the line on `u` at the time (after each draw: zoom, new data, a new chart). */
    place(u: uPlot): void {
        this.plot = u;
        if (this.line.parentElement !== u.over) u.over.append(this.line);
        const x = this.time === null ? NaN : u.valToPos(this.time, 'x');
        const inside = Number.isFinite(x) && x >= 0 && x <= u.over.clientWidth;
        this.line.hidden = !inside;
        if (inside) {
            this.line.style.transform = `translateX(${x.toFixed(1)}px)`;
            this.line.dataset.time = String(this.time);
        }
    }
}
