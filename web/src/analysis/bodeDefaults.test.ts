import { describe, expect, it } from 'vitest';
import { bodePair, signalSources } from './bodeDefaults';
import type { Component, Model, Port } from '../protocol/types';

const port = (name: string, kind: Port['kind'], connected: boolean, node = 'NodeSignal'): Port =>
    ({ name, kind, node_type: node, connected, multiport: false });
const comp = (name: string, type: string, ports: Port[], system?: Component['system']): Component =>
    ({ name, type, kind: system ? 'system' : 'S', pose: { x: 0, y: 0, angle: 0, flipped: false }, ports, parameters: [], system });
const system = (name: string, components: Component[]): NonNullable<Component['system']> =>
    ({ name, type: 'Subsystem', timestep: 1, inherit_timestep: true, parameters: [], ports: [], components, connections: [] });

// As Position Servo: a step (its y_0, y_A, t_step unconnected parameter inputs) drives a
// controller; a sensor writes a signal but is not a Signal component.
const servo: Model = {
    name: 'Servo',
    system: system('Servo', [
        comp('Sub', 'Subsystem', [], system('Sub', [comp('Sine', 'SignalSineWave', [port('out', 'write', true)])])),
        comp('GainP', 'SignalGain', [port('in', 'read', true), port('k', 'read', false), port('out', 'write', true)]),
        comp('Position_Sensor', 'MechanicPositionSensor', [port('P1', 'power', true, 'NodeMechanic'), port('out', 'write', true)]),
        comp('Offset', 'SignalConstant', [port('out', 'write', true)]),
        comp('Step', 'SignalStep', [port('out', 'write', true), port('y_0', 'read', false), port('y_A', 'read', false), port('t_step', 'read', false)]),
    ]),
};

describe('signalSources', () => {
    it('finds the step with parameter inputs, not the gain fed by a connection, the sensor or the constant; root first', () => {
        expect(signalSources(servo)).toEqual(['Step#out#Value', 'Sub$Sine#out#Value']);
    });
});

describe('bodePair', () => {
    it('takes the source as input even when only the output is plotted', () => {
        expect(bodePair(['Position_Sensor#out#Value'], ['Step#out#Value'])).toEqual({ input: 'Step#out#Value', output: 'Position_Sensor#out#Value' });
    });

    it('takes the source as input whatever the order of the plotted variables', () => {
        expect(bodePair(['Position_Sensor#out#Value', 'Step#out#Value'], ['Step#out#Value']))
            .toEqual({ input: 'Step#out#Value', output: 'Position_Sensor#out#Value' });
    });

    it('prefers a plotted source to one that is not', () => {
        expect(bodePair(['Mass#P2#Position', 'Sub$Sine#out#Value'], ['Step#out#Value', 'Sub$Sine#out#Value']))
            .toEqual({ input: 'Sub$Sine#out#Value', output: 'Mass#P2#Position' });
    });

    it('without a source, compares the second plotted variable to the first', () => {
        expect(bodePair(['A#out#Value', 'B#out#Value'], [])).toEqual({ input: 'A#out#Value', output: 'B#out#Value' });
    });
});
