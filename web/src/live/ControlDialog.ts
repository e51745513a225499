// "Add live control" (and ✎ on one): which value the control sets, its kind, and its range
// (a switch: its off and on values). The values offered are those the last live session said
// may change; before one ran here, the component's number parameters (its inputs among them).
import { h } from '../ui/dom';
import { runModalForm } from '../ui/modalForm';
import { CONTROL_KINDS, controlProblem, type LiveControl, type LiveControlKind } from './liveControls';

export interface ControlChoice { name: string; value: number }

const KIND_LABELS: Record<LiveControlKind, string> = { slider: 'Slider', knob: 'Knob', switch: 'Switch', number: 'Number field' };

/** A range around a start value: 0 to twice it (or ±1 around zero). */
export function defaultRange(value: number): { min: number; max: number } {
    if (value === 0) return { min: 0, max: 1 };
    return value > 0 ? { min: 0, max: 2 * value } : { min: 2 * value, max: 0 };
}

/**
 * Asks for a control's settings; resolves with it, or null when cancelled. `initial` is the
 * control to change, or where a new one goes with the value to preselect.
 */
export function askForControl(choices: ControlChoice[], initial: LiveControl): Promise<LiveControl | null> {
    const dialog = h('dialog', { class: 'live-control-dialog', 'data-testid': 'live-control-dialog', 'aria-label': 'Live control' });
    const list = h('datalist', { id: 'live-value-choices' }, ...choices.map((c) => h('option', { value: c.name })));
    const name = h('input', { name: 'live-name', list: 'live-value-choices', value: initial.name, size: 28, 'aria-label': 'Value it sets' });
    const kind = h('select', { name: 'live-kind', 'aria-label': 'Kind' }, ...CONTROL_KINDS.map((k) => h('option', { value: k }, KIND_LABELS[k])));
    kind.value = initial.kind;
    const number = (label: string, value: number | undefined) => h('input', { name: `live-${label.toLowerCase()}`, 'aria-label': label, inputmode: 'decimal', size: 8, value: value === undefined ? '' : String(value) });
    const min = number('Min', initial.min);
    const max = number('Max', initial.max);
    const off = number('Off', initial.off ?? initial.min);
    const on = number('On', initial.on ?? initial.max);
    const error = h('p', { class: 'form-error', role: 'alert' });
    const field = (label: string, input: HTMLElement) => h('label', {}, label, ' ', input);
    const switchFields = h('div', { class: 'live-switch-fields' }, field('Off', off), field('On', on));
    const rangeFields = h('div', { class: 'live-range-fields' }, field('Min', min), field('Max', max));
    const showKind = () => {
        switchFields.hidden = kind.value !== 'switch';
        rangeFields.hidden = kind.value === 'switch';
    };
    // a new value named: its range starts around its start value
    name.addEventListener('change', () => {
        const chosen = choices.find((c) => c.name === name.value.trim());
        if (!chosen) return;
        const range = defaultRange(chosen.value);
        min.value = String(range.min);
        max.value = String(range.max);
    });
    kind.addEventListener('change', showKind);
    showKind();
    const ok = h('button', { class: 'primary', type: 'submit', 'data-testid': 'live-control-ok' }, 'OK');
    const cancel = h('button', { type: 'button' }, 'Cancel');
    const form = h('form', { method: 'dialog' },
        h('h2', {}, 'Live control'),
        field('Value it sets', name), list,
        field('Kind', kind), rangeFields, switchFields, error,
        h('div', { class: 'dialog-buttons' }, ok, cancel));
    dialog.append(form);
    return runModalForm(dialog, form, cancel, () => {
        const k = kind.value as LiveControlKind;
        const control: LiveControl = { ...initial, kind: k, name: name.value.trim(), min: Number(min.value), max: Number(max.value) };
        if (k === 'switch') {
            control.off = Number(off.value);
            control.on = Number(on.value);
            control.min = Math.min(control.off, control.on);
            control.max = Math.max(control.off, control.on);
        } else {
            delete control.off;
            delete control.on;
        }
        const problem = control.name === '' ? 'Name the value it sets.' : controlProblem(control);
        if (problem) {
            error.textContent = problem;
            return undefined;
        }
        return control;
    }, name);
}
