import { describe, expect, it } from 'vitest';
import { readFileSync } from 'node:fs';
// @ts-expect-error the generator is plain JavaScript
import { extractAnimation, extractFile } from '../../scripts/extractAnimation.mjs';
import { animationOf } from './descriptions';

describe('animation descriptions', () => {
    it('the committed extract is what the generator makes of ../shared', () => {
        expect(readFileSync(extractFile, 'utf8')).toBe(extractAnimation());
    });

    it('a C-type cylinder: the rod moves 77.5 icon px per stroke length, with its port P3', () => {
        const d = animationOf('HydraulicCylinderC')!;
        expect(d.size).toEqual([119, 40]);
        const rod = d.movables[2];
        expect(rod.data).toEqual([['P3', 'Position']]);
        expect(rod.move).toEqual([{ x: 77.5, y: 0, a: 0, data: 0, divisor: 's_l#Value' }]);
        expect(rod.movingPorts).toEqual([{ port: 'P3', at: [100, 20] }]);
    });

    it('a pump turns about its shaft by the angle in degrees; a valve spool is adjustable', () => {
        const pump = animationOf('HydraulicFixedDisplacementPump')!.movables[0];
        expect(pump.move![0].a).toBeCloseTo(180 / Math.PI, 3);
        expect(pump.origin).toEqual([60, 50.5]);
        expect(animationOf('Hydraulic43Valve')!.movables[0].adjustable).toMatchObject({ port: 'in', dataname: 'Value', x: [-40, 40] });
    });

    it('types without moving parts have no description', () => {
        expect(animationOf('HydraulicTankC')).toBeUndefined();
        expect(animationOf('MechanicGearShaft')).toBeUndefined();
    });
});
