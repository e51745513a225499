import { describe, expect, it } from 'vitest';
import { appearanceLayout } from './appearanceLayout';
import { appearanceOf } from './appearance';
import type { Component } from '../protocol/types';

const tank = (ports: string[]): Component => ({
    name: 'Tank_C', type: 'HydraulicTankC', kind: 'C', pose: { x: 0, y: 0, angle: 0, flipped: false }, parameters: [],
    ports: ports.map((name) => ({ name, node_type: 'NodeHydraulic', kind: 'power', multiport: false, connected: true })),
});

describe('layout from appearance.json', () => {
    it('sizes the body as Hopsan\'s icon and puts each port at its fraction of it', () => {
        const facts = appearanceOf('HydraulicTankC')!;
        const layout = appearanceLayout(tank(['P1']), undefined)!;
        expect([layout.halfWidth * 2, layout.halfHeight * 2]).toEqual([facts.width, facts.height]);
        const [fx, fy] = facts.ports.P1;
        expect(layout.ports.get('P1')).toEqual({ x: (fx - 0.5) * facts.width, y: (fy - 0.5) * facts.height });
    });

    it('keeps a port the facts lack where its line ended, else on the bottom edge', () => {
        const layout = appearanceLayout(tank(['P1', 'Extra', 'Other']), new Map([['Extra', { x: 3, y: 4 }]]))!;
        expect(layout.ports.get('Extra')).toEqual({ x: 3, y: 4 });
        expect(layout.ports.get('Other')!.y).toBe(layout.halfHeight);
    });

    it('has no layout for subsystems or unknown types', () => {
        expect(appearanceLayout({ ...tank([]), type: 'NoSuchType' }, undefined)).toBeNull();
    });
});
