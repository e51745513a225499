// A window plotting one variable against another (an XY plot, e.g. force over position) in the
// run its plot window shows, over an optional time range; CSV and PNG export.
import type uPlot from 'uplot';
import type { RunData } from './RunData';
import { DerivedPlotFrame } from './DerivedPlotFrame';
import { PlotSurface } from './PlotSurface';
import { samplesIn } from '../analysis/fft';
import { toCsv } from './RunData';
import { siPrefix, unitOfVariable } from './units';
import { downloadText, errorText, h } from '../ui/dom';

const COLOUR = '#1f6fd1';

// uPlot's own line paths assume x increases (they thin out points per pixel column); an XY
// curve can turn back, so it is drawn point to point.
const pointToPoint: uPlot.Series.PathBuilder = (u, seriesIdx) => {
    const [xs, ys] = u.data[seriesIdx] as unknown as [number[], number[]];
    const stroke = new Path2D();
    for (let i = 0; i < xs.length; i++) {
        const x = u.valToPos(xs[i], 'x', true);
        const y = u.valToPos(ys[i], 'y', true);
        if (i === 0) stroke.moveTo(x, y); else stroke.lineTo(x, y);
    }
    return { stroke, fill: null, clip: null, band: null, gaps: null, flags: 0 } as unknown as uPlot.Series.Paths;
};

export class XyWindow {
    readonly element: HTMLElement;
    private readonly frame: DerivedPlotFrame;
    private readonly surface = new PlotSurface();
    private readonly xSelect: HTMLSelectElement;
    private readonly ySelect: HTMLSelectElement;
    private run: RunData | null = null;
    private points: { x: number[]; y: number[] } | null = null;

    constructor(readonly id: number, variables: string[], private readonly labelOf: (name: string) => string, onClose: (w: XyWindow) => void) {
        const choice = (label: string, selected: string | undefined) => h('select', { 'aria-label': label, onchange: () => this.redraw() },
            ...variables.map((v) => h('option', { value: v, selected: v === selected }, labelOf(v))));
        this.xSelect = choice('X variable', variables[0]);
        this.ySelect = choice('Y variable', variables[1] ?? variables[0]);
        this.frame = new DerivedPlotFrame({
            plotId: `xy${id}`, analysis: 'xy', title: 'XY', closeLabel: 'Close XY plot',
            controls: ['y ', this.ySelect, ' over x ', this.xSelect],
            body: this.surface,
            changed: () => this.redraw(),
            exportCsv: () => this.exportCsv(),
            exportPng: () => this.exportPng(),
            close: () => onClose(this),
        });
        this.element = this.frame.element;
    }

    update(current: RunData | null): void {
        this.run = current;
        if (this.frame.runChanged(current)) this.redraw();
    }

    private redraw(): void {
        const run = this.run;
        const xs = run?.columns.get(this.xSelect.value);
        const ys = run?.columns.get(this.ySelect.value);
        if (!run || !xs || !ys) {
            this.points = null;
            this.frame.setNote(run ? 'The variables are not in this run yet.' : 'Run the model first.');
            return this.surface.clear();
        }
        try {
            const { from, to } = this.frame.timeRange();
            const x = samplesIn({ time: run.time, values: xs }, from, to).values;
            const y = samplesIn({ time: run.time, values: ys }, from, to).values;
            this.points = { x, y };
            this.element.dataset.points = String(x.length);
            this.frame.setNote(`${x.length} points`);
            const label = (v: string) => this.labelOf(v);
            const axis = (name: string, values: number[], size: number): uPlot.Axis => {
                const prefixed = siPrefix(values.reduce((m, v) => Math.max(m, Math.abs(v)), 0), unitOfVariable(name));
                return {
                    label: `${label(name)}${prefixed.unit ? ` [${prefixed.unit}]` : ''}`, size,
                    values: (_u, splits) => splits.map((v) => String(Number((v / prefixed.factor).toPrecision(4)))),
                };
            };
            this.surface.draw({
                mode: 2,
                scales: { x: { time: false, auto: true }, y: { auto: true } },
                cursor: { drag: { x: true, y: true } },
                legend: { show: false },
                axes: [axis(this.xSelect.value, x, 50), axis(this.ySelect.value, y, 64)],
                series: [{}, {
                    label: `${label(this.ySelect.value)} over ${label(this.xSelect.value)}`, stroke: COLOUR, width: 1.5,
                    paths: pointToPoint, points: { show: false },
                    facets: [{ scale: 'x', auto: true }, { scale: 'y', auto: true }],
                } as uPlot.Series],
            }, [null, [x, y]] as unknown as uPlot.AlignedData);
        } catch (e) {
            this.frame.setNote(errorText(e));
        }
    }

    private exportCsv(): void {
        const p = this.points;
        if (!p) return;
        downloadText(`xy-${this.id}.csv`, toCsv([this.ySelect.value], [p.x, p.y], this.xSelect.value), 'text/csv');
    }

    private exportPng(): void {
        this.surface.exportPng(`xy-${this.id}.png`, [{ label: `${this.labelOf(this.ySelect.value)} over ${this.labelOf(this.xSelect.value)}`, colour: COLOUR, dashed: false }]);
    }

    destroy(): void { this.frame.destroy(); }
}
