// One plot window: chosen variables of one of the model's runs, the newest unless the user
// stepped back (◀ ▶, Ctrl+← Ctrl+→), and the run before it (or all the others) to compare;
// live while the run goes on; each curve names its run; on demand, each variable's difference
// between two runs (A − B); zoom by dragging, cursor read-out in the legend, CSV and PNG.
// Each axis shows the display unit the user chose for its quantity, or SI prefixes.
// The legend is a compact column beside the graph, one row per curve; two cursors give Δt and
// Δvalue; the window can fill the editor (maximised) or move into a browser window of its own.
import uPlot from 'uplot';
import { alignSeries, type RunData, type SeriesSource } from './RunData';
import { variableLabel } from '../model/variables';
import { downloadText, h, toast } from '../ui/dom';
import { PlotSurface } from './PlotSurface';
import { TwoCursors } from './twoCursors';
import { TimeMarker } from './TimeMarker';
import { detach, type Detached } from './detachedPlot';
import type { AnalysisKind } from './AnalysisWindow';
import { axisUnits, MAX_AXES, siPrefix, unitOfVariable, type Prefixed } from './units';
import { generationText, shownRuns, stepGeneration } from './generations';
import { DifferenceChoice } from './DifferenceChoice';
import { curveDifference } from './curveDifference';
import { displayUnitsOf, toDisplayValues, type DisplayUnit } from './displayUnits';
import { quantityOf } from './quantities';
import type { UnitPreferences } from './unitPreferences';
import { plotCsv, plotCsvInDisplayUnits } from './plotCsv';
import { envelopePaths } from './envelopePaths';
import { fittedRange } from './fittedRange';
import { WheelZoom } from './wheelZoom';
import type { SavedZoom } from './runHistory';

// sixteen that tell apart: a window of many curves repeats no colour before the seventeenth
const COLOURS = ['#1f6fd1', '#d1421f', '#2e8b3d', '#8a4fbf', '#d17a00', '#0f9a9a', '#b8336a', '#555555',
    '#8c6d1f', '#5fa8e8', '#e8845f', '#7cc47f', '#c59be0', '#2b3f8c', '#9e1f1f', '#a8a800'];

/**
 * A curve: its values in the base `unit`, shown in `display` when the user chose one. A
 * `difference` curve is the variable's A − B of the two runs it names ("run 3 − run 2").
 */
interface Plotted { name: string; label: string; source: SeriesSource; previous: boolean; difference?: string; colour: string; unit: string; display: DisplayUnit | null }

/** One y axis: the series of one base unit, in the chosen display unit or with the SI prefix its values need. */
interface Axis { unit: string; scale: string; prefixed: Prefixed }

/** The time axis, named as Hopsan names it. */
const TIME_AXIS = 'Time [s]';

const largestAbs = (values: number[]) => values.reduce((m, v) => (Number.isFinite(v) ? Math.max(m, Math.abs(v)) : m), 0);

export class PlotWindow {
    readonly element: HTMLElement;
    readonly variables: string[] = [];
    /** What the user clicked to get each variable, to name its curve. */
    private readonly labels = new Map<string, string>();
    private readonly units = new Map<string, string>();
    compare = false;
    /** Every run of the window drawn, the shown one solid: overrides compare. */
    allRuns = false;
    private readonly body: HTMLElement;
    private readonly surface: PlotSurface;
    private readonly cursors: TwoCursors;
    /** The playback cursor (the instant the animated diagram shows). */
    private readonly marker = new TimeMarker();
    private readonly chips: HTMLElement;
    private readonly compareBox: HTMLInputElement;
    private readonly allRunsBox: HTMLInputElement;
    private get plot(): uPlot | null { return this.surface.plot; }
    private seriesKey = '';
    private plotted: Plotted[] = [];
    /** x range to show while a run is filling the plot. */
    private span: [number, number] | null = null;
    /** The model's runs, oldest first, as last drawn. */
    private runs: readonly RunData[] = [];
    /** The job the user stepped to; null follows the newest run. */
    private shown: number | null = null;
    private readonly earlierButton: HTMLButtonElement;
    private readonly laterButton: HTMLButtonElement;
    private readonly generation: HTMLElement;
    private readonly difference: DifferenceChoice;
    /** A unit choice per axis whose quantity has several units, and the CSV in those units. */
    private readonly unitBar: HTMLElement;
    private readonly unsubscribeUnits: () => void;
    private readonly cursorsButton: HTMLButtonElement;
    private readonly maximiseButton: HTMLButtonElement;
    private readonly detachButton: HTMLButtonElement;
    /** Where the window was in the list while it is in a browser window of its own. */
    private readonly placeholder: HTMLElement;
    private detached: Detached | null = null;
    private maximised = false;
    /** The axis unit of each plotted curve, in series order (series i + 1). */
    private drawnAxes: Prefixed[] = [];
    /** Wheel zoom and pan of the chart drawn. */
    private wheelZoom: WheelZoom | null = null;
    /** The zoom the window had before a reload, shown again until the user zooms or a run streams in. */
    private restoredZoom: SavedZoom | null = null;

    constructor(readonly id: number, private readonly preferences: UnitPreferences, private readonly actions: {
        close(w: PlotWindow): void; activate(w: PlotWindow): void; changed(w: PlotWindow): void;
        analyse(w: PlotWindow, kind: AnalysisKind | 'xy'): void; zoomed(w: PlotWindow): void;
    }) {
        this.body = h('div', { class: 'plot-body' }, this.emptyNote('Click a port to plot its variables here.'));
        this.cursors = new TwoCursors(() => this.surface.legendRows(), (i, delta) => this.deltaText(i, delta));
        this.surface = new PlotSurface({ beside: true, aside: this.cursors.readout });
        this.cursorsButton = h('button', {
            class: 'small', onclick: () => this.toggleCursors(), title: 'Two cursors: Δt and the Δvalue of each curve', 'aria-label': 'Two cursors', 'aria-pressed': 'false',
        }, 'Δ');
        this.maximiseButton = h('button', { class: 'small', onclick: () => this.setMaximised(!this.maximised), title: 'Maximise', 'aria-label': 'Maximise plot', 'aria-pressed': 'false' }, '⤢');
        this.detachButton = h('button', { class: 'small', onclick: () => this.toggleDetached(), title: 'Open in a browser window of its own', 'aria-label': 'Detach plot' }, '↗');
        this.placeholder = h('p', { class: 'plot-placeholder muted', 'data-plot-id': String(id) }, `Plot ${id} is open in a window of its own. `,
            h('button', { class: 'small', onclick: () => this.detached?.close() }, 'Bring it back'));
        this.chips = h('div', { class: 'plot-chips' });
        this.compareBox = h('input', {
            type: 'checkbox', name: 'compare',
            onchange: () => { this.compare = this.compareBox.checked; this.actions.changed(this); },
        });
        this.allRunsBox = h('input', {
            type: 'checkbox', name: 'allRuns',
            onchange: () => { this.allRuns = this.allRunsBox.checked; this.actions.changed(this); },
        });
        this.earlierButton = h('button', { class: 'small', onclick: () => this.step(-1), title: 'Earlier run (Ctrl+←)', 'aria-label': 'Earlier run' }, '◀');
        this.laterButton = h('button', { class: 'small', onclick: () => this.step(1), title: 'Later run (Ctrl+→)', 'aria-label': 'Later run' }, '▶');
        this.generation = h('span', { class: 'generation', 'data-testid': 'generation' });
        this.difference = new DifferenceChoice(() => this.actions.changed(this));
        this.unitBar = h('div', { class: 'plot-units', hidden: true });
        this.element = h('section', {
            class: 'plot-window', 'data-plot-id': String(id), tabindex: 0,
            onpointerdown: () => this.actions.activate(this),
            onkeydown: (e: KeyboardEvent) => this.onKey(e),
        },
            h('header', { class: 'plot-header' },
                h('strong', {}, `Plot ${id}`), this.chips,
                // one group: in a narrow window it goes below the chips as a whole
                h('div', { class: 'plot-controls' },
                    h('span', { class: 'generations' }, this.earlierButton, this.generation, this.laterButton),
                    h('label', { class: 'compare', title: 'Show the previous run dashed' }, this.compareBox, 'compare with previous run'),
                    h('label', { class: 'compare', title: 'Show every other run dashed, the older the paler' }, this.allRunsBox, 'all runs'),
                    this.difference.button,
                    h('button', { class: 'small', onclick: () => this.actions.analyse(this, 'fft'), title: 'Amplitude spectrum of a plotted variable' }, 'FFT'),
                    h('button', { class: 'small', onclick: () => this.actions.analyse(this, 'bode'), title: 'Gain and phase of one plotted variable against another' }, 'Bode'),
                    h('button', { class: 'small', onclick: () => this.actions.analyse(this, 'xy'), title: 'One plotted variable over another' }, 'XY'),
                    h('button', { class: 'small', onclick: () => this.exportCsv(), title: 'Export the plotted data as CSV' }, 'CSV'),
                    h('button', { class: 'small', onclick: () => this.exportPng(), title: 'Save the plot as PNG' }, 'PNG'),
                    this.cursorsButton, this.maximiseButton, this.detachButton,
                    h('button', { class: 'small', onclick: () => this.actions.close(this), title: 'Close', 'aria-label': 'Close plot' }, '×'))),
            this.unitBar, this.difference.bar, this.body);
        this.element.dataset.timeAxis = TIME_AXIS;
        // a unit chosen here or in another window applies to every axis of its quantity
        this.unsubscribeUnits = preferences.subscribe(() => {
            this.drawUnitBar();
            this.update(this.runs);
        });
    }

    private emptyNote(text: string): HTMLElement {
        return h('p', { class: 'muted plot-empty' }, text);
    }

    setActive(active: boolean): void { this.element.classList.toggle('active', active); }

    add(name: string, label?: string, unit?: string): void {
        if (this.variables.includes(name)) return;
        this.variables.push(name);
        if (label) this.labels.set(name, label);
        this.units.set(name, unit ?? unitOfVariable(name));
        this.drawChips();
        this.drawUnitBar();
    }

    remove(name: string): void {
        const i = this.variables.indexOf(name);
        if (i >= 0) this.variables.splice(i, 1);
        this.labels.delete(name);
        this.drawChips();
        this.drawUnitBar();
        this.actions.changed(this);
    }

    private drawChips(): void {
        this.chips.replaceChildren(...this.variables.map((v) => h('span', { class: 'chip', 'data-variable': v },
            this.labelOf(v), h('button', { class: 'chip-x', 'aria-label': `Remove ${v}`, onclick: () => this.remove(v) }, '×'))));
    }

    private drawUnitBar(): void {
        const choices = axisUnits(this.variables.map((v) => this.unitOf(v))).flatMap((unit) => {
            const quantity = this.quantityOfAxis(unit);
            const units = quantity === null ? [] : displayUnitsOf(quantity);
            return quantity !== null && units.length > 1 ? [this.unitChoice(quantity, units)] : [];
        });
        this.unitBar.hidden = choices.length === 0;
        this.unitBar.replaceChildren(...choices, h('button', {
            class: 'small', onclick: () => this.exportCsvInDisplayUnits(), title: 'Export the plotted data as CSV in the units shown, each column naming its unit',
        }, 'CSV in display units'));
    }

    private unitChoice(quantity: string, units: DisplayUnit[]): HTMLElement {
        const chosen = this.preferences.unitOf(quantity)?.name ?? '';
        const select = h('select', {
            'aria-label': `${quantity} unit`, 'data-quantity': quantity,
            onchange: () => { void this.preferences.choose(quantity, select.value || null); },
        },
        h('option', { value: '', title: 'The base unit with an SI prefix that fits the values (kPa, MPa)' }, 'auto'),
        ...units.map((u) => h('option', { value: u.name }, u.name)));
        select.value = chosen;
        return h('label', { class: 'unit-choice', title: `Unit of ${quantity} in every plot (remembered for you)` }, `${quantity}:`, select);
    }

    /** The quantity of the variables of the axis of base unit `unit`; null when they do not agree or none is known. */
    private quantityOfAxis(unit: string): string | null {
        const quantities = new Set(this.variables.filter((v) => this.unitOf(v) === unit).map((v) => quantityOf(v, unit)));
        return quantities.size === 1 ? [...quantities][0] : null;
    }

    labelOf(name: string): string { return this.labels.get(name) ?? variableLabel(name); }

    unitOf(name: string): string { return this.units.get(name) ?? unitOfVariable(name); }

    /** Whether a variable of this unit fits: one y axis per unit, at most MAX_AXES (more only when the user asks). */
    hasRoomFor(unit: string): boolean {
        const units = this.axisUnits();
        return units.includes(unit) || units.length < MAX_AXES;
    }

    /** The run the window shows: its FFT, Bode and XY windows analyse it. */
    shownRun(): RunData | null { return shownRuns(this.runs, this.shown).run; }

    /** The runs whose data the window needs: the shown one, the one before it, and a difference's two. */
    shownRuns(): RunData[] {
        const { run, before } = shownRuns(this.runs, this.shown);
        const pair = this.difference.pair(this.runs, this.shown);
        const others = this.allRuns ? this.runs : [before];
        return [...new Set([run, ...others, pair?.a, pair?.b])].filter((r): r is RunData => !!r);
    }

    /** Shows the run of job `jobId` (chosen from the run history) until the user steps or a new run comes. */
    show(jobId: number): void { this.shown = jobId; }

    /** Shows the run `by` runs later (or earlier, if negative) than the one shown. */
    step(by: number): void {
        this.shown = stepGeneration(this.runs, this.shown, by);
        this.actions.changed(this);
    }

    /** The units of the window's axes, in order. */
    axisUnits(): string[] {
        return axisUnits(this.variables.map((v) => this.unitOf(v)));
    }

    /** Fills the editor with the window (Esc restores it), as Hopsan users expect of a plot. */
    private setMaximised(on: boolean): void {
        if (on === this.maximised || (on && this.detached)) return;
        this.maximised = on;
        this.element.classList.toggle('maximised', on);
        this.maximiseButton.setAttribute('aria-pressed', String(on));
        this.maximiseButton.setAttribute('aria-label', on ? 'Restore plot' : 'Maximise plot');
        this.maximiseButton.title = on ? 'Restore (Esc)' : 'Maximise';
        this.maximiseButton.textContent = on ? '⤡' : '⤢';
        // on the document: Esc restores wherever the focus is (and deselects nothing in the drawing)
        if (on) document.addEventListener('keydown', this.escape, true);
        else document.removeEventListener('keydown', this.escape, true);
    }

    private readonly escape = (e: KeyboardEvent): void => {
        if (e.key !== 'Escape') return;
        e.preventDefault();
        e.stopPropagation();
        this.setMaximised(false);
    };

    /** Into a browser window of its own, which keeps streaming; or back from it. */
    private toggleDetached(): void {
        if (this.detached) {
            this.detached.close();
            return;
        }
        this.setMaximised(false);
        this.element.before(this.placeholder);
        this.detached = detach(this.element, `Plot ${this.id}`, () => this.attachBack());
        if (!this.detached) {
            this.placeholder.remove();
            toast('The browser blocked the new window: allow pop-ups for this site to detach a plot.', 'error');
            return;
        }
        this.element.classList.add('detached');
        this.surface.moved();
        this.detachButton.setAttribute('aria-label', 'Attach plot');
        this.detachButton.title = 'Back into the editor';
        this.detachButton.textContent = '↙';
    }

    private attachBack(): void {
        this.detached = null;
        this.element.classList.remove('detached');
        if (this.placeholder.isConnected) this.placeholder.replaceWith(this.element);
        this.surface.moved();
        this.detachButton.setAttribute('aria-label', 'Detach plot');
        this.detachButton.title = 'Open in a browser window of its own';
        this.detachButton.textContent = '↗';
    }

    private toggleCursors(): void {
        this.cursors.toggle();
        this.cursorsButton.setAttribute('aria-pressed', String(this.cursors.shown));
    }

    private onKey(e: KeyboardEvent): void {
        if (!(e.ctrlKey || e.metaKey) || (e.key !== 'ArrowLeft' && e.key !== 'ArrowRight')) return;
        e.preventDefault();
        this.step(e.key === 'ArrowLeft' ? -1 : 1);
    }

    /**
     * Redraws with the data of the model's runs (oldest first). A new run is shown as it
     * comes, even if the user had stepped back.
     */
    update(runs: readonly RunData[]): void {
        if (runs.at(-1) !== this.runs.at(-1)) this.shown = null;
        this.runs = runs;
        const { run: current, before: previous } = shownRuns(runs, this.shown);
        // showing the newest run means following the runs that come after it
        if (current === runs.at(-1)) this.shown = null;
        const pair = this.difference.pair(runs, this.shown);
        this.difference.draw(runs, pair);
        this.generation.textContent = generationText(runs, this.shown);
        this.earlierButton.disabled = previous === null;
        this.laterButton.disabled = this.shown === null;
        // the runs drawn dashed beside the shown one, the newest first
        const compared = this.allRuns ? runs.filter((r) => r !== current).reverse() : this.compare && previous ? [previous] : [];
        const plotted: Plotted[] = [];
        this.variables.forEach((name, i) => {
            const colour = COLOURS[i % COLOURS.length];
            const unit = this.unitOf(name);
            const display = this.preferences.unitOf(this.quantityOfAxis(unit));
            // a chosen unit is named in the legend: the axis may be far from the curve
            const label = (run: RunData) => `${this.labelOf(name)} (${run.label})${display ? ` [${display.name}]` : ''}`;
            const col = current?.columns.get(name);
            if (current && col) plotted.push({ name, label: label(current), source: { time: current.time, data: col }, previous: false, colour, unit, display });
            compared.forEach((other, age) => {
                const old = other.columns.get(name);
                if (old) plotted.push({ name, label: label(other), source: { time: other.time, data: old }, previous: true, colour: paler(colour, age), unit, display });
            });
            const [a, b] = [pair?.a.columns.get(name), pair?.b.columns.get(name)];
            if (pair && a && b) {
                const runsText = `${pair.a.label} − ${pair.b.label}`;
                plotted.push({
                    name, label: `${this.labelOf(name)}: ${runsText}${display ? ` [${display.name}]` : ''}`, difference: runsText,
                    source: curveDifference({ time: pair.a.time, data: a }, { time: pair.b.time, data: b }), previous: false, colour, unit,
                    // a difference of temperatures has no offset: 10 K apart is 10 °C apart
                    display: display && { ...display, offset: 0 },
                });
            }
        });
        this.plotted = plotted;
        this.span = current && !current.finished ? current.span : null;
        if (this.span) this.restoredZoom = null;
        this.element.dataset.job = current ? String(current.jobId) : '';
        this.element.dataset.state = current?.state ?? '';
        if (plotted.length === 0) {
            this.surface.clear();
            this.seriesKey = '';
            this.element.dataset.points = '0';
            this.body.replaceChildren(this.emptyNote(this.variables.length ? 'No data yet: run the model.' : 'Click a port to plot its variables here.'));
            return;
        }
        const data = alignSeries(plotted.map((p) => (p.display ? { time: p.source.time, data: toDisplayValues(p.source.data, p.display) } : p.source)));
        this.element.dataset.points = String(data[0].length);
        const axes = this.axes(plotted);
        this.drawnAxes = plotted.map((p) => axes.find((a) => a.unit === p.unit)!.prefixed);
        // a new prefix (the values grew from kPa to MPa) needs new axes
        this.element.dataset.axes = axes.map((a) => a.prefixed.unit).join(',');
        const key = [...plotted.map((p) => p.label), ...axes.map((a) => a.prefixed.unit)].join('|');
        if (!this.plot || key !== this.seriesKey) {
            this.seriesKey = key;
            if (this.surface.element.parentNode !== this.body) this.body.replaceChildren(this.surface.element);
            const u = this.surface.draw(this.options(plotted, axes), data as uPlot.AlignedData);
            if (this.restoredZoom) this.wheelZoom?.restore(u, this.restoredZoom);
        } else {
            this.plot.setData(data as uPlot.AlignedData, !this.zoomed());
        }
    }

    /** Marks `time` with the playback cursor (null: no cursor). */
    setPlaybackTime(time: number | null): void {
        this.marker.set(time);
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

    /** The zoom to remember for the window: as restored until the user changes it, else as shown. */
    zoom(): SavedZoom | undefined {
        if (this.restoredZoom) return this.restoredZoom;
        return this.plot && this.wheelZoom ? this.wheelZoom.saved(this.plot) : undefined;
    }

    /** Shows `zoom` (remembered from before a reload) once the window has data. */
    restoreZoom(zoom: SavedZoom): void {
        this.restoredZoom = zoom;
        if (this.plot) this.wheelZoom?.restore(this.plot, zoom);
    }

    private userZoomed(): void {
        this.restoredZoom = null;
        this.actions.zoomed(this);
    }

    private deltaText(series: number, delta: number): string {
        const axis = this.drawnAxes[series - 1];
        return axis ? readout(delta, axis) : String(delta);
    }

    private axes(plotted: Plotted[]): Axis[] {
        return axisUnits(plotted.map((p) => p.unit)).map((unit, i) => {
            const series = plotted.filter((p) => p.unit === unit);
            const display = series[0].display;
            return {
                unit, scale: `y${i}`,
                prefixed: display ? { factor: 1, unit: display.name } : siPrefix(Math.max(...series.map((p) => largestAbs(p.source.data))), unit),
            };
        });
    }

    private options(plotted: Plotted[], axes: Axis[]): Omit<uPlot.Options, 'width' | 'height'> {
        // a saved y range is of the values as drawn: in the display unit, or in the base unit whatever prefix the ticks show
        this.wheelZoom = new WheelZoom(() => this.userZoomed(), new Map(axes.map((a) => [a.scale, a.prefixed.factor === 1 ? a.prefixed.unit : a.unit])));
        // long curves are drawn and ranged without walking every sample in view on each frame
        const paths = envelopePaths();
        const range = fittedRange();
        return {
            plugins: [this.wheelZoom.plugin()],
            scales: { x: { time: false, range: (_u, min, max) => this.span ?? [min, max] }, ...Object.fromEntries(axes.map((a) => [a.scale, { range }])) },
            // the cursor moves in every plot window at once (same time axis)
            cursor: { drag: { x: true, y: false }, sync: { key: 'run-time' } },
            // the previous run's marker dashed like its curve
            legend: { live: true, markers: { dash: (u, i) => (u.series[i].dash ? 'dashed' : 'solid') } },
            hooks: { draw: [(u) => { this.cursors.draw(u); this.marker.place(u); }] },
            axes: [{ label: TIME_AXIS, size: 50 }, ...axes.map((a, i): uPlot.Axis => ({
                scale: a.scale, label: a.prefixed.unit ? `[${a.prefixed.unit}]` : undefined, size: 64,
                // left, right, left, right: a fourth unit gets an axis of its own
                side: i % 2 === 1 ? 1 : 3, grid: { show: i === 0 },
                values: (_u, splits) => splits.map((v) => formatTick(v / a.prefixed.factor)),
            }))],
            series: [
                { label: 'Time', value: (_u, v) => readout(v, { factor: 1, unit: 's' }) },
                ...plotted.map((p): uPlot.Series => {
                    const axis = axes.find((a) => a.unit === p.unit)!;
                    return {
                        label: p.label, stroke: p.colour, width: 1.5, dash: p.previous ? [6, 4] : p.difference ? [2, 3] : undefined, spanGaps: true, scale: axis.scale, paths, auto: false,
                        value: (_u, v) => readout(v, axis.prefixed),
                    };
                }),
            ],
        };
    }

    /** Values of a variable of the shown run (or the one before) as logged, in its base unit (tests read the last one). */
    seriesData(name: string, previous = false): number[] {
        return this.plotted.find((p) => p.name === name && p.previous === previous && !p.difference)?.source.data ?? [];
    }

    /** A variable's difference curve as drawn, in its base unit (tests read it). */
    differenceData(name: string): SeriesSource | null {
        return this.plotted.find((p) => p.name === name && p.difference)?.source ?? null;
    }

    private exportCsv(): void {
        if (this.plotted.length === 0) return;
        downloadText(`plot-${this.id}.csv`, plotCsv(this.plotted), 'text/csv');
    }

    private exportCsvInDisplayUnits(): void {
        if (this.plotted.length === 0) return;
        downloadText(`plot-${this.id}-units.csv`, plotCsvInDisplayUnits(this.plotted), 'text/csv');
    }

    private exportPng(): void {
        this.surface.exportPng(`plot-${this.id}.png`, this.plotted.map((p) => ({ label: p.label, colour: p.colour, dashed: p.previous || !!p.difference })));
    }

    destroy(): void {
        this.setMaximised(false);
        this.detached?.close();
        this.placeholder.remove();
        this.unsubscribeUnits();
        this.surface.destroy();
        this.element.remove();
    }
}

/** `colour` ('#rrggbb') paler by `age` steps, so that runs compared at once tell apart. */
function paler(colour: string, age: number): string {
    if (age === 0) return colour;
    const alpha = Math.max(0.3, 1 - 0.3 * age);
    return colour + Math.round(alpha * 255).toString(16).padStart(2, '0');
}

function formatTick(v: number): string {
    return Math.abs(v) < 1e-12 ? '0' : String(Number(v.toPrecision(4)));
}

/** The cursor read-out of a value in the unit of its axis ("219.063 bar"; "-- bar" off the plot, so the legend always names the unit). */
function readout(v: number | null, axis: Prefixed): string {
    if (v === null) return axis.unit ? `-- ${axis.unit}` : '--';
    const value = String(Number((v / axis.factor).toPrecision(6)));
    return axis.unit ? `${value} ${axis.unit}` : value;
}
