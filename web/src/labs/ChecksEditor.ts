// The teacher's checks of an assignment: name, points, whether students may run it as a
// pretest, and what it asks: a curve (a variable against the solution's reference run within
// a relative tolerance) or a scalar (a measure of a variable within min/max). Saving runs the
// solution on the server and stores its reference result with the checks.
// A curve's tolerance is relative to the reference's largest magnitude ("scale": "range") for
// new checks, since the older rule, relative to each reference sample, fails curves near zero;
// a check made with the older rule shows it and keeps it.
import { errorText, h, toast } from '../ui/dom';
import type { CurveCheckDefinition } from '../protocol/types';
import type { Check, CheckDefinition, ScalarMeasure } from './types';
import { SCALAR_MEASURES } from './types';
import { optionalNumber } from './format';

const MEASURE_LABELS: Record<ScalarMeasure, string> = {
    final: 'final value', min: 'minimum', max: 'maximum', overshoot: 'overshoot (%)',
    settling_time: 'settling time (s)', rise_time: 'rise time 10–90 % (s)',
};

export interface ChecksEditorOptions {
    checks: Check[];
    /** false: the checks are shown, not changed (assistants, archived classes) */
    editable: boolean;
    /** whether the assignment has a solution to make the reference run from */
    hasSolution: boolean;
    save: (checks: Check[]) => Promise<void>;
    /** variable names to suggest */
    variables?: string[];
}

let editorCount = 0;

type CurveScale = NonNullable<CurveCheckDefinition['scale']>;

const SCALE_LABELS: Record<CurveScale, string> = {
    range: 'the reference\'s largest magnitude',
    sample: 'each reference sample (.hvc rule)',
};

/** The rule a check's tolerance follows: a curve check stored without `scale` keeps the sample rule; new ones get range. */
export function curveScaleOf(definition?: CheckDefinition): CurveScale {
    if (definition?.kind !== 'curve') return 'range';
    return (definition as CurveCheckDefinition).scale ?? 'sample';
}

/** A check's definition from the row's fields; throws naming the field that is wrong. */
export function readDefinition(fields: {
    kind: string; variable: string; tolerance: string; scale?: string; measure: string; min: string; max: string; band: string;
}, name: string): CheckDefinition {
    const variable = fields.variable.trim();
    if (!variable) throw new Error(`${name}: name the variable (e.g. Mass#P1#x)`);
    const number = (text: string, what: string) => {
        const n = optionalNumber(text);
        if (Number.isNaN(n)) throw new Error(`${name}: ${what} must be a number`);
        return n;
    };
    if (fields.kind === 'curve') {
        const tolerance = number(fields.tolerance, 'the tolerance');
        const curve: CurveCheckDefinition = { kind: 'curve', variable };
        if (tolerance !== undefined) curve.tolerance = tolerance;
        // the sample rule is what the server applies without `scale`: older checks stay as stored
        if (fields.scale === 'range') curve.scale = 'range';
        return curve;
    }
    const measure = fields.measure as ScalarMeasure;
    const min = number(fields.min, 'min');
    const max = number(fields.max, 'max');
    const band = number(fields.band, 'the band');
    if (min === undefined && max === undefined) throw new Error(`${name}: give min, max or both`);
    const definition: CheckDefinition = { kind: 'scalar', variable, measure };
    if (min !== undefined) definition.min = min;
    if (max !== undefined) definition.max = max;
    if (measure === 'settling_time' && band !== undefined) definition.band = band;
    return definition;
}

/** The server names a check by its place (`checks[0]`); the page says its name. */
export function nameChecks(message: string, checks: Check[]): string {
    return message.replace(/checks\[(\d+)\]/g, (whole, index: string) => {
        const check = checks[Number(index)];
        return check ? `Check ${Number(index) + 1} "${check.name}"` : whole;
    });
}

export function checksEditor(options: ChecksEditorOptions): HTMLElement {
    const id = `checks-${++editorCount}`;
    const list = h('div', { class: 'check-list' });
    const suggestions = h('datalist', { id: `${id}-variables` }, ...(options.variables ?? []).map((v) => h('option', { value: v })));
    const disabled = !options.editable;

    const addRow = (check?: Check) => {
        const n = list.children.length + 1;
        const def = check?.definition;
        const name = h('input', { 'aria-label': 'Check name', value: check?.name ?? '', required: true, disabled, class: 'check-name' });
        const points = h('input', { 'aria-label': 'Points', inputmode: 'decimal', value: check?.points ?? 1, disabled, class: 'num' });
        const pretest = h('input', { type: 'checkbox', 'aria-label': 'Pretest', checked: check?.pretest ?? false, disabled });
        const kind = h('select', { 'aria-label': 'Kind', disabled },
            h('option', { value: 'curve', selected: def?.kind !== 'scalar' }, 'curve'),
            h('option', { value: 'scalar', selected: def?.kind === 'scalar' }, 'scalar'));
        const variable = h('input', { 'aria-label': 'Variable', list: suggestions.id, value: def?.variable ?? '', placeholder: 'Mass#P1#x', disabled, class: 'variable-input' });
        const tolerance = h('input', { 'aria-label': 'Tolerance', inputmode: 'decimal', value: def?.kind === 'curve' ? def.tolerance ?? '' : '', placeholder: '0.01', disabled, class: 'num' });
        const measure = h('select', { 'aria-label': 'Measure', disabled },
            ...SCALAR_MEASURES.map((m) => h('option', { value: m, selected: def?.kind === 'scalar' && def.measure === m }, MEASURE_LABELS[m])));
        const min = h('input', { 'aria-label': 'Min', inputmode: 'decimal', value: def?.kind === 'scalar' ? def.min ?? '' : '', disabled, class: 'num' });
        const max = h('input', { 'aria-label': 'Max', inputmode: 'decimal', value: def?.kind === 'scalar' ? def.max ?? '' : '', disabled, class: 'num' });
        const band = h('input', { 'aria-label': 'Band', inputmode: 'decimal', value: def?.kind === 'scalar' ? def.band ?? '' : '', placeholder: '0.02', disabled, class: 'num' });
        const scale = h('select', { 'aria-label': 'Relative to', disabled },
            ...(['range', 'sample'] as const).map((rule) => h('option', { value: rule, selected: curveScaleOf(def) === rule }, SCALE_LABELS[rule])));
        const curveFields = h('span', { class: 'check-fields' },
            h('label', {}, 'tolerance ', tolerance), h('label', {}, 'relative to ', scale));
        const bandLabel = h('label', {}, 'band ', band);
        const scalarFields = h('span', { class: 'check-fields' }, h('label', {}, 'measure ', measure), h('label', {}, 'min ', min), h('label', {}, 'max ', max), bandLabel);
        const showKind = () => {
            curveFields.hidden = kind.value !== 'curve';
            scalarFields.hidden = kind.value !== 'scalar';
            bandLabel.hidden = measure.value !== 'settling_time';
        };
        kind.addEventListener('change', showKind);
        measure.addEventListener('change', showKind);
        showKind();
        const row = h('fieldset', { class: 'check-row', 'aria-label': `Check ${n}` },
            h('div', { class: 'check-line' },
                h('label', {}, 'name ', name), h('label', {}, 'points ', points), h('label', { class: 'inline' }, pretest, ' pretest'),
                options.editable ? h('button', { type: 'button', class: 'small danger', title: 'Remove the check', onclick: () => row.remove() }, '✕') : null),
            h('div', { class: 'check-line' }, h('label', {}, 'kind ', kind), h('label', {}, 'variable ', variable), curveFields, scalarFields));
        (row as HTMLElement & { read?: () => Check }).read = () => {
            const checkName = name.value.trim();
            if (!checkName) throw new Error('Every check needs a name.');
            const p = Number(points.value);
            if (!Number.isFinite(p) || p < 0) throw new Error(`${checkName}: points must be a number ≥ 0`);
            return {
                name: checkName, points: p, pretest: pretest.checked,
                definition: readDefinition({ kind: kind.value, variable: variable.value, tolerance: tolerance.value,
                    scale: scale.value, measure: measure.value, min: min.value, max: max.value, band: band.value }, checkName),
            };
        };
        list.append(row);
    };
    for (const c of options.checks) addRow(c);

    const message = h('p', { class: 'form-error', role: 'alert', 'data-testid': 'checks-error' });
    const saveButton = h('button', { type: 'submit', class: 'primary' }, 'Save checks');
    const form = h('form', {
        class: 'checks-editor', 'aria-label': 'Checks',
        onsubmit: async (e: Event) => {
            e.preventDefault();
            message.textContent = '';
            saveButton.disabled = true;
            saveButton.textContent = 'Running the solution…';
            let checks: Check[] = [];
            try {
                checks = [...list.children].map((row) => (row as HTMLElement & { read: () => Check }).read());
                await options.save(checks);
                toast(`Saved ${checks.length} check${checks.length === 1 ? '' : 's'} and the reference run`);
            } catch (err) {
                message.textContent = nameChecks(errorText(err), checks);
            } finally {
                saveButton.disabled = false;
                saveButton.textContent = 'Save checks';
            }
        },
    },
    !options.hasSolution ? h('p', { class: 'notice' }, 'This assignment has no solution model yet: curve checks need the solution\'s reference run.') : null,
    list, suggestions,
    options.editable ? h('div', { class: 'toolbar' },
        h('button', { type: 'button', onclick: () => addRow(), 'data-testid': 'add-check' }, 'Add check'), saveButton) : null,
    message);
    if (options.checks.length === 0 && !options.editable) list.append(h('p', { class: 'muted' }, 'No checks yet.'));
    return form;
}
