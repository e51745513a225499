// One plot window: chosen variables of the current run (and the previous one to compare),
// live while the run goes on; zoom by dragging, cursor read-out in the legend, CSV and PNG.
import uPlot from 'uplot';
import { alignSeries, toCsv, type RunData, type SeriesSource } from './RunData';
import { variableLabel } from '../model/variables';
import { downloadText, h } from '../ui/dom';
import { PlotSurface } from './PlotSurface';
import type { AnalysisKind } from './AnalysisWindow';

const COLOURS = ['#1f6fd1', '#d1421f', '#2e8b3d', '#8a4fbf', '#d17a00', '#0f9a9a', '#b8336a', '#555555'];

interface Plotted { name: string; label: string; source: SeriesSource; previous: boolean; colour: string }

export class PlotWindow {
    readonly element: HTMLElement;
    readonly variables: string[] = [];
    /** What the user clicked to get each variable, to name its curve. */
    private readonly labels = new Map<string, string>();
    compare = false;
    private readonly body: HTMLElement;
    private readonly surface = new PlotSurface();
    private readonly chips: HTMLElement;
    private readonly compareBox: HTMLInputElement;
    private get plot(): uPlot | null { return this.surface.plot; }
    private seriesKey = '';
    private plotted: Plotted[] = [];
    /** x range to show while a run is filling the plot. */
    private span: [number, number] | null = null;

    constructor(readonly id: number, private readonly actions: {
        close(w: PlotWindow): void; activate(w: PlotWindow): void; changed(w: PlotWindow): void;
        analyse(w: PlotWindow, kind: AnalysisKind): void;
    }) {
        this.body = h('div', { class: 'plot-body' }, this.emptyNote('Click a port to plot its variables here.'));
        this.chips = h('div', { class: 'plot-chips' });
        this.compareBox = h('input', {
            type: 'checkbox', name: 'compare',
            onchange: () => { this.compare = this.compareBox.checked; this.actions.changed(this); },
        });
        this.element = h('section', { class: 'plot-window', 'data-plot-id': String(id), onpointerdown: () => this.actions.activate(this) },
            h('header', { class: 'plot-header' },
                h('strong', {}, `Plot ${id}`), this.chips,
                h('label', { class: 'compare', title: 'Show the previous run dashed' }, this.compareBox, 'compare with previous run'),
                h('button', { class: 'small', onclick: () => this.actions.analyse(this, 'fft'), title: 'Amplitude spectrum of a plotted variable' }, 'FFT'),
                h('button', { class: 'small', onclick: () => this.actions.analyse(this, 'bode'), title: 'Gain and phase of one plotted variable against another' }, 'Bode'),
                h('button', { class: 'small', onclick: () => this.exportCsv(), title: 'Export the plotted data as CSV' }, 'CSV'),
                h('button', { class: 'small', onclick: () => this.exportPng(), title: 'Save the plot as PNG' }, 'PNG'),
                h('button', { class: 'small', onclick: () => this.actions.close(this), title: 'Close', 'aria-label': 'Close plot' }, '×')),
            this.body);
    }

    private emptyNote(text: string): HTMLElement {
        return h('p', { class: 'muted plot-empty' }, text);
    }

    setActive(active: boolean): void { this.element.classList.toggle('active', active); }

    add(name: string, label?: string): void {
        if (this.variables.includes(name)) return;
        this.variables.push(name);
        if (label) this.labels.set(name, label);
        this.drawChips();
    }

    remove(name: string): void {
        const i = this.variables.indexOf(name);
        if (i >= 0) this.variables.splice(i, 1);
        this.labels.delete(name);
        this.drawChips();
        this.actions.changed(this);
    }

    private drawChips(): void {
        this.chips.replaceChildren(...this.variables.map((v) => h('span', { class: 'chip', 'data-variable': v },
            this.labelOf(v), h('button', { class: 'chip-x', 'aria-label': `Remove ${v}`, onclick: () => this.remove(v) }, '×'))));
    }

    labelOf(name: string): string { return this.labels.get(name) ?? variableLabel(name); }

    /** Redraws with the runs' current data. */
    update(current: RunData | null, previous: RunData | null): void {
        const plotted: Plotted[] = [];
        this.variables.forEach((name, i) => {
            const colour = COLOURS[i % COLOURS.length];
            const col = current?.columns.get(name);
            if (current && col) plotted.push({ name, label: this.labelOf(name), source: { time: current.time, data: col }, previous: false, colour });
            const old = previous?.columns.get(name);
            if (this.compare && previous && old) {
                plotted.push({ name, label: `${this.labelOf(name)} (run ${previous.jobId})`, source: { time: previous.time, data: old }, previous: true, colour });
            }
        });
        this.plotted = plotted;
        this.span = current && !current.finished ? current.span : null;
        this.element.dataset.job = current ? String(current.jobId) : '';
        this.element.dataset.state = current?.state ?? '';
        if (plotted.length === 0) {
            this.surface.clear();
            this.seriesKey = '';
            this.element.dataset.points = '0';
            this.body.replaceChildren(this.emptyNote(this.variables.length ? 'No data yet: run the model.' : 'Click a port to plot its variables here.'));
            return;
        }
        const data = alignSeries(plotted.map((p) => p.source));
        this.element.dataset.points = String(data[0].length);
        const key = plotted.map((p) => p.label).join('|');
        if (!this.plot || key !== this.seriesKey) {
            this.seriesKey = key;
            if (this.surface.element.parentNode !== this.body) this.body.replaceChildren(this.surface.element);
            this.surface.draw(this.options(plotted), data as uPlot.AlignedData);
        } else {
            this.plot.setData(data as uPlot.AlignedData, !this.zoomed());
        }
    }

    // keep the user's zoom while new samples arrive
    private zoomed(): boolean {
        const u = this.plot;
        if (!u) return false;
        const xs = u.data[0];
        const min = u.scales.x.min;
        const max = u.scales.x.max;
        if (min === undefined || max === undefined || xs.length === 0) return false;
        return min > (xs[0] as number) || max < (xs[xs.length - 1] as number) * 0.999;
    }

    private options(plotted: Plotted[]): Omit<uPlot.Options, 'width' | 'height'> {
        return {
            scales: { x: { time: false, range: (_u, min, max) => this.span ?? [min, max] } },
            cursor: { drag: { x: true, y: false } },
            legend: { live: true },
            axes: [{ label: 'time [s]', size: 36 }, { size: 60 }],
            series: [
                { label: 'time [s]' },
                ...plotted.map((p) => ({ label: p.label, stroke: p.colour, width: 1.5, dash: p.previous ? [6, 4] : undefined, spanGaps: true })),
            ],
        };
    }

    /** Values of a variable of the current run as plotted (tests read the last one). */
    seriesData(name: string, previous = false): number[] {
        return this.plotted.find((p) => p.name === name && p.previous === previous)?.source.data ?? [];
    }

    private exportCsv(): void {
        if (this.plotted.length === 0) return;
        const aligned = alignSeries(this.plotted.map((p) => p.source));
        const names = this.plotted.map((p) => (p.previous ? `${p.name} (previous)` : p.name));
        downloadText(`plot-${this.id}.csv`, toCsv(names, aligned), 'text/csv');
    }

    private exportPng(): void {
        this.surface.exportPng(`plot-${this.id}.png`, this.plotted.map((p) => ({ label: p.label, colour: p.colour, dashed: p.previous })));
    }

    destroy(): void {
        this.surface.destroy();
        this.element.remove();
    }
}
