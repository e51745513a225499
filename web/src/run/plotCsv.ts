// CSV export of a plot window: as it always was (variable names, values as logged in base
// units), or in the display units the plot shows, with each column's unit in its header.
import { alignSeries, toCsv, type SeriesSource } from './RunData';
import { toDisplayValues, type DisplayUnit } from './displayUnits';

/**
 * A plotted curve: its variable, whether it is of the previous run or the difference of two runs
 * (which it names), its base unit and its axis' display unit.
 */
export interface CsvSeries { name: string; previous: boolean; difference?: string; source: SeriesSource; unit: string; display: DisplayUnit | null }

function columnName(s: CsvSeries): string {
    if (s.difference) return `${s.name} (${s.difference})`;
    return s.previous ? `${s.name} (previous)` : s.name;
}

export function plotCsv(series: CsvSeries[]): string {
    return toCsv(series.map(columnName), alignSeries(series.map((s) => s.source)));
}

/** "time [s],Pressure_Source#P1#Pressure [bar]": base units where none is chosen, no unit where a variable has none. */
export function plotCsvInDisplayUnits(series: CsvSeries[]): string {
    const sources = series.map((s) => (s.display ? { time: s.source.time, data: toDisplayValues(s.source.data, s.display) } : s.source));
    const names = series.map((s) => withUnit(columnName(s), s.display?.name ?? s.unit));
    return toCsv(names, alignSeries(sources), withUnit('time', 's'));
}

function withUnit(name: string, unit: string): string {
    return unit ? `${name} [${unit}]` : name;
}
