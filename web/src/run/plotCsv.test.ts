import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { plotCsv, plotCsvInDisplayUnits, type CsvSeries } from './plotCsv';
import { findDisplayUnit } from './displayUnits';

// The series of testing/plotCsvBeforeUnits.csv, which the export wrote before display units
// existed: a run and the previous one (another time vector), gaps, awkward doubles.
const now = [0, 0.001, 0.002, 0.003];
const before = [0, 0.0015, 0.003];
const series = (display: Record<string, string> = {}): CsvSeries[] => [
    { name: 'Pressure_Source#P1#Pressure', previous: false, source: { time: now, data: [100000, 123456.789, 2.5e7, 1e-7] }, unit: 'Pa', display: findDisplayUnit('Pressure', display.Pressure ?? '') },
    { name: 'Pressure_Source#P1#Pressure', previous: true, source: { time: before, data: [99999.99999999999, 0.1 + 0.2, -3e5] }, unit: 'Pa', display: findDisplayUnit('Pressure', display.Pressure ?? '') },
    { name: 'Cylinder#P1#Flow', previous: false, source: { time: now, data: [0.0001, -0.00016666666666666666, 1e-12] }, unit: 'm^3/s', display: findDisplayUnit('Flow', display.Flow ?? '') },
    { name: 'Heater#P1#Temperature', previous: false, source: { time: now, data: [273.15, 293.15, 373.15, 0] }, unit: 'K', display: findDisplayUnit('Temperature', display.Temperature ?? '') },
];

const rows = (csv: string) => csv.trimEnd().split('\n').map((line) => line.split(','));

describe('plot CSV', () => {
    it('the default export is byte for byte what it was before display units, whatever units are shown', () => {
        const old = readFileSync(new URL('../testing/plotCsvBeforeUnits.csv', import.meta.url), 'utf8');
        expect(plotCsv(series())).toBe(old);
        expect(plotCsv(series({ Pressure: 'bar', Flow: 'l/min', Temperature: 'C' }))).toBe(old);
    });

    it('in display units, each header names its unit and the values are converted', () => {
        const [header, ...body] = rows(plotCsvInDisplayUnits(series({ Pressure: 'bar', Flow: 'l/min', Temperature: 'C' })));
        expect(header).toEqual(['time [s]', 'Pressure_Source#P1#Pressure [bar]', 'Pressure_Source#P1#Pressure (previous) [bar]',
            'Cylinder#P1#Flow [l/min]', 'Heater#P1#Temperature [C]']);
        expect(body.map((r) => r[0])).toEqual(['0', '0.001', '0.0015', '0.002', '0.003']);
        const column = (i: number) => body.map((r) => (r[i] === '' ? null : Number(r[i])));
        expect(column(1)).toEqual([1, expect.closeTo(1.23456789, 14), null, 250, 1e-12]);
        expect(column(2)[4]).toBe(-3);
        expect(column(3)[0]).toBeCloseTo(6, 12);
        expect(column(3)[1]).toBeCloseTo(-10, 12);
        expect(column(4)[0]).toBe(0);
        expect(column(4)[3]).toBeCloseTo(100, 12);
        expect(column(4)[4]).toBe(-273.15);
    });

    it('in display units, a quantity with no choice keeps its base unit and its values', () => {
        const csv = plotCsvInDisplayUnits(series({ Pressure: 'bar' }));
        const [header, first] = rows(csv);
        expect(header.slice(3)).toEqual(['Cylinder#P1#Flow [m^3/s]', 'Heater#P1#Temperature [K]']);
        expect(first.slice(3)).toEqual(['0.0001', '273.15']);
        const signal: CsvSeries = { name: 'Gain#out#Value', previous: false, source: { time: [0], data: [0.5] }, unit: '', display: null };
        expect(plotCsvInDisplayUnits([signal])).toBe('time [s],Gain#out#Value\n0,0.5\n');
    });

    it('names a difference column by the two runs it sets against each other', () => {
        const difference: CsvSeries = { name: 'Heater#P1#Temperature', previous: false, difference: 'run 3 − run 2', source: { time: now, data: [1, 2, 3, 4] }, unit: 'K', display: null };
        expect(rows(plotCsv([difference]))[0]).toEqual(['time', 'Heater#P1#Temperature (run 3 − run 2)']);
    });
});
