import { describe, expect, it } from 'vitest';
import { portVariables, sinkVariables, variableLabel } from './variables';
import type { Component, Model, Port } from '../protocol/types';

const port = (name: string, kind: Port['kind'], node: string, connected: boolean, multiport = false): Port =>
    ({ name, kind, node_type: node, connected, multiport });
const comp = (name: string, type: string, ports: Port[]): Component =>
    ({ name, type, kind: 'S', pose: { x: 0, y: 0, angle: 0, flipped: false }, ports, parameters: [] });

// Volume (multiport P1) <- Valve.PP ; Sensor.out -> Scope.in (read multiport); Gain.in unconnected
function model(): Model {
    const inner = comp('Inner', 'SignalGain', [port('out', 'write', 'NodeSignal', false)]);
    return {
        name: 'M',
        system: {
            name: 'M', type: 'Subsystem', timestep: 1, inherit_timestep: false, parameters: [], ports: [],
            components: [
                comp('Volume', 'HydraulicVolumeMultiPort', [port('P1', 'power', 'NodeHydraulic', true, true)]),
                comp('Valve', 'Hydraulic43Valve', [port('PP', 'power', 'NodeHydraulic', true)]),
                comp('Sensor', 'MechanicPositionSensor', [port('out', 'write', 'NodeSignal', true)]),
                comp('Scope', 'SignalSink', [port('in', 'read', 'NodeSignal', true, true)]),
                comp('Gain', 'SignalGain', [port('in', 'read', 'NodeSignal', false)]),
                { ...comp('Sub', 'Subsystem', []), kind: 'system', system: { name: 'Sub', type: 'Subsystem', timestep: 1, inherit_timestep: true, parameters: [], ports: [], components: [inner], connections: [] } },
            ],
            connections: [
                { from: { component: 'Volume', port: 'P1' }, to: { component: 'Valve', port: 'PP' }, points: [] },
                { from: { component: 'Sensor', port: 'out' }, to: { component: 'Scope', port: 'in' }, points: [] },
            ],
        },
    };
}

describe('portVariables', () => {
    it('names the variables of an ordinary port Comp#Port#Var', () => {
        const v = portVariables(model(), [], { component: 'Valve', port: 'PP' });
        expect(v.ok && v.base).toBe('Valve#PP');
        expect(v.ok && v.variables.map((x) => x.name)).toContain('Pressure');
    });

    it('a multiport shows the port at the other end of its connection', () => {
        const v = portVariables(model(), [], { component: 'Volume', port: 'P1' });
        expect(v.ok && v.base).toBe('Valve#PP');
        // but the curve is named after the port that was clicked
        expect(v.ok && v.label).toBe('Volume.P1');
    });

    it('an unconnected input is not logged', () => {
        const v = portVariables(model(), [], { component: 'Gain', port: 'in' });
        expect(v.ok).toBe(false);
    });

    it('prefixes subsystem names with $', () => {
        const v = portVariables(model(), ['Sub'], { component: 'Inner', port: 'out' });
        expect(v.ok && v.base).toBe('Sub$Inner#out');
    });

    it('the signals wired into a sink are the default plot', () => {
        expect(sinkVariables(model())).toEqual(['Sensor#out#Value']);
    });

    it('labels read as Comp.Port Var', () => {
        expect(variableLabel('Sub$Inner#out#Value')).toBe('Sub$Inner.out Value');
    });
});
