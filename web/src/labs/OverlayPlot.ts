// The staff's overlay: one variable of every student's latest run in one uPlot chart, one
// series per student (named by user name). Runs have their own sample times: the chart's x
// is the union of them, each series null where it has no sample (lines span the gaps).
import type uPlot from 'uplot';
import { h } from '../ui/dom';
import { PlotSurface } from '../run/PlotSurface';
import type { Overlay, OverlaySeries } from './types';

const COLOURS = ['#1f6fd1', '#d1541f', '#2a9d4b', '#8e44ad', '#c9a400', '#16a0a0', '#c0392b', '#5d6d7e', '#e67e22', '#34495e'];

export function seriesColour(index: number): string { return COLOURS[index % COLOURS.length]; }

/** One x (sorted union of every run's times) and one y per run, null where the run has no sample. */
export function alignSeries(series: OverlaySeries[]): (number | null)[][] {
    const times = [...new Set(series.flatMap((s) => s.time))].sort((a, b) => a - b);
    const index = new Map(times.map((t, i) => [t, i]));
    const ys = series.map((s) => {
        const y: (number | null)[] = new Array(times.length).fill(null);
        s.time.forEach((t, i) => { y[index.get(t)!] = s.values[i] ?? null; });
        return y;
    });
    return [times, ...ys];
}

export class OverlayPlot {
    readonly element: HTMLElement;
    private readonly surface = new PlotSurface();
    private readonly caption = h('div', { class: 'overlay-caption muted' });

    constructor() {
        this.element = h('div', { class: 'overlay-plot', 'data-testid': 'overlay-plot', 'data-series': '0' },
            this.caption, h('div', { class: 'overlay-box' }, this.surface.element));
    }

    show(overlay: Overlay): void {
        const students = overlay.series.map((s) => s.student.username);
        this.element.dataset.series = String(overlay.series.length);
        this.element.dataset.students = students.join(',');
        this.element.dataset.variable = overlay.variable;
        if (overlay.series.length === 0) {
            this.surface.clear();
            this.caption.textContent = `${overlay.variable}: no finished runs yet.`;
            return;
        }
        this.caption.textContent = `${overlay.variable}: the latest finished run of ${overlay.series.length} student${overlay.series.length === 1 ? '' : 's'}`;
        const options: Omit<uPlot.Options, 'width' | 'height'> = {
            scales: { x: { time: false } },
            axes: [{ label: 'Time [s]' }, { label: overlay.variable, size: 70 }],
            series: [
                { label: 'Time' },
                ...overlay.series.map((s, i) => ({
                    label: s.student.username, stroke: seriesColour(i), width: 1.5, spanGaps: true, points: { show: false },
                })),
            ],
            cursor: { drag: { x: true, y: false } },
            legend: { live: true },
        };
        this.surface.draw(options, alignSeries(overlay.series) as uPlot.AlignedData);
    }

    clear(message: string): void {
        this.surface.clear();
        this.element.dataset.series = '0';
        this.caption.textContent = message;
    }

    dispose(): void { this.surface.destroy(); }
}
