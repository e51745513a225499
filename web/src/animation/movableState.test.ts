import { describe, expect, it } from 'vitest';
import { movableState } from './movableState';
import { animationOf } from './descriptions';

const params = (values: Record<string, number>) => (name: string) => values[name];

describe('movableState', () => {
    const cylinder = animationOf('HydraulicCylinderC')!;

    it('a cylinder at half its stroke has its rod halfway along its travel (out as P3 goes from 0 to -s_l)', () => {
        const rod = cylinder.movables[2];
        const at = (x: number) => movableState(rod, () => x, params({ 's_l#Value': 0.4 })).dx;
        expect(at(0)).toBeCloseTo(0);
        expect(at(-0.4)).toBeCloseTo(77.5);
        expect(at(-0.2)).toBeCloseTo(at(-0.4) / 2);
    });

    it('an unknown value leaves the part at rest; a missing divisor divides by 1', () => {
        const rod = cylinder.movables[2];
        expect(movableState(rod, () => undefined, params({ 's_l#Value': 0.4 }))).toMatchObject({ dx: 0, dy: 0, angle: 0 });
        expect(movableState(rod, () => -0.1, params({})).dx).toBeCloseTo(7.75);
    });

    it('a position sensor turns its pointer from its start angle', () => {
        const needle = animationOf('MechanicPositionSensor')!.movables[0];
        expect(movableState(needle, () => 0, params({})).angle).toBe(-60);
        expect(movableState(needle, () => 0.5, params({})).angle).toBe(0);
    });

    it('the piston chamber resizes and turns from blue to red with its pressure', () => {
        const piston = cylinder.movables[1];
        const state = movableState(piston, (i) => [-0.2, 1e7][i], params({ 's_l#Value': 0.4 }));
        expect(state.sx).toBeCloseTo(0.5);
        expect(state.colour).toEqual([128, 0, 128]);   // 1.275e-5 per Pa: at 100 bar half way
        expect(movableState(piston, (i) => [0, 3e7][i], params({})).colour).toEqual([255, 0, 0]);
    });
});
