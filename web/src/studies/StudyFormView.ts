// The form of a new study: its kind, the model's parameters to vary (units and current values
// shown, bounds editable), the kind's settings, outputs and, for an optimisation, the objective
// with its value on the model's latest run. Typing changes the form's state in place; adding
// or removing something draws the form again.
import { h } from '../ui/dom';
import type { StudyParameter } from './studyParameters';
import type { LoggedVariable } from './studyVariables';
import {
    buildStudyRequest, choiceFor, emptyTerm, type BuildResult, type ParameterChoice, type StudyForm, type Statistic, type TermFunction,
} from './studyForm';
import { previewObjective, termVariables, type Preview } from './objectivePreview';
import type { ResultsJson } from '../protocol/types';

export interface FormContext {
    parameters(): StudyParameter[];
    variables(): LoggedVariable[];
    /** The model's latest finished run, if any (the objective's preview is computed on it). */
    latestRun(): { jobId: number } | null;
    results(jobId: number, variables: string[]): Promise<ResultsJson>;
    /** The editor has changes the stored model (what a study runs) lacks. */
    unsaved(): boolean;
    modelId(): number;
    submit(form: StudyForm, request: Extract<BuildResult, { ok: true }>['request']): Promise<void>;
}

const STATISTICS: Statistic[] = ['final', 'min', 'max', 'mean'];
const TERM_FUNCTIONS: { fn: TermFunction; label: string }[] = [
    { fn: 'final', label: 'final value' }, { fn: 'min', label: 'minimum' }, { fn: 'max', label: 'maximum' }, { fn: 'mean', label: 'time average' },
    { fn: 'overshoot', label: 'overshoot [%]' }, { fn: 'ise', label: 'ISE against a reference' },
];
const KINDS = [
    { kind: 'sweep', label: 'Parameter sweep' }, { kind: 'sensitivity', label: 'Sensitivity analysis' }, { kind: 'optimise', label: 'Optimisation' },
] as const;

export class StudyFormView {
    readonly element = h('form', { class: 'study-form', 'data-testid': 'study-form', novalidate: true });
    private readonly datalistId = `study-variables-${Math.random().toString(36).slice(2)}`;
    private previewLine = h('p', { class: 'objective-preview', 'data-testid': 'objective-preview', 'aria-live': 'polite' });
    private errors = h('ul', { class: 'form-error study-errors', role: 'alert', 'data-testid': 'study-errors' });
    private previewKey = '';

    constructor(private readonly ctx: FormContext, private form: StudyForm) {
        this.element.addEventListener('submit', (e) => { e.preventDefault(); void this.start(); });
        this.render();
    }

    get state(): StudyForm { return this.form; }

    render(): void {
        const f = this.form;
        const variables = h('datalist', { id: this.datalistId }, ...this.ctx.variables().map((v) => h('option', { value: v.name }, v.unit ? `[${v.unit}]` : '')));
        this.element.replaceChildren(
            variables,
            h('fieldset', { class: 'study-kind' }, h('legend', {}, 'Kind'),
                ...KINDS.map(({ kind, label }) => h('label', {},
                    h('input', { type: 'radio', name: 'study-kind', value: kind, checked: f.kind === kind, 'data-testid': `study-kind-${kind}`,
                        onchange: () => { f.kind = kind; this.render(); } }), ` ${label}`))),
            h('label', { class: 'study-name' }, 'Name ', this.input(f.name, (v) => { f.name = v; }, { placeholder: 'optional', 'data-testid': 'study-name' })),
            this.parameterSection(),
            this.kindSection(),
            f.kind === 'optimise' ? this.objectiveSection() : '',
            this.outputSection(),
            h('fieldset', { class: 'study-settings' }, h('legend', {}, 'Each run'),
                h('label', {}, 'Stop time [s] ', this.input(f.stop, (v) => { f.stop = v; }, { placeholder: 'the model\'s', size: 8 })),
                h('label', {}, 'Log samples ', this.input(f.logSamples, (v) => { f.logSamples = v; }, { placeholder: 'the model\'s', size: 8 }))),
            this.ctx.unsaved()
                ? h('p', { class: 'study-unsaved', 'data-testid': 'study-unsaved' }, 'The study runs the saved model: save first to include your unsaved changes.')
                : '',
            this.errors,
            h('div', { class: 'study-actions' }, h('button', { type: 'submit', class: 'primary', 'data-testid': 'study-start' }, 'Start study')));
        if (f.kind === 'optimise') void this.updatePreview();
    }

    private input(value: string, set: (v: string) => void, attrs: Record<string, unknown> = {}): HTMLInputElement {
        return h('input', { value, oninput: (e: Event) => set((e.target as HTMLInputElement).value), ...attrs });
    }

    private parameterSection(): HTMLElement {
        const f = this.form;
        const available = this.ctx.parameters().filter((p) => !f.parameters.some((c) => c.name === p.name));
        const picker = h('select', { 'data-testid': 'study-parameter-picker', 'aria-label': 'Parameter to add' },
            h('option', { value: '' }, 'Add a parameter…'),
            ...available.map((p) => h('option', { value: p.name },
                `${p.name}${p.unit && p.unit !== '-' ? ` [${p.unit}]` : ''} = ${p.text}${p.description ? ` (${p.description})` : ''}`)));
        picker.addEventListener('change', () => {
            const p = available.find((q) => q.name === picker.value);
            if (!p) return;
            f.parameters.push(choiceFor(p));
            this.render();
        });
        const current = new Map(this.ctx.parameters().map((p) => [p.name, p]));
        const heads = f.kind === 'sweep'
            ? (f.sweepMode === 'list' ? ['values'] : f.sweepMode === 'random' ? ['from', 'to'] : ['from', 'to', 'steps', 'or a list'])
            : f.kind === 'sensitivity' ? ['distribution', 'mean / min', 'σ / max'] : ['min', 'max', 'start'];
        return h('fieldset', { class: 'study-parameters' }, h('legend', {}, 'Parameters'),
            h('table', { class: 'study-parameter-table' },
                h('thead', {}, h('tr', {}, h('th', {}, 'parameter'), h('th', {}, 'unit'), h('th', {}, 'now'), ...heads.map((t) => h('th', {}, t)), h('th', {}))),
                h('tbody', {}, ...f.parameters.map((p) => this.parameterRow(p, current.get(p.name))))),
            f.parameters.length === 0 ? h('p', { class: 'muted' }, 'No parameter chosen yet.') : null,
            picker);
    }

    private parameterRow(p: ParameterChoice, now: StudyParameter | undefined): HTMLElement {
        const f = this.form;
        const field = (key: keyof ParameterChoice, label: string) =>
            h('td', {}, this.input(String(p[key]), (v) => { (p as unknown as Record<string, string>)[key] = v; this.previewSoon(); },
                { name: key, size: 9, 'aria-label': `${p.name} ${label}` }));
        let cells: HTMLElement[];
        if (f.kind === 'sweep') {
            if (f.sweepMode === 'list') cells = [field('list', 'values')];
            else if (f.sweepMode === 'random') cells = [field('from', 'from'), field('to', 'to')];
            else {
                const useList = h('input', { type: 'checkbox', checked: p.useList, 'aria-label': `${p.name} as a list`,
                    onchange: () => { p.useList = !p.useList; this.render(); } });
                cells = p.useList
                    ? [h('td', { colspan: 3 }, this.input(p.list, (v) => { p.list = v; }, { name: 'list', 'aria-label': `${p.name} values`, placeholder: '1, 2, 5' })), h('td', {}, useList)]
                    : [field('from', 'from'), field('to', 'to'), field('steps', 'steps'), h('td', {}, useList)];
            }
        } else if (f.kind === 'sensitivity') {
            const dist = h('select', { 'aria-label': `${p.name} distribution`, onchange: (e: Event) => { p.distribution = (e.target as HTMLSelectElement).value as 'normal' | 'uniform'; this.render(); } },
                h('option', { value: 'normal', selected: p.distribution === 'normal' }, 'normal'), h('option', { value: 'uniform', selected: p.distribution === 'uniform' }, 'uniform'));
            cells = [h('td', {}, dist), ...(p.distribution === 'normal' ? [field('mean', 'mean'), field('sd', 'σ')] : [field('min', 'min'), field('max', 'max')])];
        } else {
            cells = [field('from', 'min'), field('to', 'max'), field('start', 'start')];
        }
        return h('tr', { 'data-parameter': p.name },
            h('th', { scope: 'row', title: now?.description ?? '' }, p.name), h('td', { class: 'muted' }, p.unit), h('td', { class: 'numeric' }, now?.text ?? ''),
            ...cells,
            h('td', {}, h('button', { type: 'button', class: 'link-button', 'aria-label': `Remove ${p.name}`,
                onclick: () => { f.parameters = f.parameters.filter((c) => c !== p); this.render(); } }, '✕')));
    }

    private kindSection(): HTMLElement {
        const f = this.form;
        const seed = h('label', {}, 'Seed ', this.input(f.seed, (v) => { f.seed = v; }, { size: 6, 'data-testid': 'study-seed' }));
        if (f.kind === 'sweep') {
            const mode = h('select', { 'data-testid': 'study-sweep-mode', onchange: (e: Event) => { f.sweepMode = (e.target as HTMLSelectElement).value as StudyForm['sweepMode']; this.render(); } },
                ...([['grid', 'grid: every combination'], ['list', 'list: the i-th values together'], ['random', 'random samples']] as const)
                    .map(([v, label]) => h('option', { value: v, selected: f.sweepMode === v }, label)));
            return h('fieldset', { class: 'study-kind-settings' }, h('legend', {}, 'Sweep'), h('label', {}, 'Mode ', mode),
                f.sweepMode === 'random' ? h('label', {}, 'Samples ', this.input(f.samples, (v) => { f.samples = v; }, { size: 6, 'data-testid': 'study-samples' })) : null,
                f.sweepMode === 'random' ? seed : null,
                h('span', { class: 'muted' }, f.sweepMode === 'grid' ? ` ${this.gridRuns()}` : ''));
        }
        if (f.kind === 'sensitivity') {
            return h('fieldset', { class: 'study-kind-settings' }, h('legend', {}, 'Sensitivity (Monte Carlo)'),
                h('label', {}, 'Runs ', this.input(f.runs, (v) => { f.runs = v; }, { size: 6, 'data-testid': 'study-runs' })), seed);
        }
        const algorithm = h('select', { 'data-testid': 'study-algorithm', onchange: (e: Event) => { f.algorithm = (e.target as HTMLSelectElement).value as StudyForm['algorithm']; } },
            ...([['complex-rf', 'Complex-RF'], ['nelder-mead', 'Nelder–Mead'], ['particle-swarm', 'Particle swarm']] as const)
                .map(([v, label]) => h('option', { value: v, selected: f.algorithm === v }, label)));
        const goal = h('select', { 'data-testid': 'study-goal', onchange: (e: Event) => { f.goal = (e.target as HTMLSelectElement).value as StudyForm['goal']; } },
            h('option', { value: 'minimise', selected: f.goal === 'minimise' }, 'minimise'), h('option', { value: 'maximise', selected: f.goal === 'maximise' }, 'maximise'));
        return h('fieldset', { class: 'study-kind-settings' }, h('legend', {}, 'Optimisation'),
            h('label', {}, 'Algorithm ', algorithm), h('label', {}, 'Goal ', goal),
            h('label', {}, 'Max evaluations ', this.input(f.maxEvaluations, (v) => { f.maxEvaluations = v; }, { size: 6, 'data-testid': 'study-max-evaluations' })),
            seed, h('label', {}, 'Tolerance ', this.input(f.tolerance, (v) => { f.tolerance = v; }, { size: 8, placeholder: 'default' })));
    }

    // how many runs a grid makes, as the user fills it in
    private gridRuns(): string {
        let runs = 1;
        for (const p of this.form.parameters) {
            runs *= p.useList ? p.list.split(/[\s,;]+/).filter((s) => s !== '').length : Number(p.steps) || 0;
        }
        return this.form.parameters.length > 0 ? `(${runs} runs as the form now reads)` : '';
    }

    private objectiveSection(): HTMLElement {
        const f = this.form;
        const rows = f.terms.map((t) => {
            const fn = h('select', { 'aria-label': 'Function', onchange: (e: Event) => { t.fn = (e.target as HTMLSelectElement).value as TermFunction; this.render(); } },
                ...TERM_FUNCTIONS.map(({ fn: v, label }) => h('option', { value: v, selected: t.fn === v }, label)));
            const variable = this.input(t.variable, (v) => { t.variable = v; this.previewSoon(); }, { list: this.datalistId, 'aria-label': 'Objective variable', size: 28, 'data-testid': 'objective-variable' });
            const reference = t.fn === 'ise' ? this.input(t.reference, (v) => { t.reference = v; this.previewSoon(); }, { list: this.datalistId, 'aria-label': 'Reference variable', size: 24 }) : null;
            const target = t.fn === 'ise' || t.fn === 'overshoot' ? null : this.input(t.target, (v) => { t.target = v; this.previewSoon(); }, { 'aria-label': 'Target', size: 7, placeholder: 'none' });
            return h('tr', {},
                h('td', {}, fn), h('td', {}, variable), h('td', {}, reference ?? ''), h('td', {}, target ?? ''),
                h('td', {}, this.input(t.weight, (v) => { t.weight = v; this.previewSoon(); }, { 'aria-label': 'Weight', size: 5 })),
                h('td', {}, h('button', { type: 'button', class: 'link-button', 'aria-label': 'Remove term', onclick: () => { f.terms = f.terms.filter((x) => x !== t); this.render(); } }, '✕')));
        });
        return h('fieldset', { class: 'study-objective' }, h('legend', {}, 'Objective (terms summed with their weights)'),
            h('table', { class: 'study-parameter-table' },
                h('thead', {}, h('tr', {}, ...['function', 'variable', 'reference', 'target', 'weight', ''].map((t) => h('th', {}, t)))),
                h('tbody', {}, ...rows)),
            h('button', { type: 'button', 'data-testid': 'objective-add-term', onclick: () => { f.terms.push(emptyTerm(this.ctx.variables()[0]?.name ?? '')); this.render(); } }, 'Add term'),
            this.previewLine);
    }

    private outputSection(): HTMLElement {
        const f = this.form;
        const entry = this.input('', () => undefined, { list: this.datalistId, placeholder: 'Comp#Port#Variable', size: 32, 'data-testid': 'study-output-input', 'aria-label': 'Output variable' });
        const add = () => {
            const name = entry.value.trim();
            if (name && !f.outputs.includes(name)) f.outputs.push(name);
            this.render();
        };
        entry.addEventListener('keydown', (e) => { if (e.key === 'Enter') { e.preventDefault(); add(); } });
        return h('fieldset', { class: 'study-outputs' }, h('legend', {}, f.kind === 'optimise' ? 'Outputs (optional: extra table columns)' : 'Outputs'),
            h('div', { class: 'study-chips' }, ...f.outputs.map((o) => h('span', { class: 'chip', 'data-output': o }, o,
                h('button', { type: 'button', class: 'link-button', 'aria-label': `Remove ${o}`, onclick: () => { f.outputs = f.outputs.filter((x) => x !== o); this.render(); } }, ' ✕')))),
            entry, h('button', { type: 'button', 'data-testid': 'study-output-add', onclick: add }, 'Add output'),
            h('span', { class: 'study-statistics' }, ' values: ', ...STATISTICS.map((s) => h('label', {},
                h('input', { type: 'checkbox', checked: f.statistics.includes(s), onchange: (e: Event) => {
                    const on = (e.target as HTMLInputElement).checked;
                    f.statistics = STATISTICS.filter((x) => (x === s ? on : f.statistics.includes(x)));
                } }), ` ${s} `))));
    }

    private previewTimer: ReturnType<typeof setTimeout> | undefined;
    private previewSoon(): void {
        if (this.form.kind !== 'optimise') return;
        clearTimeout(this.previewTimer);
        this.previewTimer = setTimeout(() => void this.updatePreview(), 300);
    }

    // the objective on the latest run: the run's results for the terms' variables, once per run and set of variables
    private resultsCache = new Map<string, Promise<ResultsJson>>();
    private async updatePreview(): Promise<void> {
        const run = this.ctx.latestRun();
        const line = this.previewLine;
        if (!run) {
            line.textContent = 'No run of the model yet: run it once to see the objective\'s value here.';
            line.dataset.state = 'no-run';
            return;
        }
        const terms = this.form.terms;
        const variables = termVariables(terms);
        if (terms.length === 0 || variables.length === 0) {
            line.textContent = `Add a term to see the objective on the latest run (job ${run.jobId}).`;
            line.dataset.state = 'no-terms';
            return;
        }
        const key = JSON.stringify([run.jobId, variables]);
        this.previewKey = key;
        let preview: Preview;
        try {
            if (!this.resultsCache.has(key)) this.resultsCache.set(key, this.ctx.results(run.jobId, variables));
            preview = previewObjective(terms, await this.resultsCache.get(key)!);
        } catch (e) {
            this.resultsCache.delete(key);
            preview = { ok: false, reason: e instanceof Error ? e.message : String(e) };
        }
        if (this.previewKey !== key) return;   // a newer preview is on its way
        line.dataset.state = preview.ok ? 'value' : 'error';
        line.dataset.value = preview.ok ? String(preview.value) : '';
        line.textContent = preview.ok
            ? `Objective on the latest run (job ${run.jobId}): ${Number(preview.value.toPrecision(6))}`
            : `Objective on the latest run (job ${run.jobId}): ${preview.reason}`;
    }

    private async start(): Promise<void> {
        const built = buildStudyRequest(this.form, this.ctx.modelId());
        if (!built.ok) {
            this.errors.replaceChildren(...built.errors.map((e) => h('li', {}, e)));
            return;
        }
        this.errors.replaceChildren();
        try {
            await this.ctx.submit(this.form, built.request);
        } catch (e) {
            this.errors.replaceChildren(h('li', {}, e instanceof Error ? e.message : String(e)));
        }
    }
}
