// @vitest-environment jsdom
import { afterEach, describe, expect, it } from 'vitest';
import { controlWidget } from './controlWidgets';
import type { LiveControl } from './liveControls';

const control = (kind: LiveControl['kind'], more: Partial<LiveControl> = {}): LiveControl =>
    ({ kind, name: 'Step.y_A', min: 0, max: 1, x: 0, y: 0, path: [], ...more });

function record(c: LiveControl) {
    const sent: number[] = [];
    const widget = controlWidget(c, (v) => sent.push(v));
    document.body.append(widget.element);
    return { widget, sent };
}

describe('live control widgets', () => {
    afterEach(() => document.body.replaceChildren());

    it('a slider sends every movement within its range', () => {
        const { widget, sent } = record(control('slider', { min: -0.01, max: 0.01 }));
        const input = widget.element as HTMLInputElement;
        expect([input.min, input.max]).toEqual(['-0.01', '0.01']);
        input.value = '0.005';
        input.dispatchEvent(new Event('input'));
        input.value = '-0.002';
        input.dispatchEvent(new Event('input'));
        expect(sent).toEqual([0.005, -0.002]);
    });

    it('a switch sends its on and off values in turn, and shows a value it is given', () => {
        const { widget, sent } = record(control('switch', { off: 2, on: 5, min: 2, max: 5 }));
        const button = widget.element as HTMLButtonElement;
        button.click();
        button.click();
        expect(sent).toEqual([5, 2]);
        widget.show(5);
        expect(button.getAttribute('aria-pressed')).toBe('true');
    });

    it('a knob steps with the arrow keys and stops at its ends', () => {
        const { widget, sent } = record(control('knob', { min: 0, max: 2 }));
        const key = (k: string) => widget.element.dispatchEvent(new KeyboardEvent('keydown', { key: k, bubbles: true }));
        key('ArrowUp');
        key('ArrowRight');
        expect(sent).toEqual([0.1, 0.2]);
        key('ArrowDown');
        key('ArrowDown');
        key('ArrowDown');
        expect(sent.at(-1)).toBe(0);
        widget.setEnabled(false);
        key('ArrowUp');
        expect(sent).toHaveLength(5);
    });

    it('a number field sends what is typed, kept within its range', () => {
        const { widget, sent } = record(control('number', { min: 0, max: 10 }));
        const input = widget.element as HTMLInputElement;
        for (const typed of ['4.5', '99', '']) {
            input.value = typed;
            input.dispatchEvent(new Event('change'));
        }
        expect(sent).toEqual([4.5, 10]);
    });
});
