// @vitest-environment jsdom
// The export dialog: what it lists, the hint for a model without interface components, the
// note on unsaved edits, and that the options go to the server and its refusals are shown.
import { describe, expect, it, vi } from 'vitest';
import { ApiError } from '../api/ApiError';
import type { FmuOptions } from '../api/RestClient';
import type { FmuInterface } from '../protocol/types';
import { fmuDialogContent } from './FmuDialog';
import { NO_INTERFACE_HINT } from './FmuInterfaceView';
import { gainInterface } from '../testing/fmuInterfaces';

function fakeRest(answer: (options: FmuOptions) => FmuInterface) {
    return {
        fmuInterface: vi.fn(async (_id: number, options: FmuOptions) => answer(options)),
        downloadFmu: vi.fn(async () => new Blob(['PK'])),
    };
}

const texts = (root: HTMLElement, selector: string) => [...root.querySelectorAll(selector)].map((e) => e.textContent);

describe('fmuDialogContent', () => {
    it('lists inputs, outputs, power ports with their variables, parameters and the step', async () => {
        const { element, ready } = fmuDialogContent(fakeRest(() => gainInterface), { id: 4, unsaved: false }, () => undefined);
        await ready;
        const section = (id: string) => element.querySelector<HTMLElement>(`[data-testid="${id}"]`)!;
        expect(texts(section('fmu-inputs'), '.fmu-name')).toEqual(['u']);
        expect(texts(section('fmu-outputs'), '.fmu-name')).toEqual(['y']);
        expect(texts(section('fmu-power-ports'), '.fmu-name')).toEqual(['PA.c', 'PA.Zc', 'PA.p', 'PA.q']);
        expect(section('fmu-power-ports').textContent).toContain('NodeHydraulic, C-type: takes c, Zc, gives p, q');
        expect(texts(section('fmu-parameters'), '.fmu-name')).toEqual(['Gain.k']);
        expect(element.querySelector('[data-testid="fmu-step"]')!.textContent).toBe('0.001 s');
        expect(element.querySelector('[data-testid="fmu-file"]')!.textContent).toBe('FmuGain.fmu');
        expect(element.querySelector('[data-testid="fmu-hint"]')).toBeNull();
        expect(element.querySelector('[data-testid="fmu-unsaved"]')).toBeNull();
        expect(element.querySelector<HTMLButtonElement>('[data-testid="fmu-download"]')!.disabled).toBe(false);
    });

    it('says how to add interface components when the model has none', async () => {
        const bare: FmuInterface = { ...gainInterface, power_ports: [], variables: gainInterface.variables.filter((v) => v.causality === 'parameter') };
        const { element, ready } = fmuDialogContent(fakeRest(() => bare), { id: 4, unsaved: false }, () => undefined);
        await ready;
        expect(element.querySelector('[data-testid="fmu-hint"]')!.textContent).toBe(NO_INTERFACE_HINT);
    });

    it('says that the saved version is exported when there are unsaved edits', async () => {
        const { element, ready } = fmuDialogContent(fakeRest(() => gainInterface), { id: 4, unsaved: true }, () => undefined);
        await ready;
        expect(element.querySelector('[data-testid="fmu-unsaved"]')!.textContent).toContain('saved version');
    });

    it('asks again with the parameters and identifier typed, and shows a refusal with no download', async () => {
        const rest = fakeRest((options) => {
            if (options.parameters.includes('Gain.nope')) throw new ApiError('invalid_parameter', 'no parameter Gain.nope', 422);
            return gainInterface;
        });
        const { element, ready } = fmuDialogContent(rest, { id: 4, unsaved: false }, () => undefined);
        await ready;
        element.querySelector<HTMLTextAreaElement>('[data-testid="fmu-parameters-input"]')!.value = 'Gain.k,\nGain.nope';
        element.querySelector<HTMLInputElement>('[data-testid="fmu-identifier-input"]')!.value = ' MyGain ';
        element.querySelector<HTMLButtonElement>('[data-testid="fmu-refresh"]')!.click();
        await vi.waitFor(() => expect(element.querySelector('[data-testid="fmu-error"]')!.textContent).toBe('no parameter Gain.nope'));
        expect(rest.fmuInterface).toHaveBeenLastCalledWith(4, { parameters: ['Gain.k', 'Gain.nope'], identifier: 'MyGain' });
        expect(element.querySelector<HTMLButtonElement>('[data-testid="fmu-download"]')!.disabled).toBe(true);
    });
});
