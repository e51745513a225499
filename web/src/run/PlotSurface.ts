// Where a uPlot chart lives in a window: a box sized by the window alone (the chart is
// absolutely placed inside, so it cannot push its box larger) and, beside it, a column with the
// legend (one compact row per curve, scrolling when long) under an optional read-out. Without
// that split, a growing legend grew the window without end or squeezed the graph to nothing.
import uPlot from 'uplot';
import { downloadBlob, h } from '../ui/dom';

export interface LegendEntry { label: string; colour: string; dashed: boolean }

export class PlotSurface {
    readonly element: HTMLElement;
    private readonly canvasBox: HTMLElement;
    private readonly legendBox: HTMLElement;
    private observer: ResizeObserver;
    plot: uPlot | null = null;

    /**
     * The legend goes under the chart, or `beside` it for many curves; `aside` is shown above
     * the legend (the two cursors' read-out).
     */
    constructor(options: { beside?: boolean; aside?: HTMLElement } = {}) {
        this.canvasBox = h('div', { class: 'plot-canvas' });
        this.legendBox = h('div', { class: 'plot-legend' });
        this.element = h('div', { class: options.beside ? 'plot-surface legend-beside' : 'plot-surface' },
            this.canvasBox, h('div', { class: 'plot-side' }, options.aside, this.legendBox));
        this.observer = this.observe();
    }

    // An observer reports only the sizes of its own page's layout: one made by this page does
    // not see the box once it has moved to another browser window (a detached plot).
    private observe(): ResizeObserver {
        const view = (this.canvasBox.ownerDocument.defaultView ?? window) as typeof window;
        const observer = new view.ResizeObserver(() => this.resize());
        observer.observe(this.canvasBox);
        return observer;
    }

    /** The surface has moved to another document: watch its size there. */
    moved(): void {
        this.observer.disconnect();
        this.observer = this.observe();
        this.resize();
    }

    /** The legend's rows, one per series (the first is time), in series order. */
    legendRows(): HTMLElement[] {
        return [...this.legendBox.querySelectorAll<HTMLElement>('.u-series')];
    }

    /** A new chart; `options` without size and legend mount, which the surface supplies. */
    draw(options: Omit<uPlot.Options, 'width' | 'height'>, data: uPlot.AlignedData): uPlot {
        this.clear();
        const legend = { ...options.legend, mount: (_u: uPlot, el: HTMLElement) => this.legendBox.append(el) };
        this.plot = new uPlot({ ...options, ...this.size(), legend }, data, this.canvasBox);
        // a long name is cut short in the narrow legend: the whole of it shows on hover
        for (const label of this.legendBox.querySelectorAll<HTMLElement>('.u-label')) label.title = label.textContent ?? '';
        return this.plot;
    }

    clear(): void {
        this.plot?.destroy();
        this.plot = null;
        this.canvasBox.replaceChildren();
        this.legendBox.replaceChildren();
    }

    private size(): { width: number; height: number } {
        return { width: Math.max(100, this.canvasBox.clientWidth), height: Math.max(80, this.canvasBox.clientHeight) };
    }

    private resize(): void {
        if (!this.plot) return;
        const size = this.size();
        if (size.width !== this.plot.width || size.height !== this.plot.height) this.plot.setSize(size);
    }

    /** The chart as PNG with its legend drawn under it. */
    exportPng(filename: string, entries: LegendEntry[]): void {
        const u = this.plot;
        if (!u) return;
        const source = u.ctx.canvas;
        const dpr = devicePixelRatio || 1;
        const legend = 22 * dpr * entries.length;
        const out = document.createElement('canvas');
        out.width = source.width;
        out.height = source.height + legend + 10 * dpr;
        const ctx = out.getContext('2d')!;
        ctx.fillStyle = '#fff';
        ctx.fillRect(0, 0, out.width, out.height);
        ctx.drawImage(source, 0, 0);
        ctx.font = `${12 * dpr}px sans-serif`;
        entries.forEach((e, i) => {
            ctx.fillStyle = e.colour;
            ctx.fillText(`${e.dashed ? '- - ' : '—— '}${e.label}`, 10 * dpr, source.height + (18 + i * 22) * dpr);
        });
        out.toBlob((blob) => { if (blob) downloadBlob(filename, blob); });
    }

    destroy(): void {
        this.observer.disconnect();
        this.clear();
    }
}
