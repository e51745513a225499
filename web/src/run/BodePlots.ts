// A Bode diagram as Hopsan draws it: gain above phase, two charts on one logarithmic frequency
// axis. The cursor moves on both, a zoom (drag; double-click to undo) on either zooms both, and
// the left axes have one width so the two plot areas line up.
import type uPlot from 'uplot';
import type { Bode } from '../analysis/bode';
import { PlotSurface } from './PlotSurface';
import { downloadBlob, h } from '../ui/dom';
import './bodePlots.css';

const GAIN_COLOUR = '#1f6fd1';
const PHASE_COLOUR = '#d1421f';
const LEFT_AXIS = 64;   // px, both charts: equal widths align the plot areas
// px: the frequency's tick values under each chart, and its name under the phase only
const X_AXIS = 30;
const X_LABEL = 24;
// phase ticks at multiples of the angles one reads a phase by
const DEGREE_STEPS = [1, 2, 5, 10, 15, 30, 45, 90, 180, 360, 720, 1440, 3600, 7200, 14400, 36000];

export class BodePlots {
    readonly element: HTMLElement;
    private readonly gain = new PlotSurface();
    private readonly phase = new PlotSurface();

    /** `syncKey` names the cursor group: unique per window, so other windows' cursors stay apart. */
    constructor(private readonly syncKey: string) {
        this.gain.element.dataset.plot = 'gain';
        this.phase.element.dataset.plot = 'phase';
        // the phase's chart has room for the frequency's name besides: its plot area is as tall as the gain's
        this.phase.element.style.flexBasis = `${X_LABEL}px`;
        this.element = h('div', { class: 'bode-plots' }, this.gain.element, this.phase.element);
    }

    draw(b: Bode): void {
        this.gain.draw(this.options('gain [dB]', GAIN_COLOUR, false), [b.frequency, b.gainDb]);
        this.phase.draw(this.options('phase [°]', PHASE_COLOUR, true), [b.frequency, b.phaseDeg]);
    }

    clear(): void {
        this.gain.clear();
        this.phase.clear();
    }

    private options(label: string, colour: string, bottom: boolean): Omit<uPlot.Options, 'width' | 'height'> {
        return {
            // the range is the data's (or the zoom's) exactly, not widened to whole decades
            scales: { x: { time: false, distr: 3, log: 10, range: (_u, min, max) => [min, max] } },
            // a vertical line at the same frequency on both; a horizontal one would mean nothing on the other
            cursor: { y: false, drag: { x: true, y: false }, sync: { key: this.syncKey, scales: ['x', null] } },
            legend: { live: true },
            axes: [
                // the frequency is named once, under the phase
                bottom ? { label: 'frequency [Hz]', size: X_AXIS, labelSize: X_LABEL } : { size: X_AXIS },
                { label, size: LEFT_AXIS, stroke: colour, incrs: bottom ? DEGREE_STEPS : undefined },
            ],
            series: [{ label: 'frequency [Hz]' }, { label, stroke: colour, width: 1.5 }],
            hooks: { setScale: [(u, key) => { if (key === 'x') this.zoomed(u); }] },
        };
    }

    // One chart's frequency range changed (a zoom, its reset, new data): the other follows.
    private zoomed(u: uPlot): void {
        const { min, max } = u.scales.x;
        if (min === undefined || max === undefined) return;
        for (const surface of [this.gain, this.phase]) {
            surface.element.dataset.xRange = `${min} ${max}`;
            const other = surface.plot;
            if (other && other !== u && (other.scales.x.min !== min || other.scales.x.max !== max)) other.setScale('x', { min, max });
        }
    }

    /** Both charts, gain above phase, in one PNG, with what was compared written under them. */
    exportPng(filename: string, caption: string): void {
        const charts = [this.gain.plot, this.phase.plot];
        if (!charts[0] || !charts[1]) return;
        const [top, bottom] = charts.map((c) => c!.ctx.canvas);
        const dpr = devicePixelRatio || 1;
        const out = document.createElement('canvas');
        out.width = Math.max(top.width, bottom.width);
        out.height = top.height + bottom.height + 30 * dpr;
        const ctx = out.getContext('2d')!;
        ctx.fillStyle = '#fff';
        ctx.fillRect(0, 0, out.width, out.height);
        ctx.drawImage(top, 0, 0);
        ctx.drawImage(bottom, 0, top.height);
        ctx.font = `${12 * dpr}px sans-serif`;
        ctx.fillStyle = '#000';
        ctx.fillText(caption, 10 * dpr, top.height + bottom.height + 20 * dpr);
        out.toBlob((blob) => { if (blob) downloadBlob(filename, blob); });
    }

    destroy(): void {
        this.gain.destroy();
        this.phase.destroy();
        this.element.remove();
    }
}
