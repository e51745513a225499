import { describe, expect, it } from 'vitest';
import { buildStudyRequest, choiceFor, defaultForm, emptyTerm, type StudyForm } from './studyForm';
import type { StudyParameter } from './studyParameters';

const gain = (name: string, value: number): StudyParameter => ({
    name, path: [], component: name.split('.')[0], parameter: 'k#Value', unit: '', description: 'Gain', text: String(value), value,
});

function form(kind: StudyForm['kind'], ...parameters: StudyParameter[]): StudyForm {
    return { ...defaultForm(kind), parameters: parameters.map(choiceFor) };
}

describe('the request built from the study form', () => {
    it('a 2-D grid sweep names each range with its steps, the outputs and the model', () => {
        const f = form('sweep', gain('GainP.k', 0.02), gain('GainI.k', 0.001));
        f.parameters[0] = { ...f.parameters[0], from: '0.01', to: '0.04', steps: '4' };
        f.parameters[1] = { ...f.parameters[1], useList: true, list: '0, 0.001 0.002' };
        f.outputs = ['Position_Sensor#out#Value'];
        f.stop = '2';
        const built = buildStudyRequest(f, 15);
        expect(built).toEqual({ ok: true, request: {
            kind: 'sweep', model_id: 15, stop: 2,
            sweep: { mode: 'grid', parameters: { 'GainP.k': { from: 0.01, to: 0.04, steps: 4 }, 'GainI.k': [0, 0.001, 0.002] } },
            outputs: { variables: ['Position_Sensor#out#Value'], values: ['final', 'max'] },
        } });
    });

    it('a random sweep takes ranges without steps, the samples and the seed', () => {
        const f = form('sweep', gain('GainP.k', 0.02));
        f.sweepMode = 'random';
        f.samples = '30';
        f.seed = '7';
        f.outputs = ['Mass#P1#Position'];
        const built = buildStudyRequest(f, 3);
        expect(built.ok && built.request.sweep).toEqual({ mode: 'random', samples: 30, seed: 7, parameters: { 'GainP.k': { from: 0.01, to: 0.03 } } });
    });

    it('a list sweep needs as many values for every parameter', () => {
        const f = form('sweep', gain('A.k', 1), gain('B.k', 2));
        f.sweepMode = 'list';
        f.parameters[0].list = '1 2 3';
        f.parameters[1].list = '1 2';
        f.outputs = ['A#out#Value'];
        expect(buildStudyRequest(f, 1)).toEqual({ ok: false, errors: ['List sweep: every parameter needs as many values'] });
    });

    it('a sensitivity study takes a distribution per parameter, runs and seed', () => {
        const f = form('sensitivity', gain('Mass.m', 100), gain('Spring.k', 1e4));
        f.parameters[1] = { ...f.parameters[1], distribution: 'uniform', min: '1e4', max: '2e4' };
        f.runs = '200';
        f.seed = '7';
        f.outputs = ['Mass#P1#x'];
        f.statistics = ['final'];
        const built = buildStudyRequest(f, 12);
        expect(built.ok && built.request.sensitivity).toEqual({ runs: 200, seed: 7, parameters: {
            'Mass.m': { distribution: 'normal', mean: 100, sd: 10 },
            'Spring.k': { distribution: 'uniform', min: 1e4, max: 2e4 },
        } });
    });

    it('an optimisation takes bounds, a start, the algorithm and the objective terms with their weights', () => {
        const f = form('optimise', gain('GainP.k', 0.02));
        f.parameters[0] = { ...f.parameters[0], from: '0.001', to: '0.05', start: '' };
        f.algorithm = 'nelder-mead';
        f.goal = 'maximise';
        f.maxEvaluations = '40';
        f.terms = [{ ...emptyTerm('Pos#out#Value') }, { fn: 'ise', variable: 'Pos#out#Value', reference: 'Step#out#Value', target: '', weight: '0.5' },
            { fn: 'final', variable: 'Pos#out#Value', reference: '', target: '0.7', weight: '2' }];
        const built = buildStudyRequest(f, 15);
        expect(built.ok && built.request.optimise).toEqual({
            algorithm: 'nelder-mead', max_evaluations: 40, seed: 1, parameters: { 'GainP.k': { min: 0.001, max: 0.05 } },
            objective: { goal: 'maximise', terms: [
                { function: 'overshoot', variable: 'Pos#out#Value', weight: 1 },
                { function: 'ise', variable: 'Pos#out#Value', reference_variable: 'Step#out#Value', weight: 0.5 },
                { function: 'final', variable: 'Pos#out#Value', target: 0.7, weight: 2 },
            ] },
        });
        expect(built.ok && built.request.outputs).toBeUndefined();
    });

    it('names every wrong field and sends nothing', () => {
        const f = form('optimise', gain('GainP.k', 0.02));
        f.parameters[0] = { ...f.parameters[0], from: '1', to: 'x' };
        f.maxEvaluations = '0';
        expect(buildStudyRequest(f, 1)).toEqual({ ok: false, errors: [
            'GainP.k max: "x" is not a number',
            'Objective: add at least one term',
            'Max evaluations: a whole number of at least 1',
        ] });
        expect(buildStudyRequest(defaultForm('sweep'), 1)).toEqual({ ok: false, errors: ['Choose at least one parameter', 'Outputs: choose at least one variable'] });
    });

    it('defaults come from the current value: ±50 % (0 to 1 for zero) and σ of 10 %', () => {
        expect(choiceFor(gain('G.k', 0.02))).toMatchObject({ from: '0.01', to: '0.03', steps: '5', mean: '0.02', sd: '0.002', start: '0.02' });
        expect(choiceFor(gain('G.k', -4))).toMatchObject({ from: '-6', to: '-2' });
        expect(choiceFor(gain('G.k', 0))).toMatchObject({ from: '0', to: '1', sd: '0.1' });
    });
});
