import { describe, expect, it } from 'vitest';
import { appearanceLayout } from './appearanceLayout';
import { layoutComponent } from './geometry';
import { isParameterPort, placeParameterPorts, PORT_MARKER_SIZE } from './parameterPortPlacement';
import type { Component, Port } from '../protocol/types';
// `tlmhub-cli components --json`, cut to the fields a layout reads
import componentTypes from './componentTypes.fixture.json';

const kinds: Record<string, Port['kind']> = {
    PowerPort: 'power', PowerMultiPort: 'power', ReadPort: 'read', ReadMultiPort: 'read', WritePort: 'write', BiDirectionalSignalPort: 'bidirectional',
};

function component(type: (typeof componentTypes)[number]): Component {
    return {
        name: type.type, type: type.type, kind: 'S', pose: { x: 0, y: 0, angle: 0, flipped: false },
        parameters: type.parameters.map((name) => ({ name, value: '0', unit: '', description: '' })) as unknown as Component['parameters'],
        ports: type.ports.map((p) => ({ name: p.name, node_type: p.nodetype, kind: kinds[p.porttype], multiport: p.porttype.includes('Multi'), connected: false })),
    };
}

describe('placement of shown parameter ports', () => {
    // Hopsan's own facts put a few power and signal ports close together; those stay where Hopsan has them
    it('keeps every shown parameter port of every component type a marker away from every other port', () => {
        expect(componentTypes.length).toBeGreaterThan(300);
        const crowded: string[] = [];
        for (const type of componentTypes) {
            const comp = component(type);
            const layout = placeParameterPorts(comp, appearanceLayout(comp, undefined) ?? layoutComponent(comp, undefined));
            const parameterPorts = new Set(comp.ports.filter((p) => isParameterPort(comp, p)).map((p) => p.name));
            const points = [...layout.ports];
            points.forEach(([a, p], i) => points.slice(i + 1).forEach(([b, q]) => {
                const involvesParameterPort = parameterPorts.has(a) || parameterPorts.has(b);
                if (involvesParameterPort && Math.hypot(p.x - q.x, p.y - q.y) < PORT_MARKER_SIZE) crowded.push(`${type.type}: ${a} ${b}`);
            }));
        }
        expect(crowded).toEqual([]);
    });

    it('counts as parameter ports the signal inputs with a value that Hopsan\'s icon gives no place', () => {
        const valve = component(componentTypes.find((t) => t.type === 'Hydraulic43Valve')!);
        const parameterPorts = valve.ports.filter((p) => isParameterPort(valve, p)).map((p) => p.name);
        expect(parameterPorts).toContain('x_pb');
        expect(parameterPorts).not.toContain('in');
        expect(parameterPorts).not.toContain('PT');
    });

    it('moves only parameter ports, not signal inputs of their own', () => {
        const valve = component(componentTypes.find((t) => t.type === 'HydraulicPressureReliefValve')!);
        const before = appearanceLayout(valve, undefined)!;
        const after = placeParameterPorts(valve, before);
        for (const port of valve.ports) {
            if (isParameterPort(valve, port)) expect(after.ports.get(port.name)!.y).toBeLessThan(-before.halfHeight);
            else expect(after.ports.get(port.name)).toEqual(before.ports.get(port.name));
        }
    });

    it('leaves a parameter port where its saved line ends', () => {
        const valve = component(componentTypes.find((t) => t.type === 'HydraulicPressureReliefValve')!);
        const lineEnd = new Map([['tao', { x: 50, y: 5 }]]);
        const layout = placeParameterPorts(valve, appearanceLayout(valve, lineEnd)!, lineEnd);
        expect(layout.ports.get('tao')).toEqual({ x: 50, y: 5 });
        expect(layout.ports.get('p_max')!.y).toBeLessThan(-layout.halfHeight);
    });
});
