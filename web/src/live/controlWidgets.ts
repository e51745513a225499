// The input element of each kind of live control: slider, knob, switch, number field. Each
// reports the user's value through `onValue` on every movement and shows a value it is given.
import { h } from '../ui/dom';
import { controlRange, type LiveControl } from './liveControls';

export interface ControlWidget {
    element: HTMLElement;
    show(value: number): void;
    setEnabled(enabled: boolean): void;
}

/** Steps across a slider or knob's range: fine enough to steer, coarse enough to read. */
const STEPS = 200;

export function controlWidget(c: LiveControl, onValue: (v: number) => void): ControlWidget {
    switch (c.kind) {
    case 'slider': return slider(c, onValue);
    case 'knob': return knob(c, onValue);
    case 'switch': return toggle(c, onValue);
    case 'number': return numberField(c, onValue);
    }
}

function slider(c: LiveControl, onValue: (v: number) => void): ControlWidget {
    const input = h('input', { type: 'range', min: String(c.min), max: String(c.max), step: String((c.max - c.min) / STEPS), 'aria-label': c.name, 'data-testid': 'live-control-input' });
    input.addEventListener('input', () => onValue(Number(input.value)));
    return { element: input, show: (v) => { input.value = String(v); }, setEnabled: (on) => { input.disabled = !on; } };
}

/** A round knob: drag up or right to turn it up; arrow keys step it. 270° of turn span the range. */
function knob(c: LiveControl, onValue: (v: number) => void): ControlWidget {
    const dial = h('div', { class: 'live-knob', role: 'slider', tabindex: 0, 'aria-label': c.name, 'aria-valuemin': String(c.min), 'aria-valuemax': String(c.max), 'data-testid': 'live-control-input' },
        h('span', { class: 'live-knob-mark' }));
    let value = c.min;
    let enabled = true;
    const clamp = (v: number) => Math.min(c.max, Math.max(c.min, v));
    const show = (v: number) => {
        value = clamp(v);
        dial.setAttribute('aria-valuenow', String(value));
        dial.style.setProperty('--turn', `${-135 + 270 * (value - c.min) / (c.max - c.min)}deg`);
    };
    const change = (v: number) => {
        if (!enabled) return;
        show(v);
        onValue(value);
    };
    let drag: { y: number; x: number; from: number } | null = null;
    dial.addEventListener('pointerdown', (e) => {
        if (!enabled) return;
        drag = { x: e.clientX, y: e.clientY, from: value };
        dial.setPointerCapture(e.pointerId);
    });
    dial.addEventListener('pointermove', (e) => {
        if (!drag) return;
        const moved = (e.clientX - drag.x) - (e.clientY - drag.y);
        change(drag.from + moved * (c.max - c.min) / 150);
    });
    dial.addEventListener('pointerup', () => { drag = null; });
    dial.addEventListener('keydown', (e) => {
        const by = e.key === 'ArrowUp' || e.key === 'ArrowRight' ? 1 : e.key === 'ArrowDown' || e.key === 'ArrowLeft' ? -1 : 0;
        if (by === 0) return;
        e.preventDefault();
        change(value + by * (c.max - c.min) / 20);
    });
    show(value);
    return { element: dial, show, setEnabled: (on) => { enabled = on; dial.setAttribute('aria-disabled', String(!on)); } };
}

function toggle(c: LiveControl, onValue: (v: number) => void): ControlWidget {
    const { low, high } = controlRange(c);
    const button = h('button', { class: 'live-switch', 'aria-pressed': 'false', 'aria-label': c.name, 'data-testid': 'live-control-input' }, 'off');
    const show = (v: number) => {
        const on = Math.abs(v - high) < Math.abs(v - low);
        button.setAttribute('aria-pressed', String(on));
        button.textContent = on ? 'on' : 'off';
    };
    button.addEventListener('click', () => {
        const v = button.getAttribute('aria-pressed') === 'true' ? low : high;
        show(v);
        onValue(v);
    });
    return { element: button, show, setEnabled: (on) => { button.disabled = !on; } };
}

function numberField(c: LiveControl, onValue: (v: number) => void): ControlWidget {
    const input = h('input', { type: 'number', min: String(c.min), max: String(c.max), step: 'any', 'aria-label': c.name, 'data-testid': 'live-control-input' });
    input.addEventListener('change', () => {
        const v = Number(input.value);
        if (input.value.trim() !== '' && Number.isFinite(v)) onValue(Math.min(c.max, Math.max(c.min, v)));
    });
    return {
        element: input,
        show: (v) => { if (document.activeElement !== input) input.value = String(Number(v.toPrecision(6))); },
        setEnabled: (on) => { input.disabled = !on; },
    };
}
