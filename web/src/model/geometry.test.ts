import { describe, expect, it } from 'vitest';
import { anchorsFromSystem, connectionPath, layoutComponent, orientedPoints, toLocal, toScene } from './geometry';
import type { Component, System } from '../protocol/types';

const close = (a: { x: number; y: number }, b: { x: number; y: number }) => {
    expect(a.x).toBeCloseTo(b.x, 9);
    expect(a.y).toBeCloseTo(b.y, 9);
};

describe('poses', () => {
    it('toLocal undoes toScene for every angle and flip', () => {
        for (const angle of [0, 90, 180, 270, 33]) {
            for (const flipped of [false, true]) {
                const pose = { x: 100, y: -50, angle, flipped };
                const p = { x: 12, y: -7 };
                close(toLocal(pose, toScene(pose, p)), p);
            }
        }
    });

    it('rotates clockwise on screen (y down) and flips horizontally', () => {
        close(toScene({ x: 0, y: 0, angle: 90, flipped: false }, { x: 10, y: 0 }), { x: 0, y: 10 });
        close(toScene({ x: 0, y: 0, angle: 0, flipped: true }, { x: 10, y: 0 }), { x: -10, y: 0 });
    });
});

const gain = (name: string, x: number, y: number, angle = 0): Component => ({
    name, type: 'SignalGain', kind: 'S', pose: { x, y, angle, flipped: false },
    ports: [{ name: 'in', node_type: 'NodeSignal', kind: 'read', multiport: false, connected: true },
        { name: 'out', node_type: 'NodeSignal', kind: 'write', multiport: false, connected: true },
        { name: 'k', node_type: 'NodeSignal', kind: 'read', multiport: false, connected: false }],
    parameters: [{ name: 'k#Value', value: '1', unit: '', description: '', type: 'double' }],
});

describe('port layout', () => {
    const system: System = {
        name: 'S', type: 'Subsystem', timestep: 1, inherit_timestep: false, parameters: [], ports: [],
        components: [gain('A', 100, 100), gain('B', 300, 100, 90)],
        connections: [{ from: { component: 'A', port: 'out' }, to: { component: 'B', port: 'in' }, points: [[130, 100], [200, 100], [200, 70], [300, 70]] }],
    };

    it('puts connected ports where the drawing had the line ends', () => {
        const anchors = anchorsFromSystem(system);
        close(anchors.get('A')!.get('out')!, { x: 30, y: 0 });
        // B is turned 90 degrees: scene (300,70) is local (-30, 0)
        close(anchors.get('B')!.get('in')!, { x: -30, y: 0 });
        const layout = layoutComponent(system.components[0], anchors.get('A'));
        expect(layout.halfWidth).toBe(30);
        close(layout.ports.get('out')!, { x: 30, y: 0 });
    });

    it('takes the end of the line nearer to each component, whatever order the points were drawn in', () => {
        const reversed: System = { ...system, connections: [{ ...system.connections[0], points: [...system.connections[0].points].reverse() }] };
        const anchors = anchorsFromSystem(reversed);
        close(anchors.get('A')!.get('out')!, { x: 30, y: 0 });
        close(anchors.get('B')!.get('in')!, { x: -30, y: 0 });
        const pts = orientedPoints(reversed.connections[0], { x: 100, y: 100 }, { x: 300, y: 100 });
        expect(pts[0]).toEqual([130, 100]);
    });

    it('lays out the other ports by kind: inputs left, outputs right, input variables on top', () => {
        const layout = layoutComponent(gain('C', 0, 0), undefined);
        expect(layout.ports.get('in')!.x).toBe(-layout.halfWidth);
        expect(layout.ports.get('out')!.x).toBe(layout.halfWidth);
        expect(layout.ports.get('k')!.y).toBe(-layout.halfHeight);
    });

    it('lays out bidirectional signal ports as it does power ports, alternating left and right', () => {
        const split: Component = {
            name: 'Split', type: 'Signal2DSplit', kind: 'S', pose: { x: 0, y: 0, angle: 0, flipped: false },
            ports: [{ name: 'P2d', node_type: 'NodeSignal2D', kind: 'bidirectional', multiport: false, connected: false },
                { name: 'v1', node_type: 'NodeSignal', kind: 'bidirectional', multiport: false, connected: false }],
            parameters: [],
        };
        const layout = layoutComponent(split, undefined);
        expect(layout.ports.get('P2d')!.x).toBe(-layout.halfWidth);
        expect(layout.ports.get('v1')!.x).toBe(layout.halfWidth);
    });

    it('keeps the author\'s line while both ends stay, else draws an elbow', () => {
        const conn = system.connections[0];
        const kept = connectionPath(conn.points, { x: 130, y: 100 }, { x: 300, y: 70 }, true);
        expect(kept).toHaveLength(4);
        expect(kept[1]).toEqual({ x: 200, y: 100 });
        const elbow = connectionPath(conn.points, { x: 0, y: 0 }, { x: 100, y: 50 }, false);
        expect(elbow).toEqual([{ x: 0, y: 0 }, { x: 50, y: 0 }, { x: 50, y: 50 }, { x: 100, y: 50 }]);
    });

    it('rejoins a saved line whose end lies off the port with a corner, keeping its segments square', () => {
        // saved end (130,100) -> (200,100) is horizontal; the port is really at (130,90)
        const path = connectionPath([[130, 100], [200, 100], [200, 70], [300, 70]], { x: 130, y: 90 }, { x: 300, y: 70 }, true);
        expect(path).toEqual([{ x: 130, y: 90 }, { x: 130, y: 100 }, { x: 200, y: 100 }, { x: 200, y: 70 }, { x: 300, y: 70 }]);
        for (let i = 1; i < path.length; i++) expect(path[i].x === path[i - 1].x || path[i].y === path[i - 1].y).toBe(true);
    });
});
