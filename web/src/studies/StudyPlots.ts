// The study charts drawn with uPlot: a 1-D sweep's outputs against its parameter, an
// optimisation's convergence, a sensitivity study's bands over time. Each is a PlotSurface
// (legend beside the chart) in a box of fixed height.
import type uPlot from 'uplot';
import { h } from '../ui/dom';
import { PlotSurface } from '../run/PlotSurface';
import { seriesColour } from '../labs/OverlayPlot';
import type { ConvergenceSeries } from './convergence';
import type { BandCurves, StudyTable } from './studyTypes';

export interface Chart { element: HTMLElement; dispose(): void }

function chart(testid: string, title: string, options: Omit<uPlot.Options, 'width' | 'height'>, data: uPlot.AlignedData): Chart {
    const surface = new PlotSurface();
    const element = h('figure', { class: 'study-chart', 'data-testid': testid },
        h('figcaption', {}, title), h('div', { class: 'study-chart-box' }, surface.element));
    // drawn once the box is in the page and has its size
    requestAnimationFrame(() => surface.draw(options, data));
    return { element, dispose: () => surface.destroy() };
}

/** A 1-D sweep: each output column against the parameter, points joined in the parameter's order. */
export function sweepCurves(table: StudyTable, parameter: string, outputs: string[]): Chart {
    const xi = table.columns.indexOf(parameter);
    const rows = table.rows.filter((r) => typeof r[xi] === 'number').sort((a, b) => (a[xi] as number) - (b[xi] as number));
    const ys = outputs.map((o) => rows.map((r) => r[table.columns.indexOf(o)] ?? null));
    return chart('sweep-curves', `Outputs against ${parameter}`, {
        scales: { x: { time: false } },
        axes: [{ label: parameter }, { size: 70 }],
        series: [{ label: parameter }, ...outputs.map((o, i) => ({ label: o, stroke: seriesColour(i), width: 1.5, points: { show: true, size: 5 }, spanGaps: false }))],
        legend: { live: true },
    }, [rows.map((r) => r[xi] as number), ...ys] as uPlot.AlignedData);
}

/** Each run's objective (points) and the best so far (a step line) against the run. */
export function convergencePlot(series: ConvergenceSeries, goal: string): Chart {
    return chart('convergence-plot', `Convergence (${goal})`, {
        scales: { x: { time: false } },
        // runs are whole numbers: no ticks between them
        axes: [{ label: 'Run', incrs: [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000] }, { label: 'Objective', size: 70 }],
        series: [
            { label: 'Run' },
            { label: 'Objective of the run', stroke: '#9aa5b1', width: 0, points: { show: true, size: 6, fill: '#9aa5b1' } },
            { label: 'Best so far', stroke: '#1f6fd1', width: 2, points: { show: false } },
        ],
        legend: { live: true },
    }, [series.runs, series.objective, series.best] as uPlot.AlignedData);
}

/** One variable's mean with ±1σ and ±2σ bands over time. */
export function bandsPlot(variable: string, time: number[], curves: BandCurves, n: number | undefined): Chart {
    const band = (hi: number, lo: number, fill: string): uPlot.Band => ({ series: [hi, lo], fill });
    return chart('bands-plot', `${variable}: mean ±1σ, ±2σ${n !== undefined ? ` over ${n} runs` : ''}`, {
        scales: { x: { time: false } },
        axes: [{ label: 'Time [s]' }, { size: 70 }],
        series: [
            { label: 'Time' },
            { label: '+2σ', stroke: 'rgba(31,111,209,0.35)', width: 1 },
            { label: '+1σ', stroke: 'rgba(31,111,209,0.6)', width: 1 },
            { label: 'mean', stroke: '#1f4f91', width: 2 },
            { label: '−1σ', stroke: 'rgba(31,111,209,0.6)', width: 1 },
            { label: '−2σ', stroke: 'rgba(31,111,209,0.35)', width: 1 },
        ],
        bands: [band(1, 2, 'rgba(31,111,209,0.12)'), band(2, 4, 'rgba(31,111,209,0.25)'), band(4, 5, 'rgba(31,111,209,0.12)')],
        legend: { live: true },
    }, [time, curves.plus_2sd, curves.plus_1sd, curves.mean, curves.minus_1sd, curves.minus_2sd] as uPlot.AlignedData);
}
