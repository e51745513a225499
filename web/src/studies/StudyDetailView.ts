// One study in the panel: state and progress (runs done and failed, the failure reasons),
// cancel / resume / delete, the best point with "Apply best point", and the results: the
// sortable table with its CSV, and the kind's chart (a 1-D sweep's curves, a 2-D sweep's heat
// map, an optimisation's convergence, a sensitivity study's bands).
import { h } from '../ui/dom';
import { sortableTable, type SortableTable, type SortOrder } from '../ui/sortableTable';
import { columnRoles, shortNumber, studyColumns, studyRows, type StudyRow } from './studyTable';
import { distinctValues, heatMapGrid } from './heatMap';
import { heatMapView, type HeatMapChoice } from './HeatMapView';
import { convergenceSeries, inferGoal, type Goal } from './convergence';
import { bandsPlot, convergencePlot, sweepCurves, type Chart } from './StudyPlots';
import { progressText, type FollowedStudy } from './studyProgress';
import { FINAL_STATES, type StudyBands, type StudyInfo } from './studyTypes';

export interface DetailActions {
    cancel(id: number): void;
    resume(id: number): void;
    remove(id: number): void;
    downloadCsv(info: StudyInfo): void;
    applyBest(info: StudyInfo): void;
    bands(id: number): Promise<StudyBands>;
    /** The goal when the page submitted the study itself (otherwise inferred from the table). */
    goal(id: number): Goal | undefined;
}

const KIND_NAMES: Record<string, string> = { sweep: 'Sweep', sensitivity: 'Sensitivity analysis', optimise: 'Optimisation' };

export class StudyDetailView {
    readonly element = h('section', { class: 'study-detail', 'data-testid': 'study-detail' });
    private readonly head = h('div', { class: 'study-head' });
    private readonly results = h('div', { class: 'study-results' });
    private charts: Chart[] = [];
    private order: SortOrder | null = null;
    private resultsTimer: ReturnType<typeof setTimeout> | undefined;
    private resultsDrawnAt = 0;
    private shownStudy: FollowedStudy | null = null;

    constructor(private readonly actions: DetailActions) {
        this.element.append(this.head, this.results);
    }

    /** Shows the study as it is now; the results are redrawn at most twice a second while it runs. */
    show(study: FollowedStudy): void {
        const changedStudy = this.shownStudy?.info.id !== study.info.id;
        if (changedStudy) {
            this.heatChoice = {};
            this.order = null;
            this.dropBands();
        }
        this.shownStudy = study;
        this.drawHead(study.info);
        const final = FINAL_STATES.has(study.info.state);
        clearTimeout(this.resultsTimer);
        const wait = changedStudy || final ? 0 : Math.max(0, 500 - (Date.now() - this.resultsDrawnAt));
        if (wait === 0) this.drawResults(study);
        else this.resultsTimer = setTimeout(() => this.shownStudy && this.drawResults(this.shownStudy), wait);
    }

    // The head's elements are made once and updated in place: progress events come up to ten
    // times a second, and a button drawn anew under the pointer loses the click on it.
    private readonly title = h('h3');
    private readonly bar = h('progress', { max: 1, value: 0 });
    private readonly barText = h('span', { class: 'study-progress-text' });
    private readonly progress = h('div', { class: 'study-progress', 'data-testid': 'study-progress' }, this.bar, this.barText);
    private readonly errorLine = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'study-error', hidden: true });
    private readonly failures = h('details', { class: 'study-failures', open: true, 'data-testid': 'study-failures', hidden: true });
    private readonly best = h('div', { class: 'study-best', 'data-testid': 'study-best', hidden: true });
    private readonly cancelButton = h('button', { type: 'button', 'data-testid': 'study-cancel', onclick: () => this.act((id) => this.actions.cancel(id)) }, 'Cancel');
    private readonly resumeButton = h('button', { type: 'button', 'data-testid': 'study-resume', onclick: () => this.act((id) => this.actions.resume(id)) }, 'Resume');
    private readonly csvButton = h('button', { type: 'button', 'data-testid': 'study-csv', onclick: () => this.shownStudy && this.actions.downloadCsv(this.shownStudy.info) }, 'Download CSV');
    private readonly deleteButton = h('button', { type: 'button', class: 'danger', 'data-testid': 'study-delete', onclick: () => this.act((id) => this.actions.remove(id)) }, 'Delete');
    private failuresKey = '';
    private bestKey = '';

    private act(action: (id: number) => void): void {
        if (this.shownStudy) action(this.shownStudy.info.id);
    }

    private drawHead(info: StudyInfo): void {
        if (this.head.childElementCount === 0) {
            this.head.append(this.title, this.progress, this.errorLine, this.failures, this.best,
                h('div', { class: 'study-actions' }, this.cancelButton, this.resumeButton, this.csvButton, this.deleteButton));
        }
        const running = info.state === 'queued' || info.state === 'running';
        const finished = info.runs_done + info.runs_failed;
        this.title.textContent = `${KIND_NAMES[info.kind] ?? info.kind} ${info.name ? `“${info.name}” ` : ''}(study ${info.id})`;
        Object.assign(this.progress.dataset, { state: info.state, done: String(info.runs_done), failed: String(info.runs_failed) });
        this.bar.max = Math.max(1, info.runs_total);
        this.bar.value = finished;
        this.barText.textContent = progressText(info);
        this.errorLine.textContent = info.error;
        this.errorLine.hidden = !info.error;

        const reasons = info.summary.failure_reasons ?? [];
        const failuresKey = JSON.stringify([reasons, info.runs_failed]);
        if (failuresKey !== this.failuresKey) {
            this.failuresKey = failuresKey;
            this.failures.hidden = reasons.length === 0;
            this.failures.replaceChildren(h('summary', {}, `Why runs failed (${info.runs_failed})`),
                h('ul', {}, ...reasons.map((r) => h('li', {}, `${r.message} — ${r.count} run${r.count === 1 ? '' : 's'}, first run ${r.first_run}`))));
        }

        const best = info.summary.best;
        const bestKey = JSON.stringify([info.id, best]);
        if (bestKey !== this.bestKey) {
            this.bestKey = bestKey;
            this.best.hidden = !best;
            this.best.replaceChildren(...(best ? [
                h('span', {}, `Best: run ${best.run}, objective ${shortNumber(best.objective)}; `,
                    Object.entries(best.parameters).map(([k, v]) => `${k} = ${shortNumber(v)}`).join(', ')),
                h('button', { type: 'button', class: 'primary', 'data-testid': 'apply-best', title: 'Set these values on the model (one step to undo)',
                    onclick: () => this.shownStudy && this.actions.applyBest(this.shownStudy.info) }, 'Apply best point'),
            ] : []));
        }
        this.cancelButton.hidden = !running;
        this.resumeButton.hidden = !(info.state === 'interrupted' || info.state === 'cancelled');
        this.csvButton.disabled = finished === 0;
        this.deleteButton.hidden = !FINAL_STATES.has(info.state);
    }

    // The table stays while the study runs (its scroll and order with it) and takes the new
    // rows; the charts are drawn again from the table; a heat map keeps the axes chosen.
    private readonly chartBox = h('div', { class: 'study-charts' });
    private readonly tableTitle = h('h4');
    private readonly tableBox = h('div', { class: 'study-table-box' });
    private table: { key: string; view: SortableTable<StudyRow> } | null = null;
    private heatChoice: HeatMapChoice = {};
    private bands: { id: number; element: HTMLElement; charts: Chart[] } | null = null;

    private drawResults(study: FollowedStudy): void {
        this.resultsDrawnAt = Date.now();
        for (const c of this.charts) c.dispose();
        this.charts = [];
        const { info, table } = study;
        if (this.results.childElementCount === 0) this.results.append(this.chartBox, this.tableTitle, this.tableBox);
        const roles = columnRoles(table.columns);
        const parts: HTMLElement[] = [];
        if (table.rows.length > 0 && info.kind === 'sweep' && roles.outputs.length > 0) {
            if (roles.parameters.length === 1) parts.push(this.keep(sweepCurves(table, roles.parameters[0], roles.outputs)));
            else if (roles.parameters.length >= 2) {
                parts.push(heatMapView({ parameters: roles.parameters, outputs: [...roles.outputs, ...(roles.objective ? ['objective'] : [])],
                    values: (p) => distinctValues(table, p),
                    grid: (x, y, z, fixed) => heatMapGrid(table, x, y, z, fixed),
                    choice: this.heatChoice }));
            }
        }
        if (table.rows.length > 0 && roles.objective && info.kind === 'optimise') {
            const goal = this.actions.goal(info.id) ?? inferGoal(table, info.summary.best?.objective);
            const series = convergenceSeries(table, goal);
            if (series) parts.push(this.keep(convergencePlot(series, goal)));
        }
        if (info.kind === 'sensitivity') parts.push(this.bandsPart(info));
        if (info.kind === 'sensitivity' && info.summary.correlations) parts.push(correlationTable(info.summary.correlations));
        this.chartBox.replaceChildren(...parts);

        const rows = studyRows(table);
        const key = JSON.stringify([info.id, table.columns]);
        if (this.table?.key !== key) {
            const view = sortableTable({
                columns: studyColumns(table.columns), rows, order: this.order ?? undefined,
                attrs: { 'data-testid': 'study-results-table' },
                rowAttrs: (r) => ({ class: r.ok ? '' : 'failed-run', 'data-run': String(r.run) }),
                empty: 'No run has finished yet.',
                onOrder: (order) => { this.order = order; },
            });
            this.table = { key, view };
            this.tableBox.replaceChildren(view.element);
        } else {
            this.table.view.show(rows);
        }
        this.table.view.element.dataset.rows = String(rows.length);
        this.tableTitle.textContent = `Runs (${rows.length})`;
    }

    private keep(chart: Chart): HTMLElement {
        this.charts.push(chart);
        return chart.element;
    }

    // the bands come once the study has finished: read and drawn once, one chart per output variable
    private bandsPart(info: StudyInfo): HTMLElement {
        if (this.bands?.id === info.id && info.state === 'done') return this.bands.element;
        const box = h('div', { class: 'study-bands', 'data-testid': 'study-bands' });
        if (info.state !== 'done') {
            box.append(h('p', { class: 'muted' }, 'The bands are drawn once the study has finished.'));
            return box;
        }
        this.dropBands();
        const bands = { id: info.id, element: box, charts: [] as Chart[] };
        this.bands = bands;
        this.actions.bands(info.id).then((data) => {
            if (this.bands !== bands) return;
            for (const [variable, curves] of Object.entries(data.variables)) {
                const chart = bandsPlot(variable, data.time, curves, data.n);
                bands.charts.push(chart);
                box.append(chart.element);
            }
        }, (e: unknown) => box.append(h('p', { class: 'form-error' }, `Bands: ${e instanceof Error ? e.message : String(e)}`)));
        return box;
    }

    private dropBands(): void {
        for (const c of this.bands?.charts ?? []) c.dispose();
        this.bands = null;
    }

    dispose(): void {
        clearTimeout(this.resultsTimer);
        for (const c of this.charts) c.dispose();
        this.charts = [];
        this.dropBands();
    }
}

/** Pearson's r of each parameter with each output (summary.correlations). */
function correlationTable(correlations: Record<string, Record<string, number>>): HTMLElement {
    const outputs = [...new Set(Object.values(correlations).flatMap((o) => Object.keys(o)))];
    return h('table', { class: 'model-table study-correlations', 'data-testid': 'study-correlations' },
        h('caption', {}, 'Correlation (Pearson\'s r) of each parameter with each output'),
        h('thead', {}, h('tr', {}, h('th', {}, 'parameter'), ...outputs.map((o) => h('th', { class: 'numeric' }, o)))),
        h('tbody', {}, ...Object.entries(correlations).map(([p, row]) => h('tr', {}, h('th', { scope: 'row' }, p),
            ...outputs.map((o) => h('td', { class: 'numeric' }, row[o] === undefined ? '' : row[o].toFixed(3)))))));
}
