// Run controls: start, step, stop time and log samples; run and cancel; progress.
import type { RunController, RunSettings } from './RunController';
import type { PlotArea } from './PlotArea';
import { h, errorText, toast } from '../ui/dom';
import type { SimulationSettings } from '../protocol/types';
import { checkRunSettings, fieldOfServerError, RUN_FIELDS, type RunField } from './runSettings';
import { runStatusText } from './runStatus';

export class RunPanel {
    readonly element: HTMLElement;
    private readonly inputs: Record<keyof RunSettings, HTMLInputElement>;
    private readonly errors: Record<RunField, HTMLElement>;
    private readonly runButton: HTMLButtonElement;
    private readonly cancelButton: HTMLButtonElement;
    private readonly bar: HTMLProgressElement;
    private readonly status: HTMLElement;
    /** Why the last run could not start: shown instead of the run before it until a run starts. */
    private refusal = '';

    /**
     * `onSettingsChange` receives a field the user changed, to make it the model's own
     * setting (saved with the model); a refusal is shown next to the field.
     */
    constructor(private readonly runs: RunController, private readonly plots: PlotArea,
        private model: SimulationSettings | undefined, private readonly defaultVariables: () => string[],
        private readonly onSettingsChange: (changed: Partial<RunSettings>) => Promise<void> = async () => undefined) {
        const field = (name: keyof RunSettings, label: string) =>
            h('input', { name: `run-${name}`, type: 'text', inputmode: 'decimal', 'aria-label': label, 'aria-describedby': `run-${name}-error`, size: 8 });
        this.inputs = {
            start: field('start', 'Start time'),
            step: field('step', 'Time step'),
            stop: field('stop', 'Stop time'),
            log_samples: field('log_samples', 'Log samples'),
        };
        this.inputs.log_samples.placeholder = 'default';
        this.errors = Object.fromEntries(RUN_FIELDS.map((f) => [f, h('span', { class: 'field-error', id: `run-${f}-error`, role: 'alert', hidden: true })])) as Record<RunField, HTMLElement>;
        this.fillFields(model, true);
        const labelled = (f: RunField, text: string, unit: string) =>
            h('div', { class: 'run-field' }, h('label', {}, text, this.inputs[f], unit), this.errors[f]);
        this.runButton = h('button', { class: 'primary', onclick: () => void this.start(), 'data-testid': 'run' }, '▶ Run');
        this.cancelButton = h('button', { onclick: () => void this.cancel(), disabled: true, 'data-testid': 'cancel' }, '■ Cancel');
        this.bar = h('progress', { max: 1, value: 0, 'aria-label': 'Progress' });
        this.status = h('span', { class: 'run-status', 'data-testid': 'run-status' }, 'Not run yet');
        this.element = h('div', { class: 'run-panel' },
            labelled('start', 'Start ', ' s'),
            labelled('step', 'Step ', ' s'),
            labelled('stop', 'Stop ', ' s'),
            labelled('log_samples', 'Samples ', ''),
            this.runButton, this.cancelButton, this.bar, this.status);
        for (const key of RUN_FIELDS) {
            const input = this.inputs[key];
            // errors clear as soon as the field is right again
            input.addEventListener('input', () => this.showErrors());
            input.addEventListener('change', () => {
                const { values, errors } = this.showErrors();
                const value = values[key];
                if (errors[key] || value === undefined) return;
                this.onSettingsChange({ [key]: value }).catch((e) => this.showError(key, errorText(e)));
            });
        }
        runs.subscribe(() => this.refresh());
    }

    private fillFields(settings: SimulationSettings | undefined, all: boolean): void {
        if (!settings) return;
        for (const key of RUN_FIELDS) {
            const input = this.inputs[key];
            if (!all && document.activeElement === input) continue;
            // 0 samples means "not set" (the server's default applies)
            input.value = key === 'log_samples' && settings.log_samples === 0 ? '' : String(settings[key]);
        }
    }

    /** Shows the model's settings (after an undo, say), unless a field is being edited. */
    showModelSettings(settings: SimulationSettings | undefined): void {
        this.model = settings;
        this.fillFields(settings, false);
        this.showErrors();
    }

    private typed(): Record<RunField, string> {
        return Object.fromEntries(RUN_FIELDS.map((f) => [f, this.inputs[f].value])) as Record<RunField, string>;
    }

    /** Checks the fields and shows each one's error next to it (or clears it). */
    private showErrors(): ReturnType<typeof checkRunSettings> {
        const checked = checkRunSettings(this.typed(), this.model);
        for (const f of RUN_FIELDS) this.showError(f, checked.errors[f] ?? '');
        return checked;
    }

    private showError(field: RunField, text: string): void {
        const box = this.errors[field];
        box.textContent = text;
        box.hidden = text === '';
        this.inputs[field].classList.toggle('invalid', text !== '');
        this.inputs[field].setAttribute('aria-invalid', String(text !== ''));
    }

    async start(): Promise<void> {
        const { values: chosen, errors } = this.showErrors();
        const wrong = RUN_FIELDS.find((f) => errors[f]);
        if (wrong) {
            this.refuse('Not started: correct the marked field.');
            this.inputs[wrong].focus();
            return;
        }
        this.refusal = '';
        try {
            if (this.plots.allVariables().length === 0) {
                for (const v of this.defaultVariables()) this.plots.addVariable(v);
            }
            this.runButton.disabled = true;
            // Until the server accepts the run, the status must not still say the last one is done.
            this.status.textContent = 'Starting…';
            this.status.dataset.state = 'starting';
            const start = chosen.start ?? this.model?.start;
            const stop = chosen.stop ?? this.model?.stop;
            const span: [number, number] | null = start !== undefined && stop !== undefined && stop > start ? [start, stop] : null;
            await this.runs.start(chosen, this.plots.allVariables(), span);
        } catch (e) {
            const inField = fieldOfServerError(errorText(e));
            if (inField) {
                this.showError(inField.field, inField.text);
                this.refuse('Not started: correct the marked field.');
            } else {
                toast(`Run: ${errorText(e)}`, 'error');
                this.refuse(`Not started: ${errorText(e)}`);
            }
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

    /** The run was not started: the status says why, and no longer names the run before. */
    private refuse(reason: string): void {
        this.refusal = reason;
        this.refresh();
    }

    private refresh(): void {
        const run = this.runs.current;
        const running = this.runs.running;
        this.runButton.disabled = running;
        this.cancelButton.disabled = !running;
        if (this.refusal) {
            this.bar.value = 0;
            this.status.textContent = this.refusal;
            this.status.dataset.state = 'not-started';
            delete this.status.dataset.job;
            return;
        }
        this.bar.value = run?.progress ?? 0;
        if (!run) return;
        this.status.textContent = runStatusText(run);
        this.status.dataset.state = run.state;
        this.status.dataset.job = String(run.jobId);
    }
}
