// The pressure colour scale over the canvas: the gradient with its low and high ends in bar,
// which the user may fix (typing a number turns the automatic range off; Auto turns it back on).
import { h } from '../ui/dom';
import { scaleGradient, type PressureRange } from './pressureScale';

const BAR = 1e5;   // Pa per bar: Hopsan users read line pressures in bar
const barText = (pa: number) => (Math.round((pa / BAR) * 10) / 10).toString();

export class ColourScale {
    readonly element: HTMLElement;
    private readonly low: HTMLInputElement;
    private readonly high: HTMLInputElement;
    private readonly auto: HTMLInputElement;
    private shown = '';

    /** `changed` is told when the user sets the range. */
    constructor(private readonly range: PressureRange, changed: () => void) {
        const set = () => {
            const [lo, hi] = [Number(this.low.value), Number(this.high.value)];
            if (!Number.isFinite(lo) || !Number.isFinite(hi) || lo === hi) return;
            range.set(lo * BAR, hi * BAR);
            this.auto.checked = false;
            changed();
        };
        this.low = h('input', { type: 'number', class: 'scale-low', step: 'any', 'aria-label': 'Low end of the pressure scale [bar]', onchange: set });
        this.high = h('input', { type: 'number', class: 'scale-high', step: 'any', 'aria-label': 'High end of the pressure scale [bar]', onchange: set });
        this.auto = h('input', {
            type: 'checkbox', checked: range.auto, class: 'scale-auto',
            onchange: () => {
                if (this.auto.checked) range.set(0, 0, true);
                else range.set(range.min, range.max);
                changed();
            },
        });
        const bar = h('div', { class: 'scale-bar' });
        // set through the CSSOM: the server's Content Security Policy refuses inline style attributes
        bar.style.background = scaleGradient();
        this.element = h('div', { class: 'pressure-scale', 'data-testid': 'pressure-scale', title: 'Line colour: pressure' },
            h('div', { class: 'scale-title' }, 'Pressure [bar]'),
            bar,
            h('div', { class: 'scale-ends' }, this.low, this.high),
            h('label', { class: 'scale-auto-label', title: 'The range of the pressures shown so far' }, this.auto, ' Auto'));
    }

    /** Writes the range's ends (while the user is not typing in them). */
    update(): void {
        const key = `${this.range.min} ${this.range.max} ${this.range.auto}`;
        if (key === this.shown) return;
        this.shown = key;
        const typing = document.activeElement;
        if (typing !== this.low) this.low.value = barText(this.range.min);
        if (typing !== this.high) this.high.value = barText(this.range.max);
        this.auto.checked = this.range.auto;
    }
}
