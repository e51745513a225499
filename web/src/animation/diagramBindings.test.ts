import { describe, expect, it } from 'vitest';
import { boundVariables, diagramBindings } from './diagramBindings';
import type { Component, Model, Port } from '../protocol/types';

const port = (name: string, node_type: string, extra: Partial<Port> = {}): Port =>
    ({ name, node_type, kind: 'power', connected: true, multiport: false, ...extra }) as Port;
const component = (name: string, type: string, ports: Port[], parameters: [string, string][] = []): Component => ({
    name, type, kind: 'C', pose: { x: 0, y: 0, angle: 0, flipped: false }, ports,
    parameters: parameters.map(([n, value]) => ({ name: n, value, unit: '', description: '', type: 'double' })),
}) as Component;

const model: Model = {
    name: 'm',
    system: {
        name: 'm', type: 'Subsystem', timestep: 1e-3, inherit_timestep: false, ports: [],
        parameters: [{ name: 'stroke', value: '0.5', type: 'double', unit: 'm', description: '' }],
        components: [
            component('Cyl', 'HydraulicCylinderC', [port('P1', 'NodeHydraulic'), port('P2', 'NodeHydraulic'), port('P3', 'NodeMechanic')], [['s_l#Value', 'stroke']]),
            component('Vol', 'HydraulicVolumeMultiPort', [port('P1', 'NodeHydraulic', { multiport: true })]),
            component('Tank', 'HydraulicTankC', [port('P1', 'NodeHydraulic')]),
        ],
        connections: [
            { from: { component: 'Vol', port: 'P1' }, to: { component: 'Cyl', port: 'P1' } },
            { from: { component: 'Tank', port: 'P1' }, to: { component: 'Cyl', port: 'P2' } },
        ],
    },
} as unknown as Model;

describe('diagramBindings', () => {
    const b = diagramBindings(model, []);

    it('a line reads its node pressure and the flow of an end that is not a multiport, signed along the line', () => {
        expect(b.lines.map((l) => [l.pressure, l.flow, l.sign])).toEqual([
            ['Cyl#P1#Pressure', 'Cyl#P1#Flow', 1],
            ['Tank#P1#Pressure', 'Tank#P1#Flow', -1],
        ]);
    });

    it("an animated component's parts read their ports' variables, and divisors may name system parameters", () => {
        const cyl = b.components.find((c) => c.name === 'Cyl')!;
        expect(cyl.data[2]).toEqual(['Cyl#P3#Position']);
        expect(cyl.parameters.get('s_l#Value')).toBe(0.5);
        expect(b.components.map((c) => c.name)).toEqual(['Cyl', 'Vol']);
        expect(boundVariables(b)).toContain('Cyl#P2#Pressure');
        expect(new Set(boundVariables(b)).size).toBe(boundVariables(b).length);
    });
});
