// An objective evaluated on one run's result, as the server evaluates it on each study run
// (server/studies/RunMeasures.cpp): the form shows it for the model's latest run before the
// optimisation starts, so a wrong variable or weight shows at once.
import type { ResultsJson } from '../protocol/types';
import type { ObjectiveTermForm } from './studyForm';

const finalValue = (v: number[]) => (v.length === 0 ? NaN : v[v.length - 1]);
const minValue = (v: number[]) => (v.length === 0 ? NaN : Math.min(...v));
const maxValue = (v: number[]) => (v.length === 0 ? NaN : Math.max(...v));

/** The time average by the trapezoidal rule; the value itself for one sample. */
export function timeAverage(time: number[], v: number[]): number {
    const n = Math.min(time.length, v.length);
    if (n === 0) return NaN;
    if (n === 1 || time[n - 1] === time[0]) return v[0];
    let integral = 0;
    for (let i = 1; i < n; ++i) integral += 0.5 * (v[i] + v[i - 1]) * (time[i] - time[i - 1]);
    return integral / (time[n - 1] - time[0]);
}

/** Per cent past the final value, relative to the change from the first sample; 0 when it does not pass. */
export function overshootPercent(v: number[]): number {
    if (v.length === 0) return NaN;
    const change = v[v.length - 1] - v[0];
    if (change === 0) return 0;
    const last = v[v.length - 1];
    const beyond = change > 0 ? maxValue(v) - last : last - minValue(v);
    return Math.max(0, beyond) / Math.abs(change) * 100;
}

export function integralSquaredError(time: number[], v: number[], reference: number[]): number {
    const n = Math.min(time.length, v.length, reference.length);
    let integral = 0;
    for (let i = 1; i < n; ++i) {
        const e0 = v[i - 1] - reference[i - 1];
        const e1 = v[i] - reference[i];
        integral += 0.5 * (e0 * e0 + e1 * e1) * (time[i] - time[i - 1]);
    }
    return integral;
}

export type Preview = { ok: true; value: number; terms: number[] } | { ok: false; reason: string };

/** The weighted sum of the terms on `result`; a missing variable or a wrong weight says so. */
export function previewObjective(terms: ObjectiveTermForm[], result: ResultsJson): Preview {
    if (terms.length === 0) return { ok: false, reason: 'no terms' };
    const data = (name: string) => result.variables.find((v) => v.name === name)?.data;
    const values: number[] = [];
    for (const t of terms) {
        const v = data(t.variable);
        if (!v) return { ok: false, reason: `the latest run has no variable ${t.variable || '(none chosen)'}` };
        const weight = Number(t.weight);
        if (t.weight.trim() === '' || !Number.isFinite(weight)) return { ok: false, reason: `weight "${t.weight}" is not a number` };
        let value: number;
        if (t.fn === 'overshoot') value = overshootPercent(v);
        else if (t.fn === 'ise') {
            const reference = data(t.reference);
            if (!reference) return { ok: false, reason: `the latest run has no variable ${t.reference || '(no reference chosen)'}` };
            value = integralSquaredError(result.time, v, reference);
        } else {
            value = t.fn === 'final' ? finalValue(v) : t.fn === 'min' ? minValue(v) : t.fn === 'max' ? maxValue(v) : timeAverage(result.time, v);
            const target = t.target.trim() === '' ? NaN : Number(t.target);
            if (Number.isFinite(target)) value = (value - target) ** 2;
        }
        values.push(weight * value);
    }
    return { ok: true, value: values.reduce((a, b) => a + b, 0), terms: values };
}

/** The variables the terms read (what to fetch of the latest run). */
export function termVariables(terms: ObjectiveTermForm[]): string[] {
    return [...new Set(terms.flatMap((t) => (t.fn === 'ise' ? [t.variable, t.reference] : [t.variable])).filter((v) => v !== ''))];
}
