import { describe, expect, it } from 'vitest';
import { displayUnitsOf, findDisplayUnit, fromDisplay, toDisplay, toDisplayValues } from './displayUnits';

const unit = (quantity: string, name: string) => {
    const u = findDisplayUnit(quantity, name);
    if (!u) throw new Error(`no unit ${name} of ${quantity}`);
    return u;
};

describe('display units', () => {
    it('offer the base unit first, then Hopsan\'s units of the quantity', () => {
        expect(displayUnitsOf('Pressure').map((u) => u.name)).toEqual(['Pa', 'bar', 'MPa', 'psi', 'kPa', 'GPa']);
        expect(displayUnitsOf('Flow').map((u) => u.name)).toEqual(['m^3/s', 'l/min']);
        expect(displayUnitsOf('Voltage').map((u) => u.name)).toEqual(['V']);
        expect(displayUnitsOf('NoSuchQuantity')).toEqual([]);
        expect(findDisplayUnit('Pressure', 'l/min')).toBeNull();
    });

    it('convert by scale: bar, l/min, mm', () => {
        expect(toDisplay(2.5e6, unit('Pressure', 'bar'))).toBe(25);
        expect(fromDisplay(25, unit('Pressure', 'bar'))).toBe(2.5e6);
        expect(toDisplay(1e-3 / 60, unit('Flow', 'l/min'))).toBeCloseTo(1, 12);
        expect(fromDisplay(60, unit('Flow', 'l/min'))).toBeCloseTo(1e-3, 15);
        expect(toDisplay(0.05, unit('Position', 'mm'))).toBeCloseTo(50, 12);
        expect(toDisplay(7, unit('Pressure', 'Pa'))).toBe(7);
    });

    it('convert affine temperatures both ways: C and F', () => {
        const celsius = unit('Temperature', 'C');
        expect(toDisplay(273.15, celsius)).toBe(0);
        expect(toDisplay(373.15, celsius)).toBeCloseTo(100, 12);
        expect(fromDisplay(-273.15, celsius)).toBe(0);
        expect(fromDisplay(20, celsius)).toBeCloseTo(293.15, 12);
        const fahrenheit = unit('Temperature', 'F');
        expect(toDisplay(273.15, fahrenheit)).toBeCloseTo(32, 10);
        expect(toDisplay(373.15, fahrenheit)).toBeCloseTo(212, 10);
        expect(toDisplay(0, fahrenheit)).toBeCloseTo(-459.67, 10);
        expect(fromDisplay(212, fahrenheit)).toBeCloseTo(373.15, 10);
        expect(fromDisplay(-40, fahrenheit)).toBeCloseTo(fromDisplay(-40, celsius), 10);
    });

    it('convert a series, going back gives the logged values', () => {
        const bar = unit('Pressure', 'bar');
        const logged = [1e5, 123456.789, -3e5];
        const shown = toDisplayValues(logged, bar);
        expect(shown[0]).toBe(1);
        expect(shown[1]).toBeCloseTo(1.23456789, 14);
        expect(shown[2]).toBe(-3);
        shown.forEach((v, i) => expect(fromDisplay(v, bar)).toBeCloseTo(logged[i], 6));
    });
});
