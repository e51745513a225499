// The export dialog's grouping of an FMU interface: power port variables only under their
// port, the step apart from the parameters, and the hint's condition.
import { describe, expect, it } from 'vitest';
import { gainInterface } from '../testing/fmuInterfaces';
import { hasInterfaceComponents, interfaceView, parameterList } from './fmuInterface';

describe('interfaceView', () => {
    it('lists signal inputs and outputs without the power ports variables', () => {
        const view = interfaceView(gainInterface);
        expect(view.inputs.map((v) => v.name)).toEqual(['u']);
        expect(view.outputs.map((v) => v.name)).toEqual(['y']);
    });

    it('gives each power port its variables with their direction', () => {
        const [port] = interfaceView(gainInterface).powerPorts;
        expect(port.variables.map((v) => [v.direction, v.nodeVariable, v.variable?.value_reference]))
            .toEqual([['in', 'c', 0], ['in', 'Zc', 1], ['out', 'p', 3], ['out', 'q', 4]]);
    });

    it('keeps the step apart from the parameters', () => {
        const view = interfaceView(gainInterface);
        expect(view.parameters.map((v) => v.name)).toEqual(['Gain.k']);
        expect(view.step?.start).toBe(0.001);
    });

    it('has interface components only with an input, an output or a power port', () => {
        expect(hasInterfaceComponents(interfaceView(gainInterface))).toBe(true);
        const bare = { ...gainInterface, power_ports: [], variables: gainInterface.variables.filter((v) => v.causality === 'parameter') };
        expect(hasInterfaceComponents(interfaceView(bare))).toBe(false);
    });
});

describe('parameterList', () => {
    it('splits on commas, spaces and lines and drops empty entries', () => {
        expect(parameterList(' Gain.k, Mass.m\nSpring.k ,, ')).toEqual(['Gain.k', 'Mass.m', 'Spring.k']);
        expect(parameterList('')).toEqual([]);
    });
});
