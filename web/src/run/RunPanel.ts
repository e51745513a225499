// Run controls: start, step, stop time and log samples; run and cancel; progress.
import type { RunController, RunSettings } from './RunController';
import type { PlotArea } from './PlotArea';
import { h, errorText, toast } from '../ui/dom';
import type { SimulationSettings } from '../protocol/types';

export class RunPanel {
    readonly element: HTMLElement;
    private readonly inputs: Record<keyof RunSettings, HTMLInputElement>;
    private readonly runButton: HTMLButtonElement;
    private readonly cancelButton: HTMLButtonElement;
    private readonly bar: HTMLProgressElement;
    private readonly status: HTMLElement;

    /**
     * `onSettingsChange` receives a field the user changed, to make it the model's own
     * setting (saved with the model).
     */
    constructor(private readonly runs: RunController, private readonly plots: PlotArea,
        private model: SimulationSettings | undefined, private readonly defaultVariables: () => string[],
        private readonly onSettingsChange: (changed: Partial<RunSettings>) => void = () => undefined) {
        const settings = model;
        const field = (name: keyof RunSettings, label: string, value: number | undefined) =>
            h('input', { name: `run-${name}`, type: 'text', inputmode: 'decimal', value: value ?? '', 'aria-label': label, size: 8 });
        this.inputs = {
            start: field('start', 'Start time', settings?.start),
            step: field('step', 'Time step', settings?.step),
            stop: field('stop', 'Stop time', settings?.stop),
            log_samples: field('log_samples', 'Log samples', settings?.log_samples),
        };
        this.runButton = h('button', { class: 'primary', onclick: () => void this.start(), 'data-testid': 'run' }, '▶ Run');
        this.cancelButton = h('button', { onclick: () => void this.cancel(), disabled: true, 'data-testid': 'cancel' }, '■ Cancel');
        this.bar = h('progress', { max: 1, value: 0, 'aria-label': 'Progress' });
        this.status = h('span', { class: 'run-status', 'data-testid': 'run-status' }, 'Not run yet');
        this.element = h('div', { class: 'run-panel' },
            h('label', {}, 'Start ', this.inputs.start, ' s'),
            h('label', {}, 'Step ', this.inputs.step, ' s'),
            h('label', {}, 'Stop ', this.inputs.stop, ' s'),
            h('label', {}, 'Samples ', this.inputs.log_samples),
            this.runButton, this.cancelButton, this.bar, this.status);
        for (const [key, input] of Object.entries(this.inputs) as [keyof RunSettings, HTMLInputElement][]) {
            input.addEventListener('change', () => {
                const value = Number(input.value.trim());
                if (input.value.trim() === '' || !Number.isFinite(value)) return;
                this.onSettingsChange({ [key]: key === 'log_samples' ? Math.round(value) : value });
            });
        }
        runs.subscribe(() => this.refresh());
    }

    /** Shows the model's settings (after an undo, say), unless a field is being edited. */
    showModelSettings(settings: SimulationSettings | undefined): void {
        this.model = settings;
        if (!settings) return;
        for (const [key, input] of Object.entries(this.inputs) as [keyof RunSettings, HTMLInputElement][]) {
            if (document.activeElement !== input) input.value = String(settings[key]);
        }
    }

    /** The settings typed in; empty fields use the model's own. */
    settings(): Partial<RunSettings> {
        const out: Partial<RunSettings> = {};
        for (const [key, input] of Object.entries(this.inputs) as [keyof RunSettings, HTMLInputElement][]) {
            const text = input.value.trim();
            if (text === '') continue;
            const value = Number(text);
            if (!Number.isFinite(value)) throw new Error(`${input.getAttribute('aria-label')}: not a number`);
            out[key] = key === 'log_samples' ? Math.round(value) : value;
        }
        return out;
    }

    async start(): Promise<void> {
        try {
            if (this.plots.allVariables().length === 0) {
                for (const v of this.defaultVariables()) this.plots.addVariable(v);
            }
            this.runButton.disabled = true;
            const chosen = this.settings();
            const start = chosen.start ?? this.model?.start;
            const stop = chosen.stop ?? this.model?.stop;
            const span: [number, number] | null = start !== undefined && stop !== undefined && stop > start ? [start, stop] : null;
            await this.runs.start(chosen, this.plots.allVariables(), span);
        } catch (e) {
            toast(`Run: ${errorText(e)}`, 'error');
            this.status.textContent = `Not started: ${errorText(e)}`;
        } finally {
            this.refresh();
        }
    }

    async cancel(): Promise<void> {
        try {
            await this.runs.cancel();
        } catch (e) {
            toast(`Cancel: ${errorText(e)}`, 'error');
        }
    }

    private refresh(): void {
        const run = this.runs.current;
        const running = this.runs.running;
        this.runButton.disabled = running;
        this.cancelButton.disabled = !running;
        this.bar.value = run?.progress ?? 0;
        if (!run) return;
        const pct = Math.round((run.progress ?? 0) * 100);
        this.status.textContent = running ? `Job ${run.jobId}: running ${pct}%`
            : `Job ${run.jobId}: ${run.state}${run.error ? ` — ${run.error}` : ''}`;
        this.status.dataset.state = run.state;
        this.status.dataset.job = String(run.jobId);
    }
}
