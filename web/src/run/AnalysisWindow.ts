// A window with the spectrum (FFT) of one plotted variable or the Bode diagram of one against
// another, over a chosen time range and window, from the run its plot window shows; CSV and PNG export.
import type uPlot from 'uplot';
import type { RunData } from './RunData';
import { DerivedPlotFrame } from './DerivedPlotFrame';
import { PlotSurface } from './PlotSurface';
import { BodePlots } from './BodePlots';
import { amplitudeSpectrum, peakFrequency, WINDOWS, type Spectrum, type WindowName } from '../analysis/fft';
import { bode, type Bode, type PhaseMode } from '../analysis/bode';
import { bodePair } from '../analysis/bodeDefaults';
import { toCsv } from './RunData';
import { downloadText, errorText, h } from '../ui/dom';

export type AnalysisKind = 'fft' | 'bode';

/**
 * What the window knows of the model beyond the plot window's variables: the logged outputs of
 * its signal sources (the Bode input by default, plotted or not), and how to load a variable the
 * run has not fetched yet.
 */
export interface ModelSignals { sources: string[]; load(names: string[]): Promise<void> }

const NO_MODEL: ModelSignals = { sources: [], load: async () => undefined };

export class AnalysisWindow {
    readonly element: HTMLElement;
    private readonly frame: DerivedPlotFrame;
    private readonly inputSelect: HTMLSelectElement;
    private readonly outputSelect: HTMLSelectElement;
    private readonly windowSelect: HTMLSelectElement;
    private readonly phaseSelect: HTMLSelectElement;
    // one of the two, by kind
    private readonly spectrumPlot: PlotSurface | null;
    private readonly bodePlots: BodePlots | null;
    private run: RunData | null = null;
    private spectrum: Spectrum | null = null;
    private diagram: Bode | null = null;
    /** Loads asked for (run and variables), so a variable the run lacks is asked for once. */
    private readonly loadsAsked = new Set<string>();

    constructor(readonly id: number, readonly kind: AnalysisKind, variables: string[], private readonly labelOf: (name: string) => string,
        onClose: (w: AnalysisWindow) => void, private readonly model: ModelSignals = NO_MODEL) {
        const defaults = kind === 'bode' ? bodePair(variables, model.sources) : { input: variables[0], output: undefined };
        const choices = kind === 'bode' ? [...new Set([...variables, ...model.sources])] : variables;
        const choice = (name: string, label: string, selected: string | undefined) => h('select', { name, 'aria-label': label, onchange: () => this.recompute() },
            ...choices.map((v) => h('option', { value: v, selected: v === selected }, this.labelOf(v))));
        this.inputSelect = choice('input', kind === 'fft' ? 'Variable' : 'Input', defaults.input);
        this.outputSelect = choice('output', 'Output', defaults.output);
        this.windowSelect = h('select', { name: 'window', 'aria-label': 'Window', onchange: () => this.recompute() },
            ...WINDOWS.map((w) => h('option', { value: w }, w)));
        this.phaseSelect = h('select', { name: 'phase', 'aria-label': 'Phase', onchange: () => this.recompute() },
            h('option', { value: 'unwrapped' }, 'phase unwrapped'), h('option', { value: 'wrapped' }, 'phase wrapped (±180°)'));
        this.spectrumPlot = kind === 'fft' ? new PlotSurface() : null;
        this.bodePlots = kind === 'bode' ? new BodePlots(`bode-${id}`) : null;
        this.frame = new DerivedPlotFrame({
            plotId: `a${id}`, analysis: kind, title: kind === 'fft' ? 'Spectrum (FFT)' : 'Bode', closeLabel: 'Close analysis',
            controls: kind === 'fft' ? [this.inputSelect, this.windowSelect]
                : [h('span', { class: 'analysis-pair' }, 'out ', this.outputSelect, ' / in ', this.inputSelect), this.windowSelect, this.phaseSelect],
            body: this.spectrumPlot ?? this.bodePlots!,
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
        this.spectrum = null;
        this.diagram = null;
        if (!run || !run.finished) return this.showNothing(run ? 'Waiting for the run to finish.' : 'Run the model first.');
        const names = this.kind === 'fft' ? [this.inputSelect.value] : [this.inputSelect.value, this.outputSelect.value];
        const missing = names.filter((n) => !run.has(n));
        // e.g. the source, which is the Bode input without being plotted
        const load = `${run.jobId}:${missing.join(' ')}`;
        if (missing.length > 0 && !this.loadsAsked.has(load)) {
            this.loadsAsked.add(load);
            this.showNothing('Loading results…');
            this.model.load(missing).then(() => this.recompute(), (e) => this.showNothing(errorText(e)));
            return;
        }
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
                this.spectrum = s;
                this.drawSpectrum(s);
                this.frame.setNote(`peak at ${peak.toPrecision(4)} Hz`);
            } else {
                const phase = this.phaseSelect.value as PhaseMode;
                const b = bode(column(this.inputSelect.value), column(this.outputSelect.value), { window, from, to, phase });
                this.diagram = b;
                this.bodePlots?.draw(b);
                this.frame.setNote(`${b.frequency.length} frequencies`);
            }
        } catch (e) {
            this.showNothing(errorText(e));
        }
    }

    private showNothing(note: string): void {
        this.frame.setNote(note);
        this.spectrumPlot?.clear();
        this.bodePlots?.clear();
    }

    private drawSpectrum(s: Spectrum): void {
        this.spectrumPlot?.draw({
            scales: { x: { time: false } },
            cursor: { drag: { x: true, y: false } },
            legend: { live: true },
            axes: [{ label: 'frequency [Hz]', size: 50 }, { label: 'amplitude', size: 60 }],
            series: [{ label: 'frequency [Hz]' }, { label: this.spectrumLabel(), stroke: '#1f6fd1', width: 1.5 }],
        }, [s.frequency, s.amplitude] as uPlot.AlignedData);
    }

    private spectrumLabel(): string { return `|${this.labelOf(this.inputSelect.value)}|`; }

    private exportCsv(): void {
        const file = `${this.kind}-${this.id}.csv`;
        if (this.spectrum) downloadText(file, toCsv([this.spectrumLabel()], [this.spectrum.frequency, this.spectrum.amplitude], 'frequency [Hz]'), 'text/csv');
        const b = this.diagram;
        if (b) downloadText(file, toCsv(['gain [dB]', 'phase [°]'], [b.frequency, b.gainDb, b.phaseDeg], 'frequency [Hz]'), 'text/csv');
    }

    private exportPng(): void {
        const file = `${this.kind}-${this.id}.png`;
        if (this.spectrum) this.spectrumPlot?.exportPng(file, [{ label: this.spectrumLabel(), colour: '#1f6fd1', dashed: false }]);
        if (this.diagram) this.bodePlots?.exportPng(file, `${this.labelOf(this.outputSelect.value)} / ${this.labelOf(this.inputSelect.value)}`);
    }

    destroy(): void { this.frame.destroy(); }
}
