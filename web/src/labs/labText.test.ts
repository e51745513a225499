// @vitest-environment jsdom
// What the lab pages compute from fields and replies: check definitions from the checks
// editor's fields, parameter names of a template, and the words shown to people.
import { describe, expect, it, vi } from 'vitest';

// uPlot asks for the pixel ratio's media query when it is loaded; node has none
vi.hoisted(() => {
    window.matchMedia = (() => ({ addEventListener: () => undefined, removeEventListener: () => undefined })) as unknown as typeof window.matchMedia;
});

import { nameChecks, readDefinition } from './ChecksEditor';
import { parameterNames } from './AssignmentForm';
import { joinErrorText } from './ClassListView';
import { checkText } from './StudentAssignment';
import { allowedText } from './AssignmentView';
import { ApiError } from '../api/ApiError';
import type { Assignment } from './types';
import type { System } from '../protocol/types';

const fields = { kind: 'curve', variable: ' Mass#P2#Position ', tolerance: '', measure: 'final', min: '', max: '', band: '' };

describe('check definitions from the editor fields', () => {
    it('reads a curve check, the tolerance optional', () => {
        expect(readDefinition(fields, 'c')).toEqual({ kind: 'curve', variable: 'Mass#P2#Position' });
        expect(readDefinition({ ...fields, tolerance: '0.05' }, 'c')).toEqual({ kind: 'curve', variable: 'Mass#P2#Position', tolerance: 0.05 });
    });
    it('reads a scalar check with at least one bound; the band only for the settling time', () => {
        expect(readDefinition({ ...fields, kind: 'scalar', min: '0.65', max: '0.75', band: '0.1' }, 's'))
            .toEqual({ kind: 'scalar', variable: 'Mass#P2#Position', measure: 'final', min: 0.65, max: 0.75 });
        expect(readDefinition({ ...fields, kind: 'scalar', measure: 'settling_time', max: '2', band: '0.05' }, 's'))
            .toEqual({ kind: 'scalar', variable: 'Mass#P2#Position', measure: 'settling_time', max: 2, band: 0.05 });
    });
    it('names a check the server refers to by its place', () => {
        const checks = [{ name: 'Curve', points: 1, pretest: true }, { name: 'Final', points: 1, pretest: false }];
        expect(nameChecks('checks[1]: the solution does not log X', checks)).toBe('Check 2 "Final": the solution does not log X');
        expect(nameChecks('checks[7]: odd', checks)).toBe('checks[7]: odd');
    });
    it('names the check and the field that is wrong', () => {
        expect(() => readDefinition({ ...fields, kind: 'scalar' }, 'Final')).toThrow('Final: give min, max or both');
        expect(() => readDefinition({ ...fields, tolerance: 'x' }, 'Curve')).toThrow('Curve: the tolerance must be a number');
        expect(() => readDefinition({ ...fields, variable: ' ' }, 'Curve')).toThrow(/Curve: name the variable/);
    });
});

describe('parameter names of a template', () => {
    it('lists Comp.param (without #Value), subsystems as Sub$Comp.param, system parameters; no node start values', () => {
        const param = (name: string) => ({ name, value: '1', unit: '', description: '', type: 'double' as const });
        const system = {
            name: 'S', type: 'Subsystem', timestep: 0.001, inherit_timestep: true, ports: [], connections: [],
            parameters: [param('gain')],
            components: [
                { name: 'GainP', type: 'SignalGain', kind: 'S', parameters: [param('k#Value'), param('in#Value')], ports: [] },
                { name: 'Mass', type: 'MechanicTranslationalMass', kind: 'Q', parameters: [param('m'), param('P1#Velocity')], ports: [] },
                { name: 'Sub', type: 'Subsystem', kind: 'system', parameters: [], ports: [],
                    system: { name: 'Sub', parameters: [param('inner')], components: [{ name: 'Valve', parameters: [param('Kv')] }] } },
            ],
        } as unknown as System;
        expect(parameterNames(system)).toEqual(['gain', 'GainP.k', 'GainP.in', 'Mass.m', 'Sub$Valve.Kv']);
    });
});

describe('words', () => {
    it('explains a refused join code', () => {
        expect(joinErrorText(new ApiError('not_found', 'not found', 404))).toMatch(/No class has this code/);
        expect(joinErrorText(new ApiError('rate_limited', 'too many wrong codes', 429))).toMatch(/Too many wrong codes.*too many wrong codes/);
        expect(joinErrorText(new Error('offline'))).toBe('offline');
    });
    it('describes checks and what students may change', () => {
        expect(checkText({ name: 'c', points: 2, pretest: true, definition: { kind: 'curve', variable: 'X', tolerance: 0.05 } })).toBe('X follows the reference within 5 %');
        expect(checkText({ name: 's', points: 1, pretest: true, definition: { kind: 'scalar', variable: 'X', measure: 'settling_time', max: 2 } })).toBe('settling time of X at most 2');
        expect(checkText({ name: 'h', points: 1, pretest: false })).toBe('checked at hand-in');
        const a = { edit_mode: 'parameters', parameters: [{ name: 'GainP.k', min: 0, max: 0.1 }, { name: 'gain', min: 1 }, { name: 'Mass.m' }] } as Assignment;
        expect(allowedText(a)).toBe('Students may change only: GainP.k (0 … 0.1), gain (≥ 1), Mass.m.');
        expect(allowedText({ ...a, edit_mode: 'free' })).toBe('Students may change anything in their copy.');
    });
});
