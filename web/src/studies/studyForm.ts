// What the study form holds (texts, as typed) and the request built from it. Every number is
// checked here, so a wrong field is named before anything is sent.
import type { StudyCreate, StudyKind } from './studyTypes';
import type { StudyParameter } from './studyParameters';

export type SweepMode = 'grid' | 'list' | 'random';
export type Statistic = 'final' | 'min' | 'max' | 'mean';
export type TermFunction = Statistic | 'overshoot' | 'ise';
export type Algorithm = 'complex-rf' | 'nelder-mead' | 'particle-swarm';

/** One chosen parameter, with the fields of every kind (the form keeps them when the kind changes). */
export interface ParameterChoice {
    name: string;
    unit: string;
    /** sweep (grid, random) and optimise: the range; sweep: the number of values, both ends included. */
    from: string; to: string; steps: string;
    /** sweep: an explicit list of values instead of the range (always for mode list). */
    useList: boolean; list: string;
    /** sensitivity */
    distribution: 'normal' | 'uniform'; mean: string; sd: string; min: string; max: string;
    /** optimise: where the search starts (empty: the algorithm chooses). */
    start: string;
}

export interface ObjectiveTermForm { fn: TermFunction; variable: string; reference: string; target: string; weight: string }

export interface StudyForm {
    kind: StudyKind;
    name: string;
    parameters: ParameterChoice[];
    sweepMode: SweepMode; samples: string; seed: string;
    runs: string;
    outputs: string[]; statistics: Statistic[];
    algorithm: Algorithm; goal: 'minimise' | 'maximise'; terms: ObjectiveTermForm[]; maxEvaluations: string; tolerance: string;
    /** Empty: the model's own. */
    stop: string; logSamples: string;
}

export function defaultForm(kind: StudyKind = 'sweep'): StudyForm {
    return {
        kind, name: '', parameters: [], sweepMode: 'grid', samples: '20', seed: '1', runs: '50',
        outputs: [], statistics: ['final', 'max'],
        algorithm: 'complex-rf', goal: 'minimise', terms: [], maxEvaluations: '100', tolerance: '',
        stop: '', logSamples: '',
    };
}

const text = (n: number) => String(Number(n.toPrecision(6)));

/** A parameter's fields from its current value: ±50 % (0 to 1 for a value of 0), ±10 % as σ. */
export function choiceFor(p: StudyParameter): ParameterChoice {
    const v = p.value ?? 0;
    const [from, to] = v === 0 ? [0, 1] : [Math.min(v * 0.5, v * 1.5), Math.max(v * 0.5, v * 1.5)];
    return {
        name: p.name, unit: p.unit, from: text(from), to: text(to), steps: '5', useList: false, list: p.value === null ? '' : text(v),
        distribution: 'normal', mean: text(v), sd: text(v === 0 ? 0.1 : Math.abs(v) * 0.1), min: text(from), max: text(to), start: p.value === null ? '' : text(v),
    };
}

export function emptyTerm(variable = ''): ObjectiveTermForm {
    return { fn: 'overshoot', variable, reference: '', target: '', weight: '1' };
}

export type BuildResult = { ok: true; request: StudyCreate } | { ok: false; errors: string[] };

/** The request for model `modelId`; the errors name each wrong field. */
export function buildStudyRequest(form: StudyForm, modelId: number): BuildResult {
    const errors: string[] = [];
    const num = (value: string, what: string, rule: (n: number) => boolean = () => true, ruleText = ''): number => {
        const n = Number(value.trim());
        if (value.trim() === '' || !Number.isFinite(n)) errors.push(`${what}: "${value}" is not a number`);
        else if (!rule(n)) errors.push(`${what}: ${ruleText}`);
        return n;
    };
    const count = (value: string, what: string) => num(value, what, (n) => Number.isInteger(n) && n >= 1, 'a whole number of at least 1');
    const optionalNumber = (value: string, what: string) => (value.trim() === '' ? undefined : num(value, what));
    const list = (value: string, what: string): number[] => {
        const items = value.split(/[\s,;]+/).filter((s) => s !== '');
        if (items.length === 0) errors.push(`${what}: no values`);
        return items.map((s, i) => num(s, `${what} value ${i + 1}`));
    };

    if (form.parameters.length === 0) errors.push('Choose at least one parameter');
    const request: StudyCreate = { kind: form.kind, model_id: modelId };
    if (form.name.trim()) request.name = form.name.trim();
    const stop = optionalNumber(form.stop, 'Stop time');
    if (stop !== undefined) request.stop = stop;
    const logSamples = form.logSamples.trim() === '' ? undefined : count(form.logSamples, 'Log samples');
    if (logSamples !== undefined) request.log_samples = logSamples;
    const outputs = () => {
        if (form.outputs.length > 0 && form.statistics.length === 0) errors.push('Outputs: choose at least one value (final, min, max, mean)');
        return { variables: [...form.outputs], values: [...form.statistics] };
    };
    const objective = () => {
        if (form.terms.length === 0) errors.push('Objective: add at least one term');
        return {
            goal: form.goal,
            terms: form.terms.map((t, i) => {
                const what = `Objective term ${i + 1}`;
                if (!t.variable) errors.push(`${what}: choose a variable`);
                const term: Record<string, unknown> = { function: t.fn, variable: t.variable, weight: num(t.weight, `${what} weight`) };
                if (t.fn === 'ise') {
                    if (!t.reference) errors.push(`${what}: ISE needs a reference variable`);
                    term.reference_variable = t.reference;
                }
                const target = t.fn === 'ise' || t.fn === 'overshoot' ? undefined : optionalNumber(t.target, `${what} target`);
                if (target !== undefined) term.target = target;
                return term;
            }),
        };
    };

    if (form.kind === 'sweep') {
        const parameters: Record<string, unknown> = {};
        for (const p of form.parameters) {
            if (p.useList || form.sweepMode === 'list') parameters[p.name] = list(p.list, p.name);
            else if (form.sweepMode === 'random') parameters[p.name] = { from: num(p.from, `${p.name} from`), to: num(p.to, `${p.name} to`) };
            else parameters[p.name] = { from: num(p.from, `${p.name} from`), to: num(p.to, `${p.name} to`), steps: count(p.steps, `${p.name} steps`) };
        }
        const sweep: Record<string, unknown> = { mode: form.sweepMode, parameters };
        if (form.sweepMode === 'random') {
            sweep.samples = count(form.samples, 'Samples');
            sweep.seed = num(form.seed, 'Seed', (n) => Number.isInteger(n) && n >= 0, 'a whole number');
        }
        if (form.sweepMode === 'list') {
            const lengths = new Set(Object.values(parameters).map((v) => (v as number[]).length));
            if (lengths.size > 1) errors.push('List sweep: every parameter needs as many values');
        }
        request.sweep = sweep;
        if (form.outputs.length === 0) errors.push('Outputs: choose at least one variable');
        request.outputs = outputs();
    } else if (form.kind === 'sensitivity') {
        const parameters: Record<string, unknown> = {};
        for (const p of form.parameters) {
            parameters[p.name] = p.distribution === 'normal'
                ? { distribution: 'normal', mean: num(p.mean, `${p.name} mean`), sd: num(p.sd, `${p.name} σ`, (n) => n >= 0, 'at least 0') }
                : { distribution: 'uniform', min: num(p.min, `${p.name} min`), max: num(p.max, `${p.name} max`) };
        }
        request.sensitivity = { runs: count(form.runs, 'Runs'), seed: num(form.seed, 'Seed', (n) => Number.isInteger(n) && n >= 0, 'a whole number'), parameters };
        if (form.outputs.length === 0) errors.push('Outputs: a sensitivity study needs at least one variable (its bands are drawn)');
        request.outputs = outputs();
    } else {
        const parameters: Record<string, unknown> = {};
        for (const p of form.parameters) {
            const min = num(p.from, `${p.name} min`);
            const max = num(p.to, `${p.name} max`);
            if (Number.isFinite(min) && Number.isFinite(max) && min >= max) errors.push(`${p.name}: min must be below max`);
            const bounds: Record<string, number> = { min, max };
            const start = optionalNumber(p.start, `${p.name} start`);
            if (start !== undefined) bounds.start = start;
            parameters[p.name] = bounds;
        }
        const optimise: Record<string, unknown> = {
            algorithm: form.algorithm, parameters, objective: objective(),
            max_evaluations: count(form.maxEvaluations, 'Max evaluations'),
            seed: num(form.seed, 'Seed', (n) => Number.isInteger(n) && n >= 0, 'a whole number'),
        };
        const tolerance = optionalNumber(form.tolerance, 'Tolerance');
        if (tolerance !== undefined) optimise.tolerance = tolerance;
        request.optimise = optimise;
        if (form.outputs.length > 0) request.outputs = outputs();
    }
    return errors.length > 0 ? { ok: false, errors } : { ok: true, request };
}
