// @vitest-environment jsdom
import { describe, expect, it } from 'vitest';
import extract from '../model/appearance.generated.json';
import { componentIcon } from './icons';

const types = (extract as unknown as { types: Record<string, { width: number; height: number; library: string }> }).types;

/** Types of Hopsan's library still drawn as the labelled box, by the icon itself (not by its family rule). */
function drawnAsBox(): string[] {
    return Object.entries(types)
        .filter(([type, { width, height }]) => componentIcon(type, width / 2, height / 2).querySelector('.icon-fallback') !== null)
        .map(([type]) => type);
}

describe('labelled-box fallback', () => {
    it('is drawn for no type of the Hopsan library: every one has a symbol of its own', () => {
        expect(Object.keys(types).length).toBeGreaterThan(340);
        expect(drawnAsBox()).toEqual([]);
    });

    it('still serves types the library does not know', () => {
        const g = componentIcon('SomeoneElsesComponent', 30, 20);
        expect(g.querySelector('.icon-fallback')?.textContent).toBe('SEC');
    });

    it('is replaced in every library folder that used to fall back, aero and vehicles included', () => {
        // one type of each folder that was all boxes before, with the symbol drawn
        for (const type of ['AeroAircraft6DOFSS', 'AeroJetEngine', 'MechanicVehicle1D', 'SignalPID', 'SignalFFB', 'ElectricIcontroller', 'ActivityDiagramAction', 'HydraulicInterfaceC', 'SignalAnimationGauge']) {
            const { width, height } = types[type];
            const g = componentIcon(type, width / 2, height / 2);
            expect(g.getAttribute('data-family'), type).toBeTruthy();
            expect(g.querySelectorAll('polyline, polygon, circle, rect:not(.icon-frame)').length, type).toBeGreaterThan(0);
        }
    });
});
