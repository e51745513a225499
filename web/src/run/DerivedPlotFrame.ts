// The frame of a window that plots something derived from a run (a spectrum, a
// Bode diagram, an XY curve): a header with the window's own controls, a time range, a note,
// CSV, PNG and close buttons, and the window's plot (or plots) below. It also tells its window
// when the run has changed, so the window recomputes only then.
import type { RunData } from './RunData';
import { h } from '../ui/dom';

/** What the frame shows below its header: a plot surface, or the Bode diagram's two. */
export interface PlotBody { readonly element: HTMLElement; destroy(): void }

export interface DerivedPlotOptions {
    plotId: string;
    analysis: string;                 // data-analysis: 'fft', 'bode' or 'xy'
    title: string;
    closeLabel: string;
    controls: (Node | string)[];      // between the title and the time range
    body: PlotBody;
    changed(): void;                  // the time range was edited
    exportCsv(): void;
    exportPng(): void;
    close(): void;
}

export interface TimeRange { from?: number; to?: number }

export class DerivedPlotFrame {
    readonly element: HTMLElement;
    private readonly body: PlotBody;
    private readonly note: HTMLElement;
    private readonly fromInput: HTMLInputElement;
    private readonly toInput: HTMLInputElement;
    private computedFor = '';

    constructor(o: DerivedPlotOptions) {
        this.body = o.body;
        const time = (name: string, label: string, placeholder: string) =>
            h('input', { name, 'aria-label': label, size: 6, placeholder, onchange: () => o.changed() });
        this.fromInput = time('from', 'From time', 'start');
        this.toInput = time('to', 'To time', 'end');
        this.note = h('span', { class: 'analysis-note', 'data-testid': 'analysis-note' });
        this.element = h('section', { class: 'plot-window analysis-window', 'data-analysis': o.analysis, 'data-plot-id': o.plotId },
            h('header', { class: 'plot-header' },
                h('strong', {}, o.title), ...o.controls, this.fromInput, '–', this.toInput, ' s', this.note,
                h('button', { class: 'small', onclick: () => o.exportCsv(), title: 'Export as CSV' }, 'CSV'),
                h('button', { class: 'small', onclick: () => o.exportPng(), title: 'Save as PNG' }, 'PNG'),
                h('button', { class: 'small', onclick: () => o.close(), title: 'Close', 'aria-label': o.closeLabel }, '×')),
            h('div', { class: 'plot-body' }, o.body.element));
    }

    /** True when `run` is not the run (or the state of it) the window last computed for. */
    runChanged(run: RunData | null): boolean {
        const key = run ? `${run.jobId}:${run.state}:${run.time.length}` : '';
        if (key === this.computedFor) return false;
        this.computedFor = key;
        return true;
    }

    /** The time range typed in; a blank or non-numeric end is open. */
    timeRange(): TimeRange {
        const read = (input: HTMLInputElement) => {
            const text = input.value.trim();
            return text === '' || !Number.isFinite(Number(text)) ? undefined : Number(text);
        };
        return { from: read(this.fromInput), to: read(this.toInput) };
    }

    setNote(text: string): void { this.note.textContent = text; }

    destroy(): void {
        this.body.destroy();
        this.element.remove();
    }
}
