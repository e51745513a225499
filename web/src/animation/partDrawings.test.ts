// @vitest-environment jsdom
import { describe, expect, it } from 'vitest';
import { componentIcon } from '../editor/icons';
import { animationOf, animatedTypes } from './descriptions';
import { movableState } from './movableState';
import { partDrawing, type PartFrame } from './partDrawings';

/** A type's icon at its Hopsan size, and its drawing of moving parts. */
function drawn(type: string) {
    const d = animationOf(type)!;
    const [hw, hh] = [d.size[0] / 2, d.size[1] / 2];
    const icon = componentIcon(type, hw, hh);
    return { d, icon, drawing: partDrawing(type, d, icon, hw, hh) };
}

function frameOf(type: string, values: (number | undefined)[][], parameters: Record<string, number> = {}): PartFrame {
    const d = animationOf(type)!;
    return {
        states: d.movables.map((m, i) => movableState(m, (k) => values[i]?.[k], (n) => parameters[n])),
        values, pressureColour: (p) => (p > 1e6 ? '#ff0000' : '#0000ff'),
    };
}

const shift = (el: Element | null) => Number(/translate\(([-\d.]+)/.exec(el?.getAttribute('transform') ?? '')?.[1] ?? NaN);

describe('part drawings', () => {
    it("a cylinder's piston and rod move together by the stroke share, the originals hidden", () => {
        const { icon, drawing } = drawn('HydraulicCylinderC');
        expect(drawing).not.toBeNull();
        expect((icon.querySelector('.glyph-piston') as SVGElement).style.visibility).toBe('hidden');
        const part = icon.querySelector('.animation-parts .movable-part');
        expect(part?.querySelector('.glyph-piston')).not.toBeNull();
        expect(part?.querySelector('.glyph-rod')).not.toBeNull();
        const at = (x: number) => {
            drawing!.update(frameOf('HydraulicCylinderC', [[1e5], [x, 2e6], [x]], { 's_l#Value': 1 }));
            return shift(part);
        };
        const [rest, half, full] = [at(0), at(-0.5), at(-1)];
        expect(full - rest).toBeCloseTo(77.5, 1);
        expect(half - rest).toBeCloseTo((full - rest) / 2, 5);
        // the chambers take their pressures' colours
        const chambers = icon.querySelectorAll('.chamber');
        expect([...chambers].map((c) => c.getAttribute('fill'))).toEqual(['#0000ff', '#ff0000']);
        drawing!.remove();
        expect(icon.querySelector('.animation-parts')).toBeNull();
        expect((icon.querySelector('.glyph-piston') as SVGElement).style.visibility).toBe('');
    });

    it("a position sensor's pointer turns about the gauge's centre", () => {
        const { icon, drawing } = drawn('MechanicPositionSensor');
        drawing!.update(frameOf('MechanicPositionSensor', [[0.5]]));
        // −60° at rest, less −120° per metre: 0° at 0.5 m; our pointer is drawn at −45°
        expect(icon.querySelector('.movable-part')!.getAttribute('transform')).toMatch(/ rotate\(45,0,0\)$/);
    });

    it("a valve's spool slides by xv over x_vmax; a missing value leaves it at rest", () => {
        const { icon, drawing } = drawn('Hydraulic43Valve');
        const part = icon.querySelector('.movable-part');
        drawing!.update(frameOf('Hydraulic43Valve', [[0.005]], { 'x_vmax#Value': 0.01 }));
        expect(shift(part)).toBeCloseTo(20);
        drawing!.update(frameOf('Hydraulic43Valve', [[undefined]], { 'x_vmax#Value': 0.01 }));
        expect(shift(part)).toBe(0);
    });

    it('a spring stretches between its ends, which carry its ports; a mass carries both of its ports', () => {
        const { icon, drawing } = drawn('MechanicTranslationalSpring');
        // P1 at 0.1 m, P2 at 0: the left end moves 7.75 px right (rest less −77.5 px/m times 0.1 m)
        drawing!.update(frameOf('MechanicTranslationalSpring', [[0.1], [0], [0.1, 0]]));
        expect(drawing!.portShift('P1')![0]).toBeCloseTo(7.75);
        expect(drawing!.portShift('P2')![0]).toBeCloseTo(0);
        const transform = icon.querySelector('.movable-part')!.getAttribute('transform')!;
        const scale = Number(/scale\(([\d.]+),1\)/.exec(transform)![1]);
        expect(scale).toBeCloseTo((33 - 7.75) / 33, 2);
        const mass = drawn('MechanicTranslationalMass');
        mass.drawing!.update(frameOf('MechanicTranslationalMass', [[-0.2]]));
        expect(mass.drawing!.portShift('P1')![0]).toBeCloseTo(15.5);
        expect(mass.drawing!.portShift('P2')![0]).toBeCloseTo(15.5);
    });

    it('draws a moving part for every animated type of Position Servo and Load Sensing System', () => {
        const types = ['Hydraulic43Valve', 'HydraulicCylinderC', 'HydraulicFixedDisplacementPump', 'HydraulicPressureReliefValve', 'HydraulicVolumeMultiPort',
            'MechanicPositionSensor', 'MechanicTranslationalMass', 'Hydraulic43LoadSensingValve', 'HydraulicPressureControlledPump', 'HydraulicShuttleValve',
            'HydraulicVolume', 'MechanicForceTransformer'];
        for (const type of types) expect(drawn(type).drawing, type).not.toBeNull();
        // and for every other animated hydraulic and mechanic type
        const others = animatedTypes().filter((t) => /^(Hydraulic|Mechanic)/.test(t));
        expect(others.filter((t) => drawn(t).drawing === null)).toEqual([]);
    });

    it("an orifice's two sides part as its opening grows, and stay within its box", () => {
        const { icon, drawing } = drawn('HydraulicLaminarOrifice');
        const sides = () => [...icon.querySelectorAll('.movable-part > .glyph-throttle')]
            .map((e) => Number(/translate\([-\d.]+,([-\d.]+)\)/.exec(e.getAttribute('transform') ?? '')?.[1] ?? NaN));
        drawing!.update(frameOf('HydraulicLaminarOrifice', [[0], [0]]));
        expect(sides()).toEqual([0, 0]);
        // 2e11 px per unit of Kc: 1e-11 m^5/(N s) parts them by 2 px each way
        drawing!.update(frameOf('HydraulicLaminarOrifice', [[1e-11], [1e-11]]));
        expect(sides()).toEqual([-2, 2]);
        drawing!.update(frameOf('HydraulicLaminarOrifice', [[1], [1]]));
        expect(sides()).toEqual([-23 / 4, 23 / 4]);
        const turbulent = drawn('HydraulicTurbulentOrifice');
        turbulent.drawing!.update(frameOf('HydraulicTurbulentOrifice', [[1e-5], [1e-5]]));
        expect([...turbulent.icon.querySelectorAll('.movable-part > .glyph-throttle')].map((e) => e.getAttribute('transform'))).toEqual(['translate(0,-2)', 'translate(0,2)']);
    });
});
