import { describe, expect, it } from 'vitest';
import { placeSystemPorts } from './systemPortPlacement';
import { GroupComponents } from './commands';
import { EditorStore, type Transport } from './EditorStore';
import { layoutComponent } from '../model/geometry';
import type { Component, Model, Pose, System } from '../protocol/types';

const pose = (x: number, y: number): Pose => ({ x, y, angle: 0, flipped: false });

function component(name: string, at: Pose, system?: System): Component {
    return { name, type: system ? 'Subsystem' : 'HydraulicVolume', kind: system ? 'system' : 'C', pose: at, ports: [], parameters: [], ...(system ? { system } : {}) };
}

function system(name: string, parts: Partial<System>): System {
    return { name, type: 'Subsystem', timestep: 0.001, inherit_timestep: true, parameters: [], ports: [], components: [], connections: [], ...parts };
}

// Content between x 100..300, y 200..260.
const content = [{ x: 100, y: 200 }, { x: 300, y: 260 }];

describe('system port placement', () => {
    it('puts each port on the side towards its outside connection', () => {
        const poses = placeSystemPorts(content, [
            { name: 'W', towards: { x: -200, y: 230 } },
            { name: 'E', towards: { x: 700, y: 230 } },
            { name: 'N', towards: { x: 200, y: -300 } },
            { name: 'S', towards: { x: 220, y: 900 } },
        ]);
        expect(poses.get('W')!.x).toBeLessThan(100);
        expect(poses.get('E')!.x).toBeGreaterThan(300);
        expect(poses.get('N')!.y).toBeLessThan(200);
        expect(poses.get('S')!.y).toBeGreaterThan(260);
    });

    it('never puts two ports on one spot, and keeps their outside order along a side', () => {
        const poses = placeSystemPorts(content, [
            { name: 'low', towards: { x: -400, y: 600 } },
            { name: 'high', towards: { x: -400, y: -100 } },
            { name: 'loose', towards: undefined },
        ]);
        const spots = [...poses.values()].map((p) => `${p.x},${p.y}`);
        expect(new Set(spots).size).toBe(3);
        for (const a of poses.values()) {
            for (const b of poses.values()) if (a !== b) expect(Math.hypot(a.x - b.x, a.y - b.y)).toBeGreaterThanOrEqual(40);
        }
        expect(poses.get('high')!.y).toBeLessThan(poses.get('low')!.y);
    });

    it("a subsystem's box shows each port on the side where it sits inside, in the same order", () => {
        const inner = system('Sub', {
            components: [component('B', pose(100, 200)), component('C', pose(300, 260))],
            ports: [['W_low', 20, 300], ['E', 380, 230], ['W_high', 20, 150], ['S', 200, 340]]
                .map(([name, x, y]) => ({ name: name as string, node_type: 'NodeHydraulic', pose: pose(x as number, y as number) })),
        });
        const sub: Component = {
            ...component('Sub', pose(0, 0), inner),
            ports: inner.ports.map((p) => ({ name: p.name, node_type: 'NodeHydraulic', kind: 'system' as const, multiport: false, connected: true })),
        };
        const layout = layoutComponent(sub, undefined);
        const at = (name: string) => layout.ports.get(name)!;
        expect(at('W_low').x).toBe(-layout.halfWidth);
        expect(at('W_high').x).toBe(-layout.halfWidth);
        expect(at('W_high').y).toBeLessThan(at('W_low').y);
        expect(at('E').x).toBe(layout.halfWidth);
        expect(at('S').y).toBe(layout.halfHeight);
    });

    it('grouping moves the new system ports apart, towards their outside components', async () => {
        // the server's answer after grouping B and C between A (left) and D (right): both ports at 0,0
        const inner = system('Subsystem', {
            ports: [{ name: 'Port', node_type: 'NodeHydraulic', pose: pose(0, 0) }, { name: 'Port_1', node_type: 'NodeHydraulic', pose: pose(0, 0) }],
            components: [component('B', pose(200, 100)), component('C', pose(300, 100))],
        });
        const grouped: Model = {
            name: 'm',
            system: system('top', {
                components: [component('A', pose(0, 100)), component('Subsystem', pose(250, 100), inner), component('D', pose(600, 100))],
                connections: [
                    { from: { component: 'A', port: 'P1' }, to: { component: 'Subsystem', port: 'Port' }, points: [] },
                    { from: { component: 'Subsystem', port: 'Port_1' }, to: { component: 'D', port: 'P1' }, points: [] },
                ],
            }),
        };
        const sent: { type: string; system?: string[]; name?: string; pose?: Pose }[] = [];
        const transport = async (request: { type: string }): Promise<Record<string, unknown>> => {
            sent.push(request);
            if (request.type === 'model.group') return { name: 'Subsystem' };
            if (request.type === 'model.get') return { model: grouped };
            return {};
        };
        const store = new EditorStore(grouped, transport as Transport);
        await store.execute(new GroupComponents([], ['B', 'C']));
        const moves = sent.filter((r) => r.type === 'component.move');
        expect(moves.map((m) => [m.system, m.name])).toEqual([[['Subsystem'], 'Port'], [['Subsystem'], 'Port_1']]);
        const placed = store.model.system.components.find((c) => c.name === 'Subsystem')!.system!.ports;
        const [towardsA, towardsD] = placed.map((p) => p.pose);
        expect(towardsA.x).toBeLessThan(200);
        expect(towardsD.x).toBeGreaterThan(300);
    });
});
