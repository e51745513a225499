// A window with the spectrum (FFT) of one plotted variable or the Bode diagram of one against
// another, over a chosen time range and window, from the current run; CSV and PNG export.
import type uPlot from 'uplot';
import type { RunData } from './RunData';
import { DerivedPlotFrame } from './DerivedPlotFrame';
import { amplitudeSpectrum, peakFrequency, WINDOWS, type WindowName } from '../analysis/fft';
import { bode } from '../analysis/bode';
import { toCsv } from './RunData';
import { downloadText, errorText, h } from '../ui/dom';

export type AnalysisKind = 'fft' | 'bode';

interface Result { x: number[]; series: { label: string; data: number[]; colour: string; scale: string }[] }

export class AnalysisWindow {
    readonly element: HTMLElement;
    private readonly frame: DerivedPlotFrame;
    private readonly inputSelect: HTMLSelectElement;
    private readonly outputSelect: HTMLSelectElement;
    private readonly windowSelect: HTMLSelectElement;
    private run: RunData | null = null;
    private result: Result | null = null;

    constructor(readonly id: number, readonly kind: AnalysisKind, variables: string[], private readonly labelOf: (name: string) => string,
        onClose: (w: AnalysisWindow) => void) {
        const choice = (name: string, label: string, selected: string | undefined) => h('select', { name, 'aria-label': label, onchange: () => this.recompute() },
            ...variables.map((v) => h('option', { value: v, selected: v === selected }, this.labelOf(v))));
        this.inputSelect = choice('input', kind === 'fft' ? 'Variable' : 'Input', variables[0]);
        this.outputSelect = choice('output', 'Output', variables[1] ?? variables[0]);
        this.windowSelect = h('select', { name: 'window', 'aria-label': 'Window', onchange: () => this.recompute() },
            ...WINDOWS.map((w) => h('option', { value: w }, w)));
        this.frame = new DerivedPlotFrame({
            plotId: `a${id}`, analysis: kind, title: kind === 'fft' ? 'Spectrum (FFT)' : 'Bode', closeLabel: 'Close analysis',
            controls: [kind === 'fft' ? this.inputSelect : h('span', { class: 'analysis-pair' }, 'out ', this.outputSelect, ' / in ', this.inputSelect),
                this.windowSelect],
            changed: () => this.recompute(),
            exportCsv: () => this.exportCsv(),
            exportPng: () => this.exportPng(),
            close: () => onClose(this),
        });
        this.element = this.frame.element;
    }

    /** Recomputes when the run has new data (finished runs only: a spectrum of half a run misleads). */
    update(current: RunData | null): void {
        this.run = current;
        if (this.frame.runChanged(current)) this.recompute();
    }

    private recompute(): void {
        const run = this.run;
        if (!run || !run.finished) return this.show(null, run ? 'Waiting for the run to finish.' : 'Run the model first.');
        try {
            const window = this.windowSelect.value as WindowName;
            const { from, to } = this.frame.timeRange();
            const column = (name: string) => {
                const data = run.columns.get(name);
                if (!data) throw new Error(`${this.labelOf(name)} is not in this run`);
                return { time: run.time, values: data };
            };
            if (this.kind === 'fft') {
                const s = amplitudeSpectrum(column(this.inputSelect.value), window, from, to);
                const peak = peakFrequency(s);
                this.element.dataset.peakHz = String(peak);
                this.show({ x: s.frequency, series: [{ label: `|${this.labelOf(this.inputSelect.value)}|`, data: s.amplitude, colour: '#1f6fd1', scale: 'y' }] },
                    `peak at ${peak.toPrecision(4)} Hz`);
            } else {
                const b = bode(column(this.inputSelect.value), column(this.outputSelect.value), window, from, to);
                this.show({ x: b.frequency, series: [
                    { label: 'gain [dB]', data: b.gainDb, colour: '#1f6fd1', scale: 'dB' },
                    { label: 'phase [°]', data: b.phaseDeg, colour: '#d1421f', scale: 'deg' },
                ] }, `${b.frequency.length} frequencies`);
            }
        } catch (e) {
            this.show(null, errorText(e));
        }
    }

    private show(result: Result | null, note: string): void {
        this.result = result;
        this.frame.setNote(note);
        if (!result) return this.frame.surface.clear();
        const bodeAxes: uPlot.Axis[] = [
            { label: 'frequency [Hz]', size: 50 },
            { scale: 'dB', label: 'gain [dB]', size: 60, stroke: '#1f6fd1' },
            { scale: 'deg', label: 'phase [°]', side: 1, size: 60, stroke: '#d1421f', grid: { show: false } },
        ];
        this.frame.surface.draw({
            scales: { x: { time: false, distr: this.kind === 'bode' ? 3 : 1 } },
            cursor: { drag: { x: true, y: false } },
            legend: { live: true },
            axes: this.kind === 'bode' ? bodeAxes : [{ label: 'frequency [Hz]', size: 50 }, { label: 'amplitude', size: 60 }],
            series: [{ label: 'frequency [Hz]' }, ...result.series.map((s) => ({ label: s.label, stroke: s.colour, width: 1.5, scale: s.scale }))],
        }, [result.x, ...result.series.map((s) => s.data)] as uPlot.AlignedData);
    }

    private exportCsv(): void {
        const r = this.result;
        if (!r) return;
        downloadText(`${this.kind}-${this.id}.csv`, toCsv(r.series.map((s) => s.label), [r.x, ...r.series.map((s) => s.data)], 'frequency [Hz]'), 'text/csv');
    }

    private exportPng(): void {
        this.frame.surface.exportPng(`${this.kind}-${this.id}.png`, (this.result?.series ?? []).map((s) => ({ label: s.label, colour: s.colour, dashed: false })));
    }

    destroy(): void { this.frame.destroy(); }
}
